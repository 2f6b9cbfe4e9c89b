// SPDX-License-Identifier: GPL-3.0-or-later
#include "arguments.h"
#include "commands.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"

#include <iostream>

namespace meshbridge::cli {

int check_command(const std::vector<std::string>& args) {
  const Arguments arguments(args, {"json"}, {});
  arguments.expect_positionals(1, "meshbridge check FILE [--json]");
  const std::string& path = arguments.positionals()[0];
  ReadInfo info;
  const Soup soup = read_soup(path, &info);
  warn_about_reader(path, info);
  const DefectReport report = detect_defects(soup);
  if (arguments.flag("json")) {
    std::cout << to_json(report) << "\n";
  } else {
    std::cout << path << "\n"
              << "  read: " << describe_reading(info) << "\n"
              << to_text(report);
  }
  // Every record not kept as a simple polygon is in the soup as a degenerate face, so
  // has_defects() covers it; dangling edges and lone points are not surface defects (warned).
  return report.has_defects() || info.faces_dropped_by_reader > 0 ? kDefectsFound : kOk;
}

}  // namespace meshbridge::cli
