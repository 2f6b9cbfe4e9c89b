// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/fans.h"

#include "union_find.h"

namespace meshbridge::detail {

VertexSplit split_fans(const Soup& soup, const std::vector<Index>& corner_face,
                       const std::vector<Index>& mate) {
  VertexSplit split;
  std::vector<Index>& vertex_origin = split.vertex_origin;
  const std::size_t num_corners = soup.num_corners();
  const auto& cv = soup.corner_vertices;
  UnionFind fans(num_corners);
  for (Index c = 0; c < num_corners; ++c) {
    const Index m = mate[c];
    if (m == kNoIndex || m < c)
      continue;
    const Index c_next = soup.next_corner(c, corner_face[c]);
    const Index m_next = soup.next_corner(m, corner_face[m]);
    if (cv[m] == cv[c]) {
      fans.unite(c, m);
      fans.unite(c_next, m_next);
    } else {
      fans.unite(c, m_next);
      fans.unite(c_next, m);
    }
  }
  const std::size_t num_vertices = soup.num_vertices();
  vertex_origin.resize(num_vertices);
  for (std::size_t v = 0; v < num_vertices; ++v)
    vertex_origin[v] = static_cast<Index>(v);
  // A fan's root is its first corner: fans are numbered in corner order, the first fan of each
  // vertex keeps the vertex, the others get copies appended.
  std::vector<char> taken(num_vertices, 0);
  split.corner_vertex = std::move(fans).take_labels([&](Index root) {
    const Index v = cv[root];
    if (!taken[v]) {
      taken[v] = 1;
      return v;
    }
    vertex_origin.push_back(v);
    return static_cast<Index>(vertex_origin.size() - 1);
  });
  return split;
}

}  // namespace meshbridge::detail
