// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/fans.h"

#include "union_find.h"

namespace meshbridge::detail {

VertexSplit split_fans(const Soup& soup, const CornerFaces& corner_face,
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

std::vector<char> multi_fan_vertices(const Soup& soup, const CornerFaces& corner_face,
                                     const std::vector<Index>& mate) {
  const auto& cv = soup.corner_vertices;
  const auto previous = [&](Index c) {
    const Index f = corner_face[c];
    return c == soup.face_begin[f] ? soup.face_begin[f + 1] - 1 : c - 1;
  };
  std::vector<char> fans(soup.num_vertices(), 0);  // 0, 1, or 2 = more than one
  std::vector<bool> seen(soup.num_corners(), false);
  for (Index c = 0; c < soup.num_corners(); ++c) {
    if (seen[c])
      continue;
    const Index v = cv[c];
    fans[v] = fans[v] == 0 ? 1 : 2;
    seen[c] = true;
    // Corner c's wedge touches v through two sides: its own (leaving v) and the previous one
    // (arriving). Cross each to the mate's wedge at v and on, until a boundary or a seen wedge.
    for (const Index start : {c, previous(c)}) {
      Index side = start;
      while (mate[side] != kNoIndex) {
        const Index m = mate[side];
        const bool leaves = cv[m] == v;
        const Index wedge = leaves ? m : soup.next_corner(m, corner_face[m]);
        if (seen[wedge])
          break;
        seen[wedge] = true;
        side = leaves ? previous(wedge) : wedge;  // the wedge's other side at v
      }
    }
  }
  for (char& f : fans)
    f = f == 2;
  return fans;
}

}  // namespace meshbridge::detail
