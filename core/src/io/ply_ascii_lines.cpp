// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ply_ascii_lines.h"

#include "io/parse_numbers.h"
#include "meshbridge/counted.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace meshbridge::detail {

namespace {

//! True if `word` is a whole value as the reader takes it: a number, and for `integer` (list
//! counts, polygon corners) an integer ("1.5" and "nan" are not).
bool is_value(bool integer, std::string_view word) {
  const char* first = word.data();
  const char* last = first + word.size();
  if (integer) {
    std::int64_t value = 0;
    return parse_integer(first, last, value) == last;
  }
  double value = 0;
  return parse_double(first, last, value) == last;
}

std::string property_names(const PlyElement& e) {
  std::string names;
  for (const PlyProperty& p : e.properties)
    names += (names.empty() ? "" : ", ") + p.name;
  return names;
}

//! How a line fails the properties of `e`, or empty.
std::string mismatch(const PlyElement& e, const std::vector<std::string_view>& words) {
  std::size_t w = 0;
  for (const PlyProperty& p : e.properties) {
    if (w == words.size())
      return "the line ends before property '" + p.name + "'";
    if (!p.is_list) {
      if (!is_value(false, words[w]))
        return "property '" + p.name + "' is '" + std::string(words[w]) + "', not a number";
      ++w;
      continue;
    }
    std::int64_t n = 0;
    const std::string_view count = words[w];
    if (parse_integer(count.data(), count.data() + count.size(), n) !=
            count.data() + count.size() ||
        n < 0) {
      return "the count of list '" + p.name + "' is '" + std::string(count) +
             "', not a whole number";
    }
    ++w;
    if (words.size() - w < static_cast<std::uint64_t>(n)) {
      return "list '" + p.name + "' counts " + std::to_string(n) + " entries, but the line holds " +
             std::to_string(words.size() - w);
    }
    const bool corners = p.name == "vertex_indices" || p.name == "vertex_index";
    for (std::int64_t k = 0; k < n; ++k, ++w) {
      if (corners && !is_value(true, words[w]))
        return "entry " + std::to_string(k + 1) + " of list '" + p.name + "' is '" +
               std::string(words[w]) + "', not a vertex index";
    }
  }
  if (w < words.size()) {
    return counted(words.size(), "value") + " where the header's properties (" + property_names(e) +
           ") take " + std::to_string(w);
  }
  return {};
}

}  // namespace

std::optional<std::string> locate_ascii_ply_mismatch(std::string_view file,
                                                     const PlyHeader& header) {
  std::size_t line_number =
      1 + static_cast<std::size_t>(std::count(file.begin(), file.begin() + header.body, '\n'));
  std::size_t at = header.body;
  const auto next_line = [&]() -> std::optional<std::string_view> {
    while (at < file.size()) {
      const std::size_t end = std::min(file.find('\n', at), file.size());
      const std::string_view line = file.substr(at, end - at);
      const bool blank = std::all_of(line.begin(), line.end(), is_ply_blank);
      at = end + 1;
      ++line_number;
      if (!blank)
        return line;
    }
    return std::nullopt;
  };
  for (const PlyElement& e : header.elements) {
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const std::optional<std::string_view> line = next_line();
      if (!line) {
        return "the file ends after line " + std::to_string(line_number - 1) + ", before " +
               e.name + " " + std::to_string(i + 1) + " of " + std::to_string(e.count) +
               " (a truncated file or a false count)";
      }
      const std::string fault = mismatch(e, ply_line_words(*line));
      if (!fault.empty()) {
        return "line " + std::to_string(line_number - 1) + ", " + e.name + " " +
               std::to_string(i + 1) + " of " + std::to_string(e.count) + ": " + fault +
               " (a malformed line, or a false element count before it)";
      }
    }
  }
  if (const std::optional<std::string_view> line = next_line()) {
    return "line " + std::to_string(line_number - 1) + ": values after the last declared item (" +
           (header.elements.empty() ? std::string("no element")
                                    : header.elements.back().name + " " +
                                          std::to_string(header.elements.back().count)) +
           "): a false element count, or text after the mesh";
  }
  return std::nullopt;
}

}  // namespace meshbridge::detail
