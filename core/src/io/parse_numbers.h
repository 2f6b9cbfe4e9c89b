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
