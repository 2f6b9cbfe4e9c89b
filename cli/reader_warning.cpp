// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"

#include <iostream>

namespace meshbridge::cli {

void warn_about_reader(const std::string& path, const ReadInfo& info) {
  if (!info.changed_anything())
    return;
  std::cerr << "meshbridge: warning: " << path << ": " << describe_reading(info) << "\n";
}

}  // namespace meshbridge::cli
