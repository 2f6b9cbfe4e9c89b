// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sides of a soup visited vertex pair by vertex pair without keeping the grouping: what
// detection needs (each edge seen once), in a third of EdgeBridges' memory.

#include "meshbridge/defect_report.h"
#include "meshbridge/soup.h"

#include "pipeline/corner_faces.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace meshbridge::detail {

//! Calls `visit(VertexPair{v0, v1}, const Index* sides, Index k)` once per vertex pair (v0 < v1)
//! that polygon sides of `soup` run along, with its k sides (as corners, increasing): the edges
//! and contenders of EdgeBridges in the same order (increasing (v0, v1)), one bucket of sides
//! sharing their smaller vertex at a time. Returns the number of vertex pairs (edges).
//! Memory: one Index per corner and one per vertex, freed on return, except that with `sides_out`
//! the sides, in visiting order (EdgeBridges::contenders), are moved there. O(#C) (buckets of
//! more than 32 sides are sorted). \pre `soup` passes validate_soup()
template <class Visit>
std::size_t for_each_vertex_pair(const Soup& soup, const CornerFaces& corner_face, Visit&& visit,
                                 std::vector<Index>* sides_out = nullptr) {
  const std::size_t num_corners = soup.num_corners();
  const std::size_t num_vertices = soup.num_vertices();
  const auto& cv = soup.corner_vertices;
  const auto ends = [&](Index c) {
    const Index a = cv[c];
    const Index b = cv[soup.next_corner(c, corner_face[c])];
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  };
  // Counting sort by smaller vertex, filled backwards so that each bucket holds its corners in
  // increasing order and `bucket[v]` ends up at bucket v's first entry (bucket[#V] = #C).
  std::vector<Index> bucket(num_vertices + 1, 0);
  std::vector<Index> sorted(num_corners);
  for (Index c = 0; c < num_corners; ++c)
    ++bucket[ends(c).first];
  Index sum = 0;
  for (std::size_t v = 0; v < num_vertices; ++v) {
    sum += bucket[v];
    bucket[v] = sum;
  }
  bucket[num_vertices] = static_cast<Index>(num_corners);
  for (Index c = static_cast<Index>(num_corners); c-- > 0;)
    sorted[--bucket[ends(c).first]] = c;

  std::size_t num_edges = 0;
  std::vector<std::pair<Index, Index>> local;  // one bucket: (larger vertex, corner)
  for (std::size_t v = 0; v < num_vertices; ++v) {
    const Index first = bucket[v];
    const Index last = bucket[v + 1];
    if (first == last)
      continue;
    local.clear();
    for (Index i = first; i < last; ++i)
      local.emplace_back(ends(sorted[i]).second, sorted[i]);
    if (local.size() > 32) {
      std::sort(local.begin(), local.end());
    } else {
      for (std::size_t i = 1; i < local.size(); ++i) {  // insertion sort: a handful of sides
        const auto x = local[i];
        std::size_t j = i;
        for (; j > 0 && x < local[j - 1]; --j)
          local[j] = local[j - 1];
        local[j] = x;
      }
    }
    Index* sides = sorted.data() + first;
    for (std::size_t i = 0; i < local.size(); ++i)
      sides[i] = local[i].second;
    for (std::size_t i = 0; i < local.size();) {
      const Index other = local[i].first;
      std::size_t j = i + 1;
      while (j < local.size() && local[j].first == other)
        ++j;
      visit(VertexPair{static_cast<Index>(v), other}, sides + i, static_cast<Index>(j - i));
      ++num_edges;
      i = j;
    }
  }
  if (sides_out != nullptr)
    *sides_out = std::move(sorted);
  return num_edges;
}

}  // namespace meshbridge::detail
