// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/topology.h"

#include "union_find.h"

#include <algorithm>
#include <utility>

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

// The corners of face `f` as a key that copies of it share: started at its smallest vertex, in
// the direction whose next vertex is the smaller (the same sides either way round).
std::vector<Index> sides_key(const Soup& soup, Index f) {
  const PolygonView p = soup.polygon(f);
  const std::size_t n = p.size();
  std::size_t start = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (p[i] < p[start])
      start = i;
  }
  const bool forward = p[(start + 1) % n] <= p[(start + n - 1) % n];
  std::vector<Index> key(n);
  for (std::size_t i = 0; i < n; ++i)
    key[i] = p[forward ? (start + i) % n : (start + n - i) % n];
  return key;
}

// Fills the faces, stacked copies and orientation cuts of `changes`, the components of
// `component` (per face) listed in `changed` (per component: its index in `changes`, or kNoIndex).
void describe_changes(const Soup& soup, const CornerFaces& corner_face,
                      const std::vector<Index>& mate, const std::vector<char>& cut_for_orientation,
                      const std::vector<Index>& component, const std::vector<Index>& changed,
                      std::vector<TopologyChange>& changes) {
  std::vector<std::pair<Index, std::vector<Index>>> keys;  // (change, sides key) per face
  for (Index f = 0; f < soup.num_faces(); ++f) {
    const Index i = changed[component[f]];
    if (i == kNoIndex)
      continue;
    ++changes[i].faces;
    keys.emplace_back(i, sides_key(soup, f));
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t j = 1; j < keys.size(); ++j) {
    if (keys[j] == keys[j - 1])
      ++changes[keys[j].first].stacked_copies;
  }
  for (Index c = 0; c < cut_for_orientation.size(); ++c) {
    if (cut_for_orientation[c] && mate[c] == kNoIndex) {
      const Index i = changed[component[corner_face[c]]];
      if (i != kNoIndex)
        changes[i].cut_for_orientation = true;
    }
  }
}

}  // namespace

std::vector<TopologyChange> topology_changes(const Soup& soup, const GroupedSides& grouped,
                                             const SidePairing& pairing, const VertexSplit& split,
                                             const std::vector<char>& cut_for_orientation) {
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
  std::vector<Index> changed(num_components, kNoIndex);
  for (std::size_t k = 0; k < num_components; ++k) {
    if (before[k] != after[k]) {
      changed[k] = static_cast<Index>(changes.size());
      TopologyChange change;
      change.first_face = first_face[k];
      change.euler_before = before[k];
      change.euler_after = after[k];
      changes.push_back(change);
    }
  }
  if (!changes.empty())
    describe_changes(soup, corner_face, mate, cut_for_orientation, component, changed, changes);
  // A component whose value differs only by its stacked copies (each a face of its own in the
  // input's count) has the topology it had with every face counted once: no change.
  changes.erase(std::remove_if(changes.begin(), changes.end(),
                               [](const TopologyChange& c) {
                                 return c.stacked_copies != 0 &&
                                        c.euler_before - static_cast<long long>(c.stacked_copies) ==
                                            c.euler_after;
                               }),
                changes.end());
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
