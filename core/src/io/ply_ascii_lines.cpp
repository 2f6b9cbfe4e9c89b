// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ply_ascii_lines.h"

#include "io/parse_numbers.h"
#include "io/ply_sources.h"
#include "meshbridge/counted.h"

#include <algorithm>
#include <cstdint>
#include <vector>

namespace meshbridge::detail {

namespace {

//! How `word` fails to be a value of `type` as the reader takes it (parse_ply_value), or empty:
//! "not a number", "not a whole number", "outside the range of uchar (0 to 255)", ...
std::string value_fault(PlyScalar type, std::string_view word) {
  const char* first = word.data();
  const char* last = first + word.size();
  double value = 0;
  if (parse_ply_value(first, last, type, value) == last)
    return {};
  if (is_ply_integer(type)) {
    std::int64_t whole = 0;
    if (parse_integer(first, last, whole) != last) {
      return parse_double(first, last, value) == last
                 ? "not a whole number (" + std::string(ply_scalar_name(type)) + ")"
                 : "not a number";
    }
    std::int64_t lowest = 0, highest = 0;
    ply_integer_range(type, lowest, highest);
    return "outside the range of " + std::string(ply_scalar_name(type)) + " (" +
           std::to_string(lowest) + " to " + std::to_string(highest) + ")";
  }
  if (parse_double(first, last, value) != last)
    return "not a number";
  return "outside the range of " + std::string(ply_scalar_name(type));
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
      const std::string fault = value_fault(p.type, words[w]);
      if (!fault.empty())
        return "property '" + p.name + "' is '" + std::string(words[w]) + "', " + fault;
      ++w;
      continue;
    }
    std::int64_t n = 0;
    const std::string_view count = words[w];
    if (const std::string fault = value_fault(p.count_type, count); !fault.empty()) {
      return "the count of list '" + p.name + "' is '" + std::string(count) + "', " + fault;
    }
    parse_integer(count.data(), count.data() + count.size(), n);
    if (n < 0)
      return "the count of list '" + p.name + "' is '" + std::string(count) + "', negative";
    ++w;
    if (words.size() - w < static_cast<std::uint64_t>(n)) {
      return "list '" + p.name + "' counts " + std::to_string(n) + " entries, but the line holds " +
             std::to_string(words.size() - w);
    }
    for (std::int64_t k = 0; k < n; ++k, ++w) {
      if (const std::string fault = value_fault(p.type, words[w]); !fault.empty()) {
        return "entry " + std::to_string(k + 1) + " of list '" + p.name + "' is '" +
               std::string(words[w]) + "', " + fault;
      }
    }
  }
  if (w < words.size()) {
    return counted(words.size(), "value") + " where the header's properties (" + property_names(e) +
           ") take " + std::to_string(w);
  }
  return {};
}

//! The non-blank lines of an ascii PLY body, in order, with their numbers.
class BodyLines {
 public:
  BodyLines(std::string_view file, const PlyHeader& header)
      : file_(file),
        at_(header.body),
        line_number_(1 + static_cast<std::size_t>(
                             std::count(file.begin(), file.begin() + header.body, '\n'))) {}

  //! The next non-blank line, or nothing at the end of the file.
  std::optional<std::string_view> next() {
    while (at_ < file_.size()) {
      const std::size_t end = std::min(file_.find('\n', at_), file_.size());
      const std::string_view line = file_.substr(at_, end - at_);
      const bool blank = std::all_of(line.begin(), line.end(), is_ply_blank);
      at_ = end + 1;
      ++line_number_;
      if (!blank)
        return line;
    }
    return std::nullopt;
  }
  //! The number of the line next() returned last.
  std::size_t last() const { return line_number_ - 1; }

 private:
  std::string_view file_;
  std::size_t at_;
  std::size_t line_number_;
};

}  // namespace

std::size_t ascii_ply_item_line(std::string_view file, const PlyHeader& header, std::size_t element,
                                std::uint64_t item) {
  BodyLines lines(file, header);
  for (std::size_t k = 0; k < element && k < header.elements.size(); ++k) {
    for (std::uint64_t i = 0; i < header.elements[k].count; ++i) {
      if (!lines.next())
        return 0;
    }
  }
  for (std::uint64_t i = 0; i <= item; ++i) {
    if (!lines.next())
      return 0;
  }
  return lines.last();
}

std::optional<std::string> locate_ascii_ply_mismatch(std::string_view file,
                                                     const PlyHeader& header) {
  BodyLines lines(file, header);
  for (const PlyElement& e : header.elements) {
    for (std::uint64_t i = 0; i < e.count; ++i) {
      const std::optional<std::string_view> line = lines.next();
      if (!line) {
        return "the file ends after line " + std::to_string(lines.last()) + ", before " + e.name +
               " " + std::to_string(i + 1) + " of " + std::to_string(e.count) +
               " (a truncated file or a false count)";
      }
      const std::string fault = mismatch(e, ply_line_words(*line));
      if (!fault.empty()) {
        return "line " + std::to_string(lines.last()) + ", " + e.name + " " +
               std::to_string(i + 1) + " of " + std::to_string(e.count) + ": " + fault +
               " (a malformed line, or a false element count before it)";
      }
    }
  }
  if (const std::optional<std::string_view> line = lines.next()) {
    return "line " + std::to_string(lines.last()) + ": values after the last declared item (" +
           (header.elements.empty() ? std::string("no element")
                                    : header.elements.back().name + " " +
                                          std::to_string(header.elements.back().count)) +
           "): a false element count, or text after the mesh";
  }
  return std::nullopt;
}

}  // namespace meshbridge::detail
