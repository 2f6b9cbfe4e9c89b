// SPDX-License-Identifier: GPL-3.0-or-later
// Why the scan reads what pugixml reads: pugixml, as mesh_xml_3mf.cpp calls it (parse_minimal:
// no entity, no end-of-line or whitespace conversion), gives an attribute's value as the bytes
// between its quotes and skips whitespace between elements; that route then takes a value only
// when std::from_chars reads all of it. The scan takes only elements whose name is followed by
// whitespace, attributes named exactly x, y, z (v1, v2, v3) each once, written name="value" or
// name='value' and followed by whitespace or "/>", and values that a number takes whole: on
// such text both routes see the same bytes, and the numbers are read the same way (below).
#include "io/mesh_scan_3mf.h"

#include <charconv>
#include <cmath>
#include <cstring>

namespace meshbridge::detail {

namespace {

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

inline bool is_digit(char c) {
  return static_cast<unsigned char>(c - '0') < 10;
}

// The value of an attribute whose opening quote is at `p`: [value, past) without its quotes;
// returns the byte after the closing quote, or nullptr where that is not whitespace or '/'.
inline const char* quoted(const char* p, const char* end, const char*& value, const char*& past) {
  if (p >= end || (*p != '"' && *p != '\''))
    return nullptr;
  value = p + 1;
  past = value;  // a loop, not memchr: values are a few bytes, a call costs more
  while (past < end && *past != *p)
    ++past;
  if (past + 1 >= end || !(is_space(past[1]) || past[1] == '/'))
    return nullptr;
  return past + 1;
}

// [text, past) whole as a double, as std::from_chars reads it (correctly rounded). Digits with at
// most one '.' inside, 19 digits at most, whose whole number fits in 53 bits and at most 22 after
// the point, are read as (digits as an integer) / 10^(digits after the point): both exact in a
// double, so the one division rounds correctly too (Clinger's fast path), to the value
// from_chars gives. Everything else goes to from_chars itself.
constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
                              1e8,  1e9,  1e10, 1e11, 1e12, 1e13, 1e14, 1e15,
                              1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

inline bool read_double(const char* text, const char* past, double& value) {
  const char* p = text;
  const bool negative = p < past && *p == '-';
  p += negative;
  std::uint64_t digits = 0;
  const char* first = p;
  while (p < past && is_digit(*p))
    digits = digits * 10 + std::uint64_t(*p++ - '0');
  std::size_t whole = std::size_t(p - first), after = 0;
  if (whole > 0 && p + 1 < past && *p == '.' && is_digit(p[1])) {
    const char* point = ++p;
    while (p < past && is_digit(*p))
      digits = digits * 10 + std::uint64_t(*p++ - '0');
    after = std::size_t(p - point);
  }
  if (p == past && whole > 0 && whole + after <= 19 && digits <= (std::uint64_t(1) << 53) &&
      after <= 22) {
    const double d = double(digits) / kPowers[after];
    value = negative ? -d : d;
    return true;
  }
  const auto result = std::from_chars(text, past, value);
  return result.ec == std::errc() && result.ptr == past;
}

// The decimal digits at `p`, 8 bytes of which may be read: how many (at most 8; a run of 8 may
// go on), their value into `value`. Eight bytes at once: a byte is a digit when its high nibble
// is 3 and stays 3 with 6 added (a carry out of a byte that is no digit only reaches bytes after
// the first that is none); the digits are then moved to the top, and summed in pairs, fours and
// eights (the usual SWAR sum, as in simdjson and fast_float).
inline std::size_t digit_run(const char* p, std::uint64_t& value) {
  std::uint64_t v;
  std::memcpy(&v, p, 8);
  constexpr std::uint64_t kNibbles = 0xf0f0f0f0f0f0f0f0u, kThrees = 0x3030303030303030u;
  const std::uint64_t not_digits =
      ((v & kNibbles) ^ kThrees) | (((v + 0x0606060606060606u) & kNibbles) ^ kThrees);
  const std::size_t count = not_digits == 0 ? 8 : std::size_t(__builtin_ctzll(not_digits)) / 8;
  if (count == 0)
    return 0;
  v = (v << (8 * (8 - count)) & 0x0f0f0f0f0f0f0f0fu);  // leading zeros below the digits
  v = v * 10 + (v >> 8);
  constexpr std::uint64_t kMask = 0x000000ff000000ffu;
  value = (((v & kMask) * (100 + (std::uint64_t(1000000) << 32)) +
            ((v >> 16) & kMask) * (1 + (std::uint64_t(10000) << 32))) >>
           32) &
          0xffffffffu;
  return count;
}

// The number at `p` up to a '"', when it is one that read_double() reads by its fast path
// (digits, a '.' with digits after it, 19 digits at most, ...): its value, and where the '"'
// is; nullptr for any other (the general path then reads it, the same way as before).
inline const char* fast_double(const char* p, const char* end, double& value) {
  const bool negative = p < end && *p == '-';
  p += negative;
  std::uint64_t digits = 0;
  const char* first = p;
  while (p < end && is_digit(*p))
    digits = digits * 10 + std::uint64_t(*p++ - '0');
  const std::size_t whole = std::size_t(p - first);
  std::size_t after = 0;
  if (whole == 0 || p >= end)
    return nullptr;
  if (*p == '.') {
    const char* point = ++p;
    while (p < end && is_digit(*p))
      digits = digits * 10 + std::uint64_t(*p++ - '0');
    after = std::size_t(p - point);
    if (after == 0)
      return nullptr;
  }
  if (p >= end || *p != '"' || whole + after > 19 || digits > (std::uint64_t(1) << 53) ||
      after > 22) {
    return nullptr;
  }
  const double d = double(digits) / kPowers[after];
  value = negative ? -d : d;
  return p;
}

// The index at `p` up to a '"', as read_index() reads it; nullptr where it would not.
inline const char* fast_index(const char* p, const char* end, std::uint32_t& value) {
  std::uint64_t n = 0;
  if (end - p >= 8) {  // up to 7 digits, 8 bytes at a time
    const std::size_t count = digit_run(p, n);
    if (count - 1 < 7) {
      if (p[count] != '"')
        return nullptr;
      value = static_cast<std::uint32_t>(n);
      return p + count;
    }
    n = 0;
  }
  const char* first = p;
  while (p < end && is_digit(*p) && p - first < 11)
    n = n * 10 + std::uint64_t(*p++ - '0');
  if (p == first || p >= end || *p != '"' || p - first > 10 || n > 0xffffffffu)
    return nullptr;
  value = static_cast<std::uint32_t>(n);
  return p;
}

// The element at `p` in the form writers use ("<vertex x=\"1.5\" y=\"0\" z=\"-2\"/>": attributes in
// order, one space apart, double quotes), its numbers read by read(k, p) (the '"' after it, or
// nullptr) and then element(): the byte after it, or nullptr where anything differs (the
// general path then reads the element, and decides).
template <std::size_t kOpen, class Read, class Element>
inline const char* fast_element(const char* p, const char* end, const char (&open)[kOpen],
                                const char* const (&between)[2], std::size_t between_length,
                                Read read, Element element) {
  if (std::size_t(end - p) < kOpen - 1 || std::memcmp(p, open, kOpen - 1) != 0)
    return nullptr;
  p += kOpen - 1;
  for (int k = 0; k < 3; ++k) {
    p = read(k, p);
    if (p == nullptr)
      return nullptr;
    if (k < 2) {
      if (std::size_t(end - p) < between_length || std::memcmp(p, between[k], between_length) != 0)
        return nullptr;
      p += between_length;
    }
  }
  if (std::size_t(end - p) >= 3 && std::memcmp(p, "\"/>", 3) == 0)
    p += 3;
  else if (std::size_t(end - p) >= 4 && std::memcmp(p, "\" />", 4) == 0)
    p += 4;
  else
    return nullptr;
  return element() ? p : nullptr;
}

// [text, past) whole as an unsigned 32-bit number (decimal digits only, as from_chars reads it).
inline bool read_index(const char* text, const char* past, std::uint32_t& value) {
  if (text == past || past - text > 10)
    return false;
  std::uint64_t n = 0;
  for (const char* p = text; p < past; ++p) {
    if (!is_digit(*p))
      return false;
    n = n * 10 + std::uint64_t(*p - '0');
  }
  if (n > 0xffffffffu)
    return false;
  value = static_cast<std::uint32_t>(n);
  return true;
}

// Scans the list [begin, end) of elements named `name` (`length` bytes) whose attributes are
// `first` followed by one character from `low` to `high` (first == 0: that character alone):
// calls value(k, text, past) for attribute k, then element() when all three were given. Returns
// `end` when all of the text was read, else where the element it stopped at begins (one that
// value() or element() refused, that leaves the narrow form, or that `end` cuts off).
template <class Fast, class Value, class Element>
const char* scan(const char* begin, const char* end, const char* name, std::size_t length,
                 char first, char low, Fast fast, Value value, Element element) {
  const char* p = begin;
  const std::size_t skip = first != 0 ? 1 : 0;
  for (;;) {
    while (p < end && is_space(*p))
      ++p;
    if (p == end)
      return end;
    const char* const start = p;
    if (const char* past = fast(p, end)) {
      p = past;
      continue;
    }
    if (std::size_t(end - p) < length + 2 || p[0] != '<' || std::memcmp(p + 1, name, length) != 0 ||
        !is_space(p[length + 1])) {
      return start;
    }
    p += length + 2;
    int given = 0;
    for (;;) {
      while (p < end && is_space(*p))
        ++p;
      if (p + 1 >= end)
        return start;
      if (*p == '/') {
        if (p[1] != '>')
          return start;
        p += 2;
        break;
      }
      if (skip != 0 && *p != first)
        return start;
      const int k = p[skip] - low;
      if (k < 0 || k > 2 || p + skip + 1 >= end || p[skip + 1] != '=' || (given >> k & 1) != 0)
        return start;
      const char *text = nullptr, *past = nullptr;
      p = quoted(p + skip + 2, end, text, past);
      if (p == nullptr || !value(k, text, past))
        return start;
      given |= 1 << k;
    }
    if (given != 7 || !element())
      return start;
  }
}

}  // namespace

const char* scan_vertices_until(const char* begin, const char* end, std::vector<Point>& positions) {
  double xyz[3];
  const auto element = [&] {
    float f[3];
    for (int k = 0; k < 3; ++k) {
      f[k] = static_cast<float>(xyz[k]);
      if (!std::isfinite(f[k]) || std::abs(f[k]) > 1e9f)
        return false;  // lib3mf's limit: the pugixml route refuses it
    }
    positions.emplace_back(f[0], f[1], f[2]);
    return true;
  };
  static const char* const kBetween[2] = {"\" y=\"", "\" z=\""};
  return scan(
      begin, end, "vertex", 6, 0, 'x',
      [&](const char* p, const char* stop) {
        return fast_element(
            p, stop, "<vertex x=\"", kBetween, 5,
            [&](int k, const char* at) { return fast_double(at, stop, xyz[k]); }, element);
      },
      [&](int k, const char* text, const char* past) { return read_double(text, past, xyz[k]); },
      element);
}

bool scan_vertices(const char* begin, const char* end, std::vector<Point>& positions) {
  const std::size_t before = positions.size();
  const bool read = scan_vertices_until(begin, end, positions) == end;
  if (!read)
    positions.resize(before);
  return read;
}

const char* scan_triangles_until(const char* begin, const char* end, std::size_t vertex_count,
                                 std::vector<std::uint32_t>& corners) {
  std::uint32_t v[3];
  const auto element = [&] {
    if (v[0] >= vertex_count || v[1] >= vertex_count || v[2] >= vertex_count || v[0] == v[1] ||
        v[1] == v[2] || v[0] == v[2]) {
      return false;
    }
    corners.push_back(v[0]);
    corners.push_back(v[1]);
    corners.push_back(v[2]);
    return true;
  };
  static const char* const kBetween[2] = {"\" v2=\"", "\" v3=\""};
  return scan(
      begin, end, "triangle", 8, 'v', '1',
      [&](const char* p, const char* stop) {
        return fast_element(
            p, stop, "<triangle v1=\"", kBetween, 6,
            [&](int k, const char* at) { return fast_index(at, stop, v[k]); }, element);
      },
      [&](int k, const char* text, const char* past) { return read_index(text, past, v[k]); },
      element);
}

bool scan_triangles(const char* begin, const char* end, std::size_t vertex_count,
                    std::vector<std::uint32_t>& corners) {
  const std::size_t before = corners.size();
  const bool read = scan_triangles_until(begin, end, vertex_count, corners) == end;
  if (!read)
    corners.resize(before);
  return read;
}

}  // namespace meshbridge::detail
