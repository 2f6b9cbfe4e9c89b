// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The splitmix64 finaliser (Steele, Lea and Flood 2014): a 64-bit key spread over all bits, for
// the open-addressing tables of gap closing and of the per-face-vertex weld.

#include <cstdint>

namespace meshbridge::detail {

inline std::uint64_t mix(std::uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

}  // namespace meshbridge::detail
