// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/separate_copies.h"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace meshbridge {

std::size_t separate_split_vertices(IndexedMesh& mesh, double distance) {
  Soup& soup = mesh.soup;
  if (mesh.vertex_origin.size() != soup.num_vertices()) {
    throw std::invalid_argument("separate_split_vertices: vertex_origin has " +
                                std::to_string(mesh.vertex_origin.size()) + " entries for " +
                                std::to_string(soup.num_vertices()) + " vertices");
  }
  if (!std::isfinite(distance) || distance < 0) {
    throw std::invalid_argument("separate_split_vertices: distance must be finite and >= 0");
  }
  std::size_t max_origin = 0;
  for (Index o : mesh.vertex_origin) {
    if (o != kNoIndex)  // kNoIndex: a vertex repair added (a midpoint), no copy of anything
      max_origin = std::max<std::size_t>(max_origin, std::size_t(o) + 1);
  }
  std::vector<Index> copies(max_origin + 1, 0);  // the last slot: kNoIndex's, never >= 2
  for (Index o : mesh.vertex_origin)
    ++copies[o == kNoIndex ? max_origin : o];
  copies[max_origin] = 0;

  std::vector<Point> target(soup.num_vertices(), Point(0, 0, 0));
  std::vector<Index> count(soup.num_vertices(), 0);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    Point centroid(0, 0, 0);
    for (Index v : polygon)
      centroid += soup.positions[v];
    centroid /= static_cast<double>(polygon.size());
    for (Index v : polygon) {
      target[v] += centroid;
      ++count[v];
    }
  }
  std::size_t moved = 0;
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const Index o = mesh.vertex_origin[v];
    if (o == kNoIndex || copies[o] < 2 || count[v] == 0 || distance == 0)
      continue;
    Point direction = target[v] / static_cast<double>(count[v]) - soup.positions[v];
    const double length = direction.norm();
    if (!(length > 0))
      continue;
    soup.positions[v] += direction * (std::min(distance, length) / length);
    ++moved;
  }
  return moved;
}

}  // namespace meshbridge
