// SPDX-License-Identifier: GPL-3.0-or-later
// What a file that its extension's reader cannot read looks like instead (another format's
// magic bytes or first word): the hint that ends such a reading error.

#include "io/formats.h"
#include "meshbridge/counted.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>
#include <string_view>

namespace meshbridge::detail {

// The first line of `head` that is no comment, after a byte order mark and blank lines: how
// an OFF file starts ("'COFF'", "the counts '8 6 12'"), or empty if it does not start so.
namespace {

std::string off_start(std::string_view head) {
  if (head.substr(0, 3) == "\xEF\xBB\xBF")
    head.remove_prefix(3);
  std::string_view line;
  while (!head.empty()) {
    const std::size_t end = std::min(head.find('\n'), head.size());
    line = head.substr(0, end);
    head.remove_prefix(std::min(end + 1, head.size()));
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back())))
      line.remove_suffix(1);
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.front())))
      line.remove_prefix(1);
    if (!line.empty() && line.front() != '#')
      break;
    line = {};
  }
  const std::string_view word = line.substr(0, line.find_first_of(" \t#"));
  const std::size_t off = word.find("OFF");
  if (off != std::string_view::npos && off + 3 == word.size() &&
      word.find_first_not_of("STCN4n") >= off)  // [ST][C][N][4][n]OFF
    return "'" + std::string(word) + "'";
  // The counts "vertices faces [edges]" of an OFF file without its (optional) keyword.
  std::size_t numbers = 0;
  for (std::size_t i = 0; i < line.size();) {
    const std::size_t end = std::min(line.find_first_of(" \t", i), line.size());
    if (end > i) {
      const std::string_view number = line.substr(i, end - i);
      if (number.find_first_not_of("0123456789") != std::string_view::npos)
        return {};
      ++numbers;
    }
    i = end + 1;
  }
  return numbers == 2 || numbers == 3 ? "the counts '" + std::string(line.substr(0, 40)) + "'"
                                      : std::string();
}

}  // namespace

std::string other_format_hint(std::string_view file, Format format) {
  const std::string_view head = file.substr(0, 4096);
  const auto begins = [&head](std::string_view word) {
    return head.substr(0, word.size()) == word &&
           (head.size() == word.size() ||
            std::isspace(static_cast<unsigned char>(head[word.size()])));
  };
  const std::uint64_t stl_triangles =
      file.size() >= 84 ? std::uint64_t(static_cast<unsigned char>(file[80])) |
                              std::uint64_t(static_cast<unsigned char>(file[81])) << 8 |
                              std::uint64_t(static_cast<unsigned char>(file[82])) << 16 |
                              std::uint64_t(static_cast<unsigned char>(file[83])) << 24
                        : 0;
  if (format != Format::threemf && head.substr(0, 4) == std::string_view("PK\3\4", 4))
    return "; it begins with 'PK': a zip archive (a 3MF file under another name?)";
  if (format != Format::ply && begins("ply"))
    return "; it begins with 'ply': a PLY file under another name?";
  if (format != Format::off) {
    const std::string off = off_start(head);
    if (!off.empty())
      return "; it begins with " + off + ": an OFF file under another name?";
  }
  if (format != Format::stl && file.size() >= 84 && 84 + 50 * stl_triangles == file.size())
    return "; its size is that of a binary STL of " + counted(stl_triangles, "triangle") +
           ": an STL file under another name?";
  if (format != Format::stl && begins("solid"))
    return "; it begins with 'solid': an ASCII STL file under another name?";
  const std::size_t nul = head.find('\0');
  if (nul != std::string_view::npos && (format == Format::obj || format == Format::off))
    return "; it holds binary data (a NUL byte at offset " + std::to_string(nul) +
           "), which a text file never does";
  return {};
}

}  // namespace meshbridge::detail
