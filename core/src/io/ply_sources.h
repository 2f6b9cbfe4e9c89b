// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The values of a PLY body, one source per encoding: binary (either byte order) and ascii.

#include "io/parse_numbers.h"
#include "io/ply_header.h"

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace meshbridge::detail {

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
  //! A value declared `float` is rounded to float, as the binary encoding of the same file
  //! would store it (so ascii and binary PLY of one mesh read the same).
  bool real(PlyScalar type, double& value) {
    skip_space();
    const char* e = parse_double(p_, end_, value);
    if (e == nullptr || (e != end_ && !is_space(*e)))
      return false;
    if (type == PlyScalar::f32)
      value = static_cast<float>(value);
    p_ = e;
    return true;
  }
  bool integer(PlyScalar, std::int64_t& value) {
    skip_space();
    const char* e = parse_integer(p_, end_, value);
    if (e == nullptr || (e != end_ && !is_space(*e)))
      return false;
    p_ = e;
    return true;
  }
  bool skip(PlyScalar, std::uint64_t count = 1) {
    for (std::uint64_t i = 0; i < count; ++i) {
      skip_space();
      if (p_ == end_)
        return false;
      while (p_ != end_ && !is_space(*p_))
        ++p_;
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
