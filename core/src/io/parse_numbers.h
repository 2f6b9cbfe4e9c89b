// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Numbers from text through std::from_chars: no locale, no allocation, no stream state.

#include <charconv>
#include <cstdint>
#include <system_error>

namespace meshbridge::detail {

//! Parses a decimal floating-point number at [first, last): an optional '+' or '-', digits,
//! fraction, exponent; also "inf" and "nan" (callers refuse non-finite values where they matter).
//! Returns the end of the number, or nullptr if none starts at `first` (value untouched).
//! An out-of-range magnitude is refused too (nullptr).
inline const char* parse_double(const char* first, const char* last, double& value) {
  // Fast path (Clinger's): an optional '-', digits, and digits after a '.' if any, 19 digits at
  // most whose whole number fits in 53 bits and at most 22 of them after the point: the number
  // and 10^(digits after the point) are both exact doubles, so their one division rounds
  // correctly, to the value from_chars gives. Anything else (an exponent, more digits, "inf",
  // ".5", "1.") goes to from_chars.
  static constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                                       1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                                       1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const auto digit = [](char c) { return static_cast<unsigned>(c - '0') < 10; };
  const char* p = first;
  const bool negative = p != last && *p == '-';
  p += negative;
  std::uint64_t digits = 0;
  const char* whole = p;
  while (p != last && digit(*p) && p - whole < 20)
    digits = 10 * digits + static_cast<unsigned>(*p++ - '0');
  const std::ptrdiff_t whole_digits = p - whole;
  std::ptrdiff_t after = 0;
  if (whole_digits > 0 && last - p >= 2 && *p == '.' && digit(p[1])) {
    const char* point = ++p;
    while (p != last && digit(*p) && whole_digits + (p - point) < 20)
      digits = 10 * digits + static_cast<unsigned>(*p++ - '0');
    after = p - point;
  }
  if (whole_digits > 0 && whole_digits + after <= 19 && after <= 22 &&
      digits <= (std::uint64_t(1) << 53) &&
      (p == last || !(digit(*p) || *p == '.' || *p == 'e' || *p == 'E'))) {
    const double d = static_cast<double>(digits) / kPowers[after];
    value = negative ? -d : d;
    return p;
  }
  if (first != last && *first == '+') {
    ++first;
    if (first != last && (*first == '-' || *first == '+'))
      return nullptr;
  }
  const auto [end, error] = std::from_chars(first, last, value, std::chars_format::general);
  return error == std::errc() ? end : nullptr;
}

//! Parses a decimal integer (optional '+' or '-') at [first, last) into a 64-bit value.
//! Returns the end of the number, or nullptr if none starts there or it overflows int64.
inline const char* parse_integer(const char* first, const char* last, std::int64_t& value) {
  // Fast path: up to 18 digits (no overflow possible), not followed by another digit.
  std::uint64_t digits = 0;
  const char* p = first;
  while (p != last && p - first < 18 && static_cast<unsigned>(*p - '0') < 10)
    digits = 10 * digits + static_cast<unsigned>(*p++ - '0');
  if (p != first && (p == last || static_cast<unsigned>(*p - '0') >= 10)) {
    value = static_cast<std::int64_t>(digits);
    return p;
  }
  if (first != last && *first == '+') {
    ++first;
    if (first != last && (*first == '-' || *first == '+'))
      return nullptr;
  }
  const auto [end, error] = std::from_chars(first, last, value, 10);
  return error == std::errc() ? end : nullptr;
}

}  // namespace meshbridge::detail
