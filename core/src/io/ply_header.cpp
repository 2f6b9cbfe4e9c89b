// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ply_header.h"

#include "io/formats.h"

#include "meshbridge/errors.h"

#include <algorithm>
#include <charconv>
#include <utility>

namespace meshbridge::detail {

namespace {

bool parse_ply_scalar(std::string_view name, PlyScalar& type) {
  static const std::pair<std::string_view, PlyScalar> kNames[] = {
      {"char", PlyScalar::i8},    {"int8", PlyScalar::i8},     {"uchar", PlyScalar::u8},
      {"uint8", PlyScalar::u8},   {"short", PlyScalar::i16},   {"int16", PlyScalar::i16},
      {"ushort", PlyScalar::u16}, {"uint16", PlyScalar::u16},  {"int", PlyScalar::i32},
      {"int32", PlyScalar::i32},  {"uint", PlyScalar::u32},    {"uint32", PlyScalar::u32},
      {"float", PlyScalar::f32},  {"float32", PlyScalar::f32}, {"double", PlyScalar::f64},
      {"float64", PlyScalar::f64}};
  for (const auto& [text, value] : kNames) {
    if (text == name) {
      type = value;
      return true;
    }
  }
  return false;
}

}  // namespace

bool is_ply_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

std::vector<std::string_view> ply_line_words(std::string_view line) {
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_ply_blank(line[i]))
      ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_ply_blank(line[i]))
      ++i;
    if (i > start)
      words.push_back(line.substr(start, i - start));
  }
  return words;
}

std::size_t ply_scalar_size(PlyScalar type) {
  switch (type) {
    case PlyScalar::i8:
    case PlyScalar::u8:
      return 1;
    case PlyScalar::i16:
    case PlyScalar::u16:
      return 2;
    case PlyScalar::i32:
    case PlyScalar::u32:
    case PlyScalar::f32:
      return 4;
    case PlyScalar::f64:
      return 8;
  }
  return 0;
}

bool is_ply_integer(PlyScalar type) {
  return type != PlyScalar::f32 && type != PlyScalar::f64;
}

const char* ply_scalar_name(PlyScalar type) {
  static const char* const kNames[] = {"char", "uchar", "short", "ushort",
                                       "int",  "uint",  "float", "double"};
  return kNames[static_cast<int>(type)];
}

int PlyElement::find(std::string_view property) const {
  for (std::size_t i = 0; i < properties.size(); ++i) {
    if (properties[i].name == property)
      return static_cast<int>(i);
  }
  return -1;
}

std::size_t PlyElement::fixed_size() const {
  std::size_t size = 0;
  for (const PlyProperty& p : properties) {
    if (p.is_list)
      return 0;
    size += ply_scalar_size(p.type);
  }
  return size;
}

std::size_t PlyElement::min_size() const {
  std::size_t size = 0;
  for (const PlyProperty& p : properties)
    size += ply_scalar_size(p.is_list ? p.count_type : p.type);
  return size;
}

