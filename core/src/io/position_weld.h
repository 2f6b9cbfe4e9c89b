// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Welding STL corners by exact position: an open-addressing hash table on the 32-bit float bit
// patterns, vertices in order of first appearance (as OpenMesh's STL reader numbers them).

#include "meshbridge/soup.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <functional>

namespace meshbridge::detail {

//! A corner position as the bit patterns of its three floats, -0 stored as +0 (they are equal).
using FloatKey = std::array<std::uint32_t, 3>;
static_assert(sizeof(FloatKey) == 12, "keys of a triangle's corners are 36 contiguous bytes");

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

//! Writes the FloatKeys of corners [first, first + count) to `keys` (count <= 64). `first` and
//! `count` are multiples of 3: a call gets whole triangles. May throw (e.g. for a non-finite
//! coordinate); it is called in corner order within each part.
using CornerKeys = std::function<void(std::size_t first, std::size_t count, FloatKey* keys)>;

//! Fills `soup` (empty) with `corners / 3` triangles, corner c of the file becoming soup corner
//! c: one vertex per distinct position, numbered in order of first appearance. With `threads`
//! > 1 (and enough corners) the corners are cut into that many parts, welded side by side and
//! merged; the soup is the same as with one thread, and so is the error thrown (the one of the
//! first corner in file order whose `corner_keys` call throws).
void weld_triangle_corners(std::size_t corners, const CornerKeys& corner_keys, Soup& soup,
                           unsigned threads);

//! Writes corner `c`'s three coordinates as the file has them to `xyz`.
using CornerFloats = std::function<void(std::size_t c, float* xyz)>;

//! After weld_triangle_corners(): gives every vertex the zero signs of its first corner in the
//! file. The weld takes -0 and +0 as one position (they are equal) and keeps +0; this puts back
//! a -0 the file wrote first, so that a file read and written back keeps its bytes. One pass
//! over the corners; call it only when the file has a -0.
void restore_negative_zeros(Soup& soup, const CornerFloats& corner_floats);

}  // namespace meshbridge::detail
