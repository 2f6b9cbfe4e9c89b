// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/repeated_vertices.h"

#include "hash_mix.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

namespace meshbridge::detail {

namespace {

std::uint64_t bits(double x) {
  if (x == 0)
    x = 0;  // -0 and +0 are one position
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

}  // namespace

std::size_t weld_repeated_vertices(Soup& soup, MeshAttributes* attributes) {
  const std::size_t n = soup.num_vertices();
  if (soup.num_faces() < 2)
    return 0;
  // Each vertex used by one corner at most, else the file indexes its vertices.
  std::vector<char> used(n, 0);
  for (Index v : soup.corner_vertices) {
    if (v >= n || used[v])
      return 0;
    used[v] = 1;
  }
  const bool colors = attributes != nullptr && !attributes->vertex_colors.empty();
  const auto same = [&](Index a, Index b) {
    const Point& p = soup.positions[a];
    const Point& q = soup.positions[b];
    if (!(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]))
      return false;
    if (!colors)
      return true;
    const bool has_a =
        MeshAttributes::has_color(attributes->vertex_colors, attributes->vertex_color_missing, a);
    const bool has_b =
        MeshAttributes::has_color(attributes->vertex_colors, attributes->vertex_color_missing, b);
    return has_a == has_b && attributes->vertex_colors[a] == attributes->vertex_colors[b];
  };
  // Open addressing on position hashes: the first vertex of each position.
  std::size_t capacity = 16;
  while (capacity < 2 * soup.num_corners())
    capacity *= 2;
  std::vector<Index> table(capacity, kNoIndex);
  std::vector<Index> survivor(n);
  std::size_t removed = 0;
  for (std::size_t v = 0; v < n; ++v) {
    survivor[v] = static_cast<Index>(v);
    if (!used[v])
      continue;
    const Point& p = soup.positions[v];
    std::size_t slot = mix(bits(p[0]) ^ mix(bits(p[1]) ^ mix(bits(p[2])))) & (capacity - 1);
    while (table[slot] != kNoIndex && !same(table[slot], static_cast<Index>(v)))
      slot = (slot + 1) & (capacity - 1);
    if (table[slot] == kNoIndex) {
      table[slot] = static_cast<Index>(v);
    } else {
      survivor[v] = table[slot];
      ++removed;
    }
  }
  if (removed == 0)
    return 0;
  // A per-face-vertex file of a surface: welded, most sides share their edge with another side
  // (every side of a closed mesh). Faces that would meet only at vertices (a repaired mesh whose
  // split vertices each carry one face: the two triangles of a bowtie) are a file's own choice:
  // left as they are.
  std::size_t edge_capacity = 16;
  while (edge_capacity < 2 * soup.num_corners())
    edge_capacity *= 2;
  std::vector<std::uint64_t> edge_keys(edge_capacity, 0);
  std::vector<Index> edge_sides(edge_capacity, 0);
  const auto edge_slot = [&](Index a, Index b) {
    const std::uint64_t key =
        ((static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b)) + 1;  // never 0
    std::size_t slot = mix(key) & (edge_capacity - 1);
    while (edge_keys[slot] != 0 && edge_keys[slot] != key)
      slot = (slot + 1) & (edge_capacity - 1);
    edge_keys[slot] = key;
    return slot;
  };
  for (Index f = 0; f < soup.num_faces(); ++f) {
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      const Index a = survivor[soup.corner_vertices[c]];
      const Index b = survivor[soup.corner_vertices[soup.next_corner(c, f)]];
      if (a != b)
        ++edge_sides[edge_slot(a, b)];
    }
  }
  std::size_t sides = 0, shared = 0;
  for (std::size_t slot = 0; slot < edge_capacity; ++slot) {
    sides += edge_sides[slot];
    shared += edge_sides[slot] >= 2 ? edge_sides[slot] : 0;
  }
  if (2 * shared < sides)
    return 0;
  std::vector<Index> new_index(n, kNoIndex);
  Index next = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (survivor[v] != v)
      continue;
    new_index[v] = next;
    soup.positions[next] = soup.positions[v];
    if (colors) {
      attributes->vertex_colors[next] = attributes->vertex_colors[v];
      if (!attributes->vertex_color_missing.empty())
        attributes->vertex_color_missing[next] = attributes->vertex_color_missing[v];
    }
    ++next;
  }
  soup.positions.resize(next);
  if (colors) {
    attributes->vertex_colors.resize(next);
    if (!attributes->vertex_color_missing.empty())
      attributes->vertex_color_missing.resize(next);
  }
  for (Index& v : soup.corner_vertices)
    v = new_index[survivor[v]];
  return removed;
}

}  // namespace meshbridge::detail
