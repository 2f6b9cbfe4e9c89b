// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The values of a PLY body, one source per encoding: binary (either byte order) and ascii.

#include "io/parse_numbers.h"
#include "io/ply_header.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace meshbridge::detail {

// --- ascii values ---------------------------------------------------------------------------

//! The range of an integer PLY type (int8 -128..127 ... uint32 0..4294967295).
inline void ply_integer_range(PlyScalar type, std::int64_t& lowest, std::int64_t& highest) {
  // In the order of PlyScalar: i8, u8, i16, u16, i32, u32 (the float types are never asked).
  static constexpr std::int64_t kLowest[] = {-128, 0, -32768, 0, -2147483648LL, 0};
  static constexpr std::int64_t kHighest[] = {127, 255, 32767, 65535, 2147483647, 4294967295LL};
  const int t = std::min(static_cast<int>(type), 5);
  lowest = kLowest[t];
  highest = kHighest[t];
}

//! Parses the ascii value at [first, last) as an integer of `type` (an integer type): a whole
//! number within the type's range, as the binary encoding could store it. Returns the end of the
//! number, or nullptr ("1.5", "300" for uchar, "-1" for uint).
inline const char* parse_ply_integer(const char* first, const char* last, PlyScalar type,
                                     std::int64_t& value) {
  const char* end = parse_integer(first, last, value);
  std::int64_t lowest = 0, highest = 0;
  ply_integer_range(type, lowest, highest);
  return end != nullptr && value >= lowest && value <= highest ? end : nullptr;
}

//! Parses the ascii value at [first, last) as a value of `type`: for an integer type as
//! parse_ply_integer; `float` a number within float's range (or nan, inf: a binary float holds
//! them too), rounded to float as the binary encoding would store it (so ascii and binary PLY of
//! one mesh read the same); `double` any number. Returns the end of the value, or nullptr ("x",
//! "1e40" for float). A non-finite coordinate is the soup's to refuse (validate_soup).
inline const char* parse_ply_value(const char* first, const char* last, PlyScalar type,
                                   double& value) {
  if (is_ply_integer(type)) {
    std::int64_t whole = 0;
    const char* end = parse_ply_integer(first, last, type, whole);
    if (end != nullptr)
      value = static_cast<double>(whole);
    return end;
  }
  double number = 0;
  const char* end = parse_double(first, last, number);
  if (end == nullptr)
    return nullptr;
  if (type == PlyScalar::f32 && number - number == 0) {  // finite (inf - inf, nan - nan: nan)
    if (number > 3.4028234663852886e38 || number < -3.4028234663852886e38)
      return nullptr;
    number = static_cast<float>(number);
  }
  value = number;
  return end;
}

// --- binary values --------------------------------------------------------------------------

template <class T>
T load(const unsigned char* p, bool swap) {
  unsigned char bytes[sizeof(T)];
  if (swap) {
    for (std::size_t i = 0; i < sizeof(T); ++i)
      bytes[i] = p[sizeof(T) - 1 - i];
  } else {
    std::memcpy(bytes, p, sizeof(T));
  }
  T value;
  std::memcpy(&value, bytes, sizeof(T));
  return value;
}

inline double load_real(const unsigned char* p, PlyScalar type, bool swap) {
  switch (type) {
    case PlyScalar::i8:
      return load<std::int8_t>(p, swap);
    case PlyScalar::u8:
      return load<std::uint8_t>(p, swap);
    case PlyScalar::i16:
      return load<std::int16_t>(p, swap);
    case PlyScalar::u16:
      return load<std::uint16_t>(p, swap);
    case PlyScalar::i32:
      return load<std::int32_t>(p, swap);
    case PlyScalar::u32:
      return load<std::uint32_t>(p, swap);
    case PlyScalar::f32:
      return load<float>(p, swap);
    case PlyScalar::f64:
      return load<double>(p, swap);
  }
  return 0;
}

