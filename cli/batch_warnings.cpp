// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_warnings.h"

#include "meshbridge/batch_warnings.h"

#include <iostream>
#include <set>
#include <sstream>

namespace meshbridge::cli {

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
