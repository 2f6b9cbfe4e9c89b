// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/topology.h"

#include "union_find.h"

namespace meshbridge::detail {

namespace {

// True if the output has exactly the edges and vertices of the soup: every vertex pair is one
// unpaired side or two sides paired with each other, and no vertex was split.
bool keeps_every_edge_and_vertex(const Soup& soup, const GroupedSides& grouped,
                                 const SidePairing& pairing, const VertexSplit& split) {
  if (split.vertex_origin.size() != soup.num_vertices())
    return false;
  const EdgeBridges& bridges = grouped.bridges;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index k = bridges.num_contenders(e);
    const Index* sides = bridges.contenders.data() + bridges.begin[e];
    if (k > 2 || (k == 2 && pairing.mate[sides[0]] != sides[1]))
      return false;
  }
  return true;
}

}  // namespace

std::vector<TopologyChange> topology_changes(const Soup& soup, const GroupedSides& grouped,
                                             const SidePairing& pairing, const VertexSplit& split) {
  std::vector<TopologyChange> changes;
  if (keeps_every_edge_and_vertex(soup, grouped, pairing, split))
    return changes;
  const CornerFaces& corner_face = grouped.corner_face;
  const std::vector<Index>& mate = pairing.mate;
  const Index num_corners = static_cast<Index>(soup.num_corners());
  // Components: faces joined through pairs. The output is manifold (one fan per output vertex),
  // so faces that share an output vertex are joined through pairs too.
  UnionFind joined(soup.num_faces());
  for (Index c = 0; c < num_corners; ++c) {
    if (mate[c] != kNoIndex && mate[c] > c)
      joined.unite(corner_face[c], corner_face[mate[c]]);
  }
  std::vector<Index> first_face;
  const std::vector<Index> component = std::move(joined).take_labels([&](Index root) {
    first_face.push_back(root);
    return static_cast<Index>(first_face.size() - 1);
  });
  const std::size_t num_components = first_face.size();
  // V - E + F, before and after, per component.
  std::vector<long long> before(num_components, 0), after(num_components, 0);
  for (Index k : component) {
    ++before[k];
    ++after[k];
  }
  // Edges after: a pair is one, an unpaired side one.
  for (Index c = 0; c < num_corners; ++c) {
    if (mate[c] == kNoIndex || mate[c] > c)
      --after[component[corner_face[c]]];
  }
  // Edges before: each vertex pair once in every component that has a side on it.
  std::vector<Index> seen(num_components, kNoIndex);
  const EdgeBridges& bridges = grouped.bridges;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i) {
      const Index k = component[corner_face[bridges.contenders[i]]];
      if (seen[k] != static_cast<Index>(e)) {
        seen[k] = static_cast<Index>(e);
        --before[k];
      }
    }
  }
  // Vertices after: each output vertex is in one component (that of its corners).
  const std::size_t num_out = split.vertex_origin.size();
  std::vector<Index> vertex_component(num_out, kNoIndex);
  for (Index c = 0; c < num_corners; ++c)
    vertex_component[split.corner_vertex[c]] = component[corner_face[c]];
  for (Index k : vertex_component) {
    if (k != kNoIndex)
      ++after[k];
  }
  // Vertices before: each soup vertex once in every component that has one of its copies (the
  // output vertices grouped by origin, a counting sort).
  const std::size_t num_vertices = soup.num_vertices();
  std::vector<Index> begin(num_vertices + 1, 0);
  for (Index v : split.vertex_origin)
    ++begin[v + 1];
  for (std::size_t v = 0; v < num_vertices; ++v)
    begin[v + 1] += begin[v];
  std::vector<Index> copies(num_out), next(begin.begin(), begin.end() - 1);
  for (std::size_t u = 0; u < num_out; ++u)
    copies[next[split.vertex_origin[u]]++] = static_cast<Index>(u);
  seen.assign(num_components, kNoIndex);
  for (std::size_t v = 0; v < num_vertices; ++v) {
    for (Index i = begin[v]; i < begin[v + 1]; ++i) {
      const Index k = vertex_component[copies[i]];
      if (k != kNoIndex && seen[k] != static_cast<Index>(v)) {
        seen[k] = static_cast<Index>(v);
        ++before[k];
      }
    }
  }
  for (std::size_t k = 0; k < num_components; ++k) {
    if (before[k] != after[k])
      changes.push_back({first_face[k], before[k], after[k]});
  }
  return changes;
}

MidpointFaces midpoint_faces(const Soup& soup, const CornerFaces& corner_face,
                             const SidePairing& pairing) {
  MidpointFaces counted;
  Index last = kNoIndex;  // a polygon's corners are consecutive
  for (Index c = 0; c < pairing.midpoint.size(); ++c) {
    if (!pairing.midpoint[c] || corner_face[c] == last)
      continue;
    last = corner_face[c];
    ++counted.faces;
    counted.triangles += soup.face_begin[last + 1] - soup.face_begin[last] == 3 ? 1 : 0;
  }
  return counted;
}

}  // namespace meshbridge::detail