inline std::int64_t load_integer(const unsigned char* p, PlyScalar type, bool swap) {
  switch (type) {
    case PlyScalar::i8:
      return load<std::int8_t>(p, swap);
    case PlyScalar::u8:
      return load<std::uint8_t>(p, swap);
    case PlyScalar::i16:
      return load<std::int16_t>(p, swap);
    case PlyScalar::u16:
      return load<std::uint16_t>(p, swap);
    case PlyScalar::i32:
      return load<std::int32_t>(p, swap);
    case PlyScalar::u32:
      return load<std::uint32_t>(p, swap);
    default:
      return 0;  // the header parser allows only integer types here
  }
}

// --- one value source per encoding ----------------------------------------------------------

//! Values of a binary body, checked against the end of the file.
class BinarySource {
 public:
  BinarySource(const char* first, const char* last, bool big_endian)
      : p_(reinterpret_cast<const unsigned char*>(first)),
        end_(reinterpret_cast<const unsigned char*>(last)),
        swap_(big_endian) {}
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }
  bool real(PlyScalar type, double& value) {
    const std::size_t n = ply_scalar_size(type);
    if (remaining() < n)
      return false;
    value = load_real(p_, type, swap_);
    p_ += n;
    return true;
  }
  bool integer(PlyScalar type, std::int64_t& value) {
    const std::size_t n = ply_scalar_size(type);
    if (remaining() < n)
      return false;
    value = is_ply_integer(type) ? load_integer(p_, type, swap_) : 0;
    p_ += n;
    return true;
  }
  bool skip(PlyScalar type, std::uint64_t count = 1) {
    const std::uint64_t n = ply_scalar_size(type) * count;
    if (count > remaining() || n > remaining())
      return false;
    p_ += n;
    return true;
  }
  //! Could `count` more values of `type` still be in the file?
  bool can_hold(PlyScalar type, std::uint64_t count) const {
    return count <= remaining() / ply_scalar_size(type);
  }
  const unsigned char* position() const { return p_; }
  void advance(std::size_t n) { p_ += n; }
  bool swaps() const { return swap_; }

 private:
  const unsigned char* p_;
  const unsigned char* end_;
  bool swap_;
};

//! Values of an ascii body: words separated by blanks or line ends.
class AsciiSource {
 public:
  AsciiSource(const char* first, const char* last) : p_(first), end_(last) {}
  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }
  //! A value of the declared type (parse_ply_value: a float rounded to float, an integer type
  //! within its range); false for anything else.
  bool real(PlyScalar type, double& value) {
    skip_space();
    const char* e = parse_ply_value(p_, end_, type, value);
    if (e == nullptr || (e != end_ && !is_space(*e)))
      return false;
    p_ = e;
    return true;
  }
  //! A list count, list entry or edge vertex: a whole number within the declared type's range.
  bool integer(PlyScalar type, std::int64_t& value) {
    skip_space();
    const char* e = is_ply_integer(type) ? parse_ply_integer(p_, end_, type, value)
                                         : parse_integer(p_, end_, value);
    if (e == nullptr || (e != end_ && !is_space(*e)))
      return false;
    p_ = e;
    return true;
  }
  //! Skips `count` values of `type`, each checked as real() checks it (a property MeshBridge
  //! does not keep still holds a value of its type, so every reader of the file agrees on it).
  bool skip(PlyScalar type, std::uint64_t count = 1) {
    double value = 0;
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!real(type, value))
        return false;
    }
    return true;
  }
  //! True if only blanks and line ends are left.
  bool only_space_left() {
    skip_space();
    return p_ == end_;
  }
  //! Every ascii value takes at least two bytes but the last ("0 ").
  bool can_hold(PlyScalar, std::uint64_t count) const { return count <= remaining() / 2 + 1; }

 private:
  static bool is_space(char c) {
    return c == ' ' || c == '\n' || c == '\r' || c == '\t' || c == '\v' || c == '\f';
  }
  void skip_space() {
    while (p_ != end_ && is_space(*p_))
      ++p_;
  }
  const char* p_;
  const char* end_;
};

}  // namespace meshbridge::detail
