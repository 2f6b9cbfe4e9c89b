// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/repeated_vertices.h"

#include "hash_mix.h"

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
  // A per-face-vertex file repeats most positions (every corner of a closed mesh, most of an
  // open one). Copies at only a few positions are a file's own choice (a repaired mesh whose
  // split vertices each carry one face, the two triangles of a bowtie): left as they are.
  std::vector<char> shared(n, 0);
  std::size_t used_vertices = 0, with_copies = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (survivor[v] != v)
      shared[v] = shared[survivor[v]] = 1;
  }
  for (std::size_t v = 0; v < n; ++v) {
    used_vertices += used[v];
    with_copies += shared[v];
  }
  if (2 * with_copies < used_vertices)
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
