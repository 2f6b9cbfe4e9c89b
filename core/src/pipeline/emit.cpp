// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/emit.h"

#include <algorithm>

namespace meshbridge::detail {

namespace {

// Inserts the midpoint vertices of the pairs marked in pairing.midpoint into `mesh` (as emitted
// from `soup`, face for face): one new vertex per pair, a new corner in each of its two faces
// between the corners of the side.
void insert_midpoints(const Soup& soup, const WorkingSoup& working, const SidePairing& pairing,
                      IndexedMesh& mesh) {
  const std::vector<char>& midpoint = pairing.midpoint;
  const std::vector<char>& flipped = pairing.flipped;
  // The new vertex of each marked side (the same for both sides of a pair).
  std::vector<Index> vertex_of(soup.num_corners(), kNoIndex);
  for (Index f = 0; f < soup.num_faces(); ++f) {
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      if (!midpoint[c] || vertex_of[c] != kNoIndex)
        continue;
      const Index v = static_cast<Index>(mesh.soup.positions.size());
      vertex_of[c] = vertex_of[pairing.mate[c]] = v;
      mesh.soup.positions.push_back(Point(0, 0, 0));  // set below, from the side's two ends
      mesh.vertex_origin.push_back(kNoIndex);
    }
  }
  Soup& out = mesh.soup;
  const std::size_t added =
      static_cast<std::size_t>(std::count(pairing.midpoint.begin(), pairing.midpoint.end(), 1));
  std::vector<Index> corners, origins, begin{0};
  corners.reserve(out.num_corners() + added);
  origins.reserve(out.num_corners() + added);
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const Index first = soup.face_begin[f], last = soup.face_begin[f + 1];
    for (Index c = first; c < last; ++c) {
      corners.push_back(out.corner_vertices[c]);
      origins.push_back(mesh.corner_origin[c]);
      // Emitted corner c is followed by emitted corner c + 1 (cyclically); the soup side
      // between them is the side of soup corner c (as written) or, reversed, of the soup
      // corner emitted at c + 1.
      const Index next = c + 1 < last ? c + 1 : first;
      const Index source = flipped[f] ? (next == first ? first : first + (last - next)) : c;
      const Index side = flipped[f] ? source : c;
      if (!midpoint[side])
        continue;
      const Index v = vertex_of[side];
      out.positions[v] =
          (out.positions[out.corner_vertices[c]] + out.positions[out.corner_vertices[next]]) * 0.5;
      corners.push_back(v);
      origins.push_back(working.corner_origin(side));
    }
    begin.push_back(static_cast<Index>(corners.size()));
  }
  out.corner_vertices = std::move(corners);
  out.face_begin = std::move(begin);
  mesh.corner_origin = std::move(origins);
}

}  // namespace

IndexedMesh emit_mesh(const WorkingSoup& working, VertexSplit split, const SidePairing& pairing) {
  const std::vector<char>& flipped = pairing.flipped;
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
  const bool midpoints =
      std::find(pairing.midpoint.begin(), pairing.midpoint.end(), 1) != pairing.midpoint.end();
  if (std::none_of(flipped.begin(), flipped.end(), [](char f) { return f != 0; })) {
    // Nothing reversed: every corner stays where it is.
    mesh.soup.corner_vertices = std::move(corner_vertex);
    for (Index c = 0; c < soup.num_corners(); ++c)
      mesh.corner_origin[c] = working.corner_origin(c);
  } else {
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
  }
  if (midpoints)
    insert_midpoints(soup, working, pairing, mesh);
  return mesh;
}

}  // namespace meshbridge::detail
