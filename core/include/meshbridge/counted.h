// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file counted.h
//! A count with its noun in the right number, for messages: "1 singular edge", "2 singular edges".

#include <cstddef>
#include <string>

namespace meshbridge {

//! `n` and `noun` ("singular edge", "singular vertex", "copy"), plural unless n == 1: an "s"
//! appended, "vertex" becoming "vertices", a final "y" after a consonant becoming "ies".
inline std::string counted(std::size_t n, const std::string& noun) {
  std::string text = std::to_string(n) + " " + noun;
  if (n == 1)
    return text;
  const std::string vertex = "vertex";
  if (noun.size() >= vertex.size() &&
      noun.compare(noun.size() - vertex.size(), vertex.size(), vertex) == 0)
    return text.substr(0, text.size() - 2) + "ices";
  if (noun.size() >= 2 && noun.back() == 'y' &&
      std::string("aeiou").find(noun[noun.size() - 2]) == std::string::npos)
    return text.substr(0, text.size() - 1) + "ies";
  return text + "s";
}

}  // namespace meshbridge
