// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/stl_facets.h"

#include <cmath>

#if defined(__SSE2__) && defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
#include <emmintrin.h>
#define MESHBRIDGE_STL_SSE2 1
#endif

namespace meshbridge::detail {

bool normal_against_winding(const float n[3], const float a[3], const float b[3],
                            const float c[3]) {
  const double u[3] = {double(b[0]) - a[0], double(b[1]) - a[1], double(b[2]) - a[2]};
  const double v[3] = {double(c[0]) - a[0], double(c[1]) - a[1], double(c[2]) - a[2]};
  const double w[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                       u[0] * v[1] - u[1] * v[0]};
  const double dot = n[0] * w[0] + n[1] * w[1] + n[2] * w[2];
  return std::isfinite(dot) && dot < 0;
}

namespace {

//! normal_against_winding() of the facet at `facet`.
bool facet_normal_against_winding(const unsigned char* facet) {
  float values[12];  // the normal and the three corners
  for (int k = 0; k < 12; ++k)
    values[k] = little_endian_float(facet + 4 * k);
  return normal_against_winding(values, values + 3, values + 6, values + 9);
}

}  // namespace

CornerBits facet_corner_keys(const unsigned char* facets, std::size_t n, FloatKey* keys) {
  auto* out = reinterpret_cast<unsigned char*>(keys);
  std::uint32_t minus_zero = 0, exponent_carry = 0;
  // (x & exponent) + the lowest exponent bit carries into the sign bit only if every exponent
  // bit of x is set: an infinite or NaN x.
  const auto word = [&](const unsigned char* from, unsigned char* to) {
    std::uint32_t x = little_endian_u32(from);
    const std::uint32_t zero = x == 0x80000000u ? ~0u : 0u;
    minus_zero |= zero;
    exponent_carry |= (x & 0x7F800000u) + 0x00800000u;
    x &= ~zero;
    std::memcpy(to, &x, 4);
  };
#ifdef MESHBRIDGE_STL_SSE2
  // A facet's nine coordinates as two 16-byte vectors and one word.
  const __m128i sign = _mm_set1_epi32(static_cast<int>(0x80000000u));
  const __m128i exponent = _mm_set1_epi32(0x7F800000), low = _mm_set1_epi32(0x00800000);
  __m128i zeros = _mm_setzero_si128(), carries = _mm_setzero_si128();
  for (std::size_t t = 0; t < n; ++t, facets += 50, out += 36) {
    __builtin_prefetch(facets + 2048);  // the file, well ahead (the weld's probes crowd it out)
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(facets + 12));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(facets + 28));
    const __m128i a_zero = _mm_cmpeq_epi32(a, sign), b_zero = _mm_cmpeq_epi32(b, sign);
    zeros = _mm_or_si128(zeros, _mm_or_si128(a_zero, b_zero));
    carries = _mm_or_si128(carries, _mm_add_epi32(_mm_and_si128(a, exponent), low));
    carries = _mm_or_si128(carries, _mm_add_epi32(_mm_and_si128(b, exponent), low));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out), _mm_andnot_si128(a_zero, a));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 16), _mm_andnot_si128(b_zero, b));
    word(facets + 44, out + 32);
  }
  minus_zero |= static_cast<std::uint32_t>(_mm_movemask_epi8(zeros));
  if (_mm_movemask_ps(_mm_castsi128_ps(carries)) != 0)  // a lane's sign bit
    exponent_carry |= 0x80000000u;
#else
  for (std::size_t t = 0; t < n; ++t, facets += 50, out += 36) {
    for (int k = 0; k < 9; ++k)
      word(facets + 12 + 4 * k, out + 4 * k);
  }
#endif
  return {(exponent_carry & 0x80000000u) != 0, minus_zero != 0};
}

FacetNotes facet_notes(const unsigned char* facets, std::size_t n) {
  FacetNotes notes;
  for (std::size_t t = 0; t < n; ++t)
    notes.attribute_words += (facets[50 * t + 48] | facets[50 * t + 49]) != 0;
#ifdef MESHBRIDGE_STL_SSE2
  // The dot product of the stored normal and (b - a) x (c - a) in float, with a bound on its
  // rounding error: where the sign is sure, it is the sign the double computation gives; near
  // zero (or not finite) the facet goes to normal_against_winding(). The error of the float
  // result is below 8 * 2^-24 of sum |n_i| (|p_i| + |q_i|) for the products p, q of the cross
  // product (each difference, product and sum rounds once); the margin is 2^-18.
  const __m128 magnitude = _mm_castsi128_ps(_mm_set1_epi32(0x7FFFFFFF));
  const float margin = 1.0f / (1 << 18);
  const auto sum3 = [](__m128 x) {  // lanes 0 + 1 + 2
    const __m128 y = _mm_add_ss(x, _mm_shuffle_ps(x, x, _MM_SHUFFLE(1, 1, 1, 1)));
    return _mm_cvtss_f32(_mm_add_ss(y, _mm_shuffle_ps(x, x, _MM_SHUFFLE(2, 2, 2, 2))));
  };
  for (std::size_t t = 0; t < n; ++t) {
    const unsigned char* f = facets + 50 * t;
    const __m128 normal = _mm_loadu_ps(reinterpret_cast<const float*>(f));  // nx ny nz ax
    if ((_mm_movemask_ps(_mm_cmpeq_ps(_mm_and_ps(normal, magnitude), _mm_setzero_ps())) & 7) == 7)
      continue;  // a zero normal: no claim
    const __m128 a = _mm_loadu_ps(reinterpret_cast<const float*>(f + 12));  // ax ay az bx
    const __m128 b = _mm_loadu_ps(reinterpret_cast<const float*>(f + 24));  // bx by bz cx
    // cx cy cz 0, without reading past the facet's 50 bytes.
    const __m128 c = _mm_castsi128_ps(
        _mm_srli_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(f + 32)), 4));
    const __m128 u = _mm_sub_ps(b, a), v = _mm_sub_ps(c, a);
    const __m128 p = _mm_mul_ps(_mm_shuffle_ps(u, u, _MM_SHUFFLE(3, 0, 2, 1)),
                                _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 1, 0, 2)));
    const __m128 q = _mm_mul_ps(_mm_shuffle_ps(u, u, _MM_SHUFFLE(3, 1, 0, 2)),
                                _mm_shuffle_ps(v, v, _MM_SHUFFLE(3, 0, 2, 1)));
    const float dot = sum3(_mm_mul_ps(normal, _mm_sub_ps(p, q)));
    const float bound =
        margin * sum3(_mm_mul_ps(_mm_and_ps(normal, magnitude),
                                 _mm_add_ps(_mm_and_ps(p, magnitude), _mm_and_ps(q, magnitude))));
    if (dot > bound)
      continue;
    notes.normals_reversed += dot < -bound ? 1 : facet_normal_against_winding(f);
  }
#else
  for (std::size_t t = 0; t < n; ++t)
    notes.normals_reversed += facet_normal_against_winding(facets + 50 * t);
#endif
  return notes;
}

}  // namespace meshbridge::detail
