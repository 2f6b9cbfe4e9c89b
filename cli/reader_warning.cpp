// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"

#include "meshbridge/counted.h"

#include <iostream>

namespace meshbridge::cli {

void warn_about_reader(const std::string& path, const ReadInfo& info) {
  if (!info.changed_anything())
    return;
  std::cerr << "meshbridge: warning: " << path << ": " << describe_reading(info) << "\n";
}

void warn_about_file_faults(const std::string& path, const MeshAttributes& attributes) {
  for (const NotKept& n : attributes.not_kept) {
    if (n.fault) {
      std::cerr << "meshbridge: warning: " << path << ": " << n.what << ", on "
                << counted(n.count, n.noun) << "\n";
    }
  }
}

}  // namespace meshbridge::cli
