// SPDX-License-Identifier: GPL-3.0-or-later
// Every face record as kept, split or set aside: the same rule as repair's WorkingSoup. The same
// walk checks each face as validate_soup() does, so reading makes one pass over the corners.

#include "geometry/triangulate.h"
#include "io/formats.h"
#include "validate_faces.h"
#include "working_soup.h"

#include <algorithm>
#include <vector>

namespace meshbridge::detail {

void account_faces(const Soup& soup, ReadInfo& info) {
  validate_layout(soup);
  const Index* corners = soup.corner_vertices.data();
  const std::size_t vertices = soup.num_vertices();
  std::vector<Index> loop;
  Triangulation keyhole;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    // Fast path: a valid triangle with three different corners (almost every face).
    const std::size_t begin = soup.face_begin[f];
    if (soup.face_begin[f + 1] == begin + 3 && begin + 3 <= soup.corner_vertices.size()) {
      const Index a = corners[begin], b = corners[begin + 1], c = corners[begin + 2];
      if (a < vertices && b < vertices && c < vertices && a != b && b != c && a != c) {
        ++info.faces_kept;
        continue;
      }
    }
    if (!is_valid_face(soup, f))
      throw_invalid_face(soup, f);
    const PolygonView polygon = soup.polygon(f);
    // Collapse consecutive repeats (cyclically), as WorkingSoup does.
    loop.clear();
    for (Index v : polygon) {
      if (loop.empty() || loop.back() != v)
        loop.push_back(v);
    }
    while (loop.size() > 1 && loop.front() == loop.back())
      loop.pop_back();
    std::vector<Index> sorted = loop;
    std::sort(sorted.begin(), sorted.end());
    const std::size_t distinct =
        static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
    if (distinct < 3)
      ++info.faces_set_aside;
    else if (distinct < loop.size()) {
      ++info.faces_split;
      // A keyhole polygon, as WorkingSoup tells it: a slit, and triangles as one polygon.
      std::vector<std::pair<Index, Index>> slits;
      simple_loops(
          loop, [](Index v) { return v; }, &slits);
      if (!slits.empty() &&
          triangulate_keyhole(soup, std::vector<Index>(polygon.begin(), polygon.end()), keyhole))
        ++info.keyhole_polygons;
    } else
      ++info.faces_kept;
  }
  info.faces_set_aside += info.faces_without_corners;
}

}  // namespace meshbridge::detail
