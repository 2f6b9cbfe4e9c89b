// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Binary STL facet records (50 bytes: a normal, three corners as little-endian floats, a 16-bit
// attribute word): the corner keys the weld needs and the notes a reader gives on what it reads
// past. Both run once per facet of the file, so they are written to be vectorized (SSE2 where
// the compiler targets it; the same results word by word elsewhere).

#include "io/position_weld.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace meshbridge::detail {

inline std::uint32_t little_endian_u32(const unsigned char* b) {
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}

inline float little_endian_float(const unsigned char* b) {
  const std::uint32_t bits = little_endian_u32(b);
  float value;
  std::memcpy(&value, &bits, 4);
  return value;
}

//! True if a facet's stored normal `n` points against the normal of its corners' winding
//! (a b c, counter-clockwise seen from outside): both non-zero and their dot product, computed
//! in double, negative. A zero or non-finite stored normal (many writers leave it 0 0 0) is no
//! claim either way.
bool normal_against_winding(const float n[3], const float a[3], const float b[3], const float c[3]);

//! What facet_corner_keys() saw in the corners' bit patterns.
struct CornerBits {
  bool non_finite = false;     //!< a coordinate is infinite or NaN (all exponent bits set)
  bool negative_zero = false;  //!< a coordinate is -0 (its key says +0)
};

//! Writes the keys of the 3 `n` corners of the `n` facets at `facets` to `keys` (3 `n` of them),
//! -0 as +0 (as float_key() does).
CornerBits facet_corner_keys(const unsigned char* facets, std::size_t n, FloatKey* keys);

//! What a binary STL reader reads past, in facets.
struct FacetNotes {
  std::size_t attribute_words = 0;   //!< a non-zero attribute word (a colour in some programs)
  std::size_t normals_reversed = 0;  //!< a stored normal against the winding
};

//! Counts, among the `n` facets at `facets`, those with a non-zero attribute word and those
//! whose normal is against their winding (exactly as normal_against_winding() decides).
FacetNotes facet_notes(const unsigned char* facets, std::size_t n);

}  // namespace meshbridge::detail
