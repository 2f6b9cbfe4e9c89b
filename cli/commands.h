// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The subcommands of `meshbridge`. Each returns an exit code (see ExitCode) and throws
// UsageError or a meshbridge error for main() to print.

#include "meshbridge/io.h"

#include <string>
#include <vector>

namespace meshbridge::cli {

//! Tells on stderr, in one line (describe_reading), about every record of the file that is not
//! kept as one simple polygon: split, set aside, dangling edges, lone points. Silent otherwise.
void warn_about_reader(const std::string& path, const ReadInfo& info);

int check_command(const std::vector<std::string>& args);
int compare_command(const std::vector<std::string>& args);
int repair_command(const std::vector<std::string>& args);
int batch_command(const std::vector<std::string>& args);
//! Draws the defects with Qt on the "offscreen" platform and writes a PNG (cli/defect_snapshot.h).
int snapshot_command(const std::vector<std::string>& args);

}  // namespace meshbridge::cli
