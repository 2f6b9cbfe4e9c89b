// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file ply_header.h
//! The PLY header: format, elements and their properties with scalar types and sizes.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace meshbridge::detail {

//! The eight PLY scalar types (both naming schemes: char/int8 ... double/float64).
enum class PlyScalar : std::uint8_t { i8, u8, i16, u16, i32, u32, f32, f64 };

//! Size in bytes of a PLY scalar in binary files.
std::size_t ply_scalar_size(PlyScalar type);
//! True for the six integer types.
bool is_ply_integer(PlyScalar type);
//! True for the blanks that separate the words of a PLY line (space, tab, '\r', '\f', '\v').
bool is_ply_blank(char c);
//! The blank-separated words of one line of a PLY header or ascii body.
std::vector<std::string_view> ply_line_words(std::string_view line);

//! The type's name as PLY writes it ("char", "uchar", ..., "double").
const char* ply_scalar_name(PlyScalar type);

//! One property of an element: a scalar or a list (a count, then that many entries).
struct PlyProperty {
  std::string name;
  PlyScalar type = PlyScalar::f32;       //!< the scalar, or the entry type of a list
  PlyScalar count_type = PlyScalar::u8;  //!< lists only
  bool is_list = false;
};

//! One element of the header ("vertex", "face", "tristrips", "edge", or anything else).
struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  //! Index of the property named `name`, or -1.
  int find(std::string_view property) const;
  //! Bytes of one item in a binary file when it has no list property; 0 otherwise.
  std::size_t fixed_size() const;
  //! Fewest bytes one item takes in a binary file (lists empty).
  std::size_t min_size() const;
};

//! A parsed PLY header.
struct PlyHeader {
  enum class Format { ascii, binary_little_endian, binary_big_endian };
  Format format = Format::ascii;
  std::vector<PlyElement> elements;
  std::size_t body = 0;  //!< byte offset of the first data byte after "end_header\n"
  //! `comment` and `obj_info` lines, MeshBridge's own "comment written by MeshBridge" aside.
  std::size_t comments = 0;
  //! Lines that are neither keywords nor comments ("Created by Blender3D 247 ..."), read past as
  //! MeshLab's and Blender's readers do; the first one, for the warning.
  std::size_t unknown_lines = 0;
  std::string first_unknown_line;
  std::size_t first_unknown_line_number = 0;
};

//! Parses the header at the start of `data` (a whole file).
//! A line that starts with no keyword is counted in `unknown_lines` and read past.
//! \throw ReadError naming `path` and the problem: not a PLY file, unknown format or version,
//! unknown scalar type, property before any element, an element declared twice, a count that is
//! not a non-negative integer, or no end_header line.
PlyHeader parse_ply_header(std::string_view data, const std::string& path);

}  // namespace meshbridge::detail
