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
    std::cout << path << "\n" << to_text(report);
  }
  return report.has_defects() || info.faces_dropped_by_reader > 0 ? kDefectsFound : kOk;
}

}  // namespace meshbridge::cli
