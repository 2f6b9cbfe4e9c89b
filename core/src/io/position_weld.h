// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Welding STL corners by exact position: one open-addressing hash table on the 32-bit float
// bit patterns, vertices in order of first appearance (as OpenMesh's STL reader numbers them).

#include "meshbridge/soup.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace meshbridge::detail {

//! A corner position as the bit patterns of its three floats, -0 stored as +0 (they are equal).
using FloatKey = std::array<std::uint32_t, 3>;

inline FloatKey float_key(float x, float y, float z) {
  FloatKey key;
  const float xyz[3] = {x, y, z};
  for (int i = 0; i < 3; ++i) {
    std::memcpy(&key[i], &xyz[i], 4);
    if (key[i] == 0x80000000u)
      key[i] = 0;
  }
  return key;
}

inline std::uint32_t float_key_hash(const FloatKey& k) {
  std::uint64_t h = (std::uint64_t(k[0]) << 32 | k[1]) * 0x9E3779B97F4A7C15ull;
  h ^= (h >> 29) + k[2] * 0xC2B2AE3D27D4EB4Full;
  h *= 0x165667B19E3779F9ull;
  return static_cast<std::uint32_t>(h >> 32);
}

//! Appends the triangles of `corners` corners (3 per triangle, in order) to `soup`: one vertex
//! per distinct position in order of first appearance. `corner(c)` returns corner c's FloatKey
//! (and may throw, e.g. for a non-finite coordinate).
template <class CornerKey>
void weld_triangle_corners(std::size_t corners, CornerKey corner, Soup& soup) {
  std::size_t capacity = 1024;
  while (capacity < corners / 2)
    capacity *= 2;
  std::vector<Index> slots(capacity, kNoIndex);
  std::size_t mask = capacity - 1;
  std::vector<FloatKey> keys;  // one per vertex: compact, so probes stay in cache
  keys.reserve(corners / 4 + 16);
  soup.corner_vertices.resize(corners);
  soup.face_begin.resize(corners / 3 + 1);
  for (std::size_t f = 0; f <= corners / 3; ++f)
    soup.face_begin[f] = static_cast<Index>(3 * f);
  for (std::size_t c = 0; c < corners; ++c) {
    const FloatKey key = corner(c);
    std::size_t s = float_key_hash(key) & mask;
    while (slots[s] != kNoIndex && keys[slots[s]] != key)
      s = (s + 1) & mask;
    if (slots[s] != kNoIndex) {
      soup.corner_vertices[c] = slots[s];
      continue;
    }
    const Index v = static_cast<Index>(keys.size());
    keys.push_back(key);
    slots[s] = v;
    soup.corner_vertices[c] = v;
    if (2 * keys.size() > capacity) {  // keep the load at most 1/2
      capacity *= 2;
      mask = capacity - 1;
      slots.assign(capacity, kNoIndex);
      for (std::size_t u = 0; u < keys.size(); ++u) {
        std::size_t t = float_key_hash(keys[u]) & mask;
        while (slots[t] != kNoIndex)
          t = (t + 1) & mask;
        slots[t] = static_cast<Index>(u);
      }
    }
  }
  std::vector<Index>().swap(slots);
  soup.positions.resize(keys.size());
  for (std::size_t v = 0; v < keys.size(); ++v) {
    float xyz[3];
    std::memcpy(xyz, keys[v].data(), 12);
    soup.positions[v] = Point(xyz[0], xyz[1], xyz[2]);
  }
}

}  // namespace meshbridge::detail
