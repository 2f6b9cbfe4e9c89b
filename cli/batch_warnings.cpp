// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_warnings.h"

#include <iostream>
#include <set>
#include <sstream>

namespace meshbridge::cli {

namespace {

//! Harmless warnings: what the line contains -> the kind printed once for the whole batch.
struct Harmless {
  const char* contains;
  const char* kind;
};
constexpr Harmless kHarmless[] = {
    {"ASCII STL solid names", "ASCII STL solid names not written (MeshBridge reads past them)"},
    {"STL facet normals against the winding",
     "STL facet normals against the winding of their corners (written ones follow the winding)"},
    {"PLY comment and obj_info lines",
     "PLY comment and obj_info lines not written (MeshBridge reads past them)"},
    {"rounded to 32-bit floats", "vertex positions rounded to 32-bit floats (STL holds no more)"},
    {"as lib3mf wrote them",
     "vertex positions moved by lib3mf's rounding (3MF text, at most 6 decimals)"},
};

}  // namespace

std::string harmless_warning_kind(const std::string& line) {
  for (const Harmless& h : kHarmless) {
    if (line.find(h.contains) != std::string::npos)
      return h.kind;
  }
  return "";
}

void BatchWarnings::file(const std::string& name, const std::string& lines) {
  if (quiet_ || lines.empty())
    return;
  std::cout.flush();
  std::set<std::string> seen;
  std::istringstream in(lines);
  for (std::string line; std::getline(in, line);) {
    const std::string kind = harmless_warning_kind(line);
    if (kind.empty()) {
      std::cerr << "meshbridge: warning: " << name << ": " << line << "\n";
    } else if (seen.insert(kind).second) {
      if (files_[kind]++ == 0)
        order_[order_.size()] = kind;
    }
  }
}

void BatchWarnings::finish() {
  for (const auto& [first, kind] : order_) {
    const std::size_t n = files_[kind];
    std::cerr << "meshbridge: warning: " << n << (n == 1 ? " file: " : " files: ") << kind << "\n";
  }
}

}  // namespace meshbridge::cli
