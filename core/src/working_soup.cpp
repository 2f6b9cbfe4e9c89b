// SPDX-License-Identifier: GPL-3.0-or-later
#include "working_soup.h"

#include "geometry/triangulate.h"

#include <algorithm>

namespace meshbridge::detail {

bool has_repeated_vertex(PolygonView polygon) {
  const std::size_t n = polygon.size();
  if (n <= 16) {
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j)
        if (polygon[i] == polygon[j])
          return true;
    return false;
  }
  std::vector<Index> sorted(polygon.begin(), polygon.end());
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

WorkingSoup::WorkingSoup(const Soup& input) : input_(input) {
  for (std::size_t f = 0; f < input.num_faces(); ++f) {
    if (has_repeated_vertex(input.polygon(f)))
      degenerate_.push_back(static_cast<Index>(f));
  }
  if (degenerate_.empty())
    return;

  identity_ = false;
  owned_.positions = input.positions;
  owned_.reserve(input.num_vertices(), input.num_faces(), input.num_corners());
  face_origin_.reserve(input.num_faces());
  corner_origin_.reserve(input.num_corners());
  std::size_t next_degenerate = 0;
  Triangulation keyhole;
  for (std::size_t f = 0; f < input.num_faces(); ++f) {
    const Index first = input.face_begin[f];
    const Index last = input.face_begin[f + 1];
    std::vector<std::vector<Index>> loops;
    if (next_degenerate < degenerate_.size() && degenerate_[next_degenerate] == f) {
      ++next_degenerate;
      std::vector<Index> corners(last - first);
      for (Index c = first; c < last; ++c)
        corners[c - first] = c;
      std::vector<std::pair<Index, Index>> slits;
      loops = simple_loops(
          std::move(corners), [&](Index c) { return input.corner_vertices[c]; }, &slits);
      if (loops.empty()) {  // a polygon with no loop left is set aside whole
        set_aside_.push_back(static_cast<Index>(f));
        continue;
      }
      const bool is_keyhole =
          !slits.empty() &&
          triangulate_keyhole(input,
                              std::vector<Index>(input.corner_vertices.begin() + first,
                                                 input.corner_vertices.begin() + last),
                              keyhole);
      for (const auto& [a, b] : slits) {
        slits_.push_back({static_cast<Index>(face_origin_.size()), input.corner_vertices[a],
                          input.corner_vertices[b], is_keyhole});
      }
      if (is_keyhole) {
        slits_in_keyholes_ += slits.size();
        keyholes_.push_back({static_cast<Index>(face_origin_.size()),
                             static_cast<Index>(loops.size()),
                             static_cast<Index>(keyhole_corners_.size()),
                             static_cast<Index>(keyhole.positions.size())});
        for (const auto& triangle : keyhole.positions) {
          for (Index i : triangle)
            keyhole_corners_.push_back(first + i);
        }
        ++faces_split_;
        faces_added_by_split_ += keyhole.positions.size() - 1;
      } else if (loops.size() > 1) {
        ++faces_split_;
        faces_added_by_split_ += loops.size() - 1;
      }
    } else {
      loops.emplace_back();
      for (Index c = first; c < last; ++c)
        loops.back().push_back(c);
    }
    for (const auto& loop : loops) {
      for (Index c : loop) {
        owned_.corner_vertices.push_back(input.corner_vertices[c]);
        corner_origin_.push_back(c);
      }
      owned_.face_begin.push_back(static_cast<Index>(owned_.corner_vertices.size()));
      face_origin_.push_back(static_cast<Index>(f));
    }
  }
}

}  // namespace meshbridge::detail
