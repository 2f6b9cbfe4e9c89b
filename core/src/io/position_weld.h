// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Welding corners by exact position (STL): one hash table, vertices in order of first appearance.

#include "meshbridge/soup.h"

#include <cstdint>
#include <cstring>
#include <vector>

namespace meshbridge::detail {

//! Hash of a position's exact value (-0 and +0 hash alike, as they compare equal).
inline std::uint64_t position_hash(const Point& p) {
  std::uint64_t h = 0;
  for (int i = 0; i < 3; ++i) {
    const double x = p[i] + 0.0;  // -0 becomes +0
    std::uint64_t bits;
    std::memcpy(&bits, &x, 8);
    h = (h ^ bits) * 0x9E3779B97F4A7C15ull;
    h ^= h >> 32;
  }
  return h;
}

//! Appends triangles of `corners` corners (3 per triangle) to `soup`, one vertex per distinct
//! position in order of first appearance. `corner(c)` gives corner c's position (finite).
template <class CornerPosition>
void weld_triangle_corners(std::size_t corners, CornerPosition corner, Soup& soup) {
  std::size_t capacity = 1024;
  while (capacity < corners / 2)
    capacity *= 2;
  std::vector<Index> slots(capacity, kNoIndex);
  std::size_t mask = capacity - 1;
  soup.positions.reserve(corners / 4);
  soup.corner_vertices.resize(corners);
  soup.face_begin.resize(corners / 3 + 1);
  for (std::size_t f = 0; f <= corners / 3; ++f)
    soup.face_begin[f] = static_cast<Index>(3 * f);
  for (std::size_t c = 0; c < corners; ++c) {
    const Point p = corner(c);
    std::size_t s = position_hash(p) & mask;
    while (slots[s] != kNoIndex && !(soup.positions[slots[s]] == p))
      s = (s + 1) & mask;
    if (slots[s] == kNoIndex) {
      slots[s] = static_cast<Index>(soup.positions.size());
      soup.positions.push_back(p);
      if (2 * soup.positions.size() > capacity) {  // keep the load at most 1/2
        capacity *= 2;
        mask = capacity - 1;
        slots.assign(capacity, kNoIndex);
        for (std::size_t v = 0; v < soup.positions.size(); ++v) {
          std::size_t t = position_hash(soup.positions[v]) & mask;
          while (slots[t] != kNoIndex)
            t = (t + 1) & mask;
          slots[t] = static_cast<Index>(v);
        }
        soup.corner_vertices[c] = static_cast<Index>(soup.positions.size() - 1);
        continue;
      }
    }
    soup.corner_vertices[c] = slots[s];
  }
}

}  // namespace meshbridge::detail
