// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"

#include <iostream>

namespace meshbridge::cli {

void warn_about_reader(const std::string& path, const ReadInfo& info) {
  if (info.faces_dropped_by_reader == 0)
    return;
  std::cerr << "meshbridge: warning: " << path << " declares " << info.declared_faces
            << " faces but OpenMesh's reader passed on "
            << info.declared_faces - info.faces_dropped_by_reader << ": "
            << info.faces_dropped_by_reader
            << " face record(s) with fewer than 3 distinct vertices were dropped by the reader\n";
}

}  // namespace meshbridge::cli
