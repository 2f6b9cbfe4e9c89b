// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A count with its noun in the right number, for messages: "1 singular edge", "2 singular edges".

#include <cstddef>
#include <string>

namespace meshbridge::cli {

//! `n` and `noun` ("singular edge", "singular vertex"), plural unless n == 1: an "s" appended,
//! "vertex" becoming "vertices".
inline std::string counted(std::size_t n, const std::string& noun) {
  std::string text = std::to_string(n) + " " + noun;
  if (n == 1)
    return text;
  const std::string vertex = "vertex";
  if (noun.size() >= vertex.size() &&
      noun.compare(noun.size() - vertex.size(), vertex.size(), vertex) == 0)
    return text.substr(0, text.size() - 2) + "ices";
  return text + "s";
}

}  // namespace meshbridge::cli