PlyHeader parse_ply_header(std::string_view data, const std::string& path) {
  const std::string where = path + ": ";
  PlyHeader header;
  // A UTF-8 byte order mark that a text editor put before "ply" is skipped, as in OBJ and OFF.
  std::size_t pos = data.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;
  std::size_t line_number = 0;
  bool has_format = false;
  // Returns the next line without its end of line; false at the end of the data.
  const auto next_line = [&](std::string_view& line) {
    if (pos >= data.size())
      return false;
    std::size_t end = data.find('\n', pos);
    if (end == std::string_view::npos)
      end = data.size();
    line = data.substr(pos, end - pos);
    pos = end + 1;
    ++line_number;
    return true;
  };
  std::string_view line;
  const bool has_line = next_line(line);
  const std::vector<std::string_view> first = ply_line_words(line);
  if (has_line && !first.empty() && (first[0] == "ply" || first[0] == "PLY") &&
      line.find('\r') != std::string_view::npos && line.find('\r') + 1 < line.size()) {
    throw ReadError(where +
                    "its header lines end in CR alone (classic Mac OS text); PLY headers end "
                    "in LF or CRLF: convert the file first (tr '\\r' '\\n' for ascii PLY)");
  }
  if (!has_line || first.size() != 1 || (first[0] != "ply" && first[0] != "PLY")) {
    std::string start(first.empty() ? std::string_view() : first[0].substr(0, 16));
    for (char& c : start)
      c = c >= 32 && c < 127 ? c : '?';
    throw ReadError(where + "not a PLY file: it starts with '" + start + "', not 'ply'" +
                    other_format_hint(data, Format::ply));
  }
  while (true) {
    if (!next_line(line)) {
      throw ReadError(where + "the PLY header has no end_header line (a truncated or " +
                      "malformed header)");
    }
    const std::vector<std::string_view> w = ply_line_words(line);
    const std::string at = where + "PLY header line " + std::to_string(line_number) + ": ";
    if (w.empty())
      continue;
    if (w[0] == "comment" || w[0] == "obj_info") {
      header.comments += line.find("comment written by MeshBridge") == std::string_view::npos;
      continue;
    }
    if (w[0] == "end_header") {
      if (!has_format)
        throw ReadError(where + "the PLY header has no format line");
      header.body = pos > data.size() ? data.size() : pos;
      return header;
    }
    if (w[0] == "format") {
      if (w.size() < 2)
        throw ReadError(at + "format without a name");
      if (w[1] == "ascii") {
        header.format = PlyHeader::Format::ascii;
      } else if (w[1] == "binary_little_endian") {
        header.format = PlyHeader::Format::binary_little_endian;
      } else if (w[1] == "binary_big_endian") {
        header.format = PlyHeader::Format::binary_big_endian;
      } else {
        throw ReadError(at + "Unsupported PLY format: " + std::string(w[1]) +
                        " (expected ascii, binary_little_endian or binary_big_endian)");
      }
      if (w.size() < 3 || (w[2] != "1.0" && w[2] != "1")) {
        throw ReadError(at + "unsupported PLY version '" +
                        std::string(w.size() < 3 ? std::string_view() : w[2]) + "' (expected 1.0)");
      }
      has_format = true;
    } else if (w[0] == "element") {
      if (w.size() != 3)
        throw ReadError(at + "expected 'element NAME COUNT'");
      PlyElement element;
      element.name = std::string(w[1]);
      const auto [end, error] =
          std::from_chars(w[2].data(), w[2].data() + w[2].size(), element.count);
      if (error != std::errc() || end != w[2].data() + w[2].size()) {
        throw ReadError(at + "PLY element '" + element.name + "' has count '" + std::string(w[2]) +
                        "', not a non-negative integer");
      }
      for (const PlyElement& e : header.elements) {
        if (e.name == element.name)
          throw ReadError(at + "PLY element '" + element.name + "' is declared twice");
      }
      header.elements.push_back(std::move(element));
    } else if (w[0] == "property") {
      if (header.elements.empty())
        throw ReadError(at + "PLY property before any element in the header");
      PlyProperty property;
      std::string_view type_name;
      if (w.size() == 5 && w[1] == "list") {
        property.is_list = true;
        if (!parse_ply_scalar(w[2], property.count_type) || !is_ply_integer(property.count_type))
          throw ReadError(at + "list count type '" + std::string(w[2]) +
                          "' is not an integer type");
        type_name = w[3];
        property.name = std::string(w[4]);
      } else if (w.size() == 3) {
        type_name = w[1];
        property.name = std::string(w[2]);
      } else {
        throw ReadError(at + "expected 'property TYPE NAME' or 'property list TYPE TYPE NAME'");
      }
      if (!parse_ply_scalar(type_name, property.type)) {
        throw ReadError(at + "PLY property '" + property.name + "' of element '" +
                        header.elements.back().name + "' has unknown type '" +
                        std::string(type_name) + "'");
      }
      if (header.elements.back().find(property.name) >= 0) {
        throw ReadError(at + "PLY element '" + header.elements.back().name + "' has property '" +
                        property.name + "' twice");
      }
      header.elements.back().properties.push_back(std::move(property));
    } else {  // a line of free text (Blender 2.47's "Created by Blender3D 247 ..."): read past
      if (header.unknown_lines++ == 0) {
        header.first_unknown_line = std::string(
            line.substr(0, std::min<std::size_t>(60, line.find_last_not_of(" \t\r") + 1)));
        header.first_unknown_line_number = line_number;
      }
    }
  }
}

}  // namespace meshbridge::detail
