// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/emit.h"

#include <algorithm>

namespace meshbridge::detail {

IndexedMesh emit_mesh(const WorkingSoup& working, VertexSplit split,
                      const std::vector<char>& flipped) {
  std::vector<Index>& corner_vertex = split.corner_vertex;
  std::vector<Index>& vertex_origin = split.vertex_origin;
  const Soup& soup = working.soup();
  IndexedMesh mesh;
  mesh.vertex_origin = std::move(vertex_origin);
  mesh.soup.positions.reserve(mesh.vertex_origin.size());
  for (const Index v : mesh.vertex_origin)
    mesh.soup.positions.push_back(soup.positions[v]);
  mesh.soup.face_begin = soup.face_begin;
  mesh.face_origin.resize(soup.num_faces());
  for (Index f = 0; f < soup.num_faces(); ++f)
    mesh.face_origin[f] = working.face_origin(f);
  mesh.corner_origin.resize(soup.num_corners());
  if (std::none_of(flipped.begin(), flipped.end(), [](char f) { return f != 0; })) {
    // Nothing reversed: every corner stays where it is.
    mesh.soup.corner_vertices = std::move(corner_vertex);
    for (Index c = 0; c < soup.num_corners(); ++c)
      mesh.corner_origin[c] = working.corner_origin(c);
    return mesh;
  }
  mesh.soup.corner_vertices.resize(soup.num_corners());
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const Index first = soup.face_begin[f];
    const Index last = soup.face_begin[f + 1];
    for (Index c = first; c < last; ++c) {
      // Reversal keeps the first corner: c0 c1 ... ck-1 -> c0 ck-1 ... c1.
      const Index source = (flipped[f] && c != first) ? first + (last - c) : c;
      mesh.soup.corner_vertices[c] = corner_vertex[source];
      mesh.corner_origin[c] = working.corner_origin(source);
    }
  }
  return mesh;
}

}  // namespace meshbridge::detail
