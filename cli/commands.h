// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The subcommands of `meshbridge`. Each returns an exit code (see ExitCode) and throws
// UsageError or a meshbridge error for main() to print.

#include "meshbridge/io.h"

#include <string>
#include <vector>

namespace meshbridge::cli {

//! Tells on stderr about face records the file reader dropped (OpenMesh's OBJ reader skips
//! faces with fewer than 3 distinct vertices without a word).
void warn_about_reader(const std::string& path, const ReadInfo& info);

int check_command(const std::vector<std::string>& args);
int compare_command(const std::vector<std::string>& args);
int repair_command(const std::vector<std::string>& args);
int batch_command(const std::vector<std::string>& args);
//! Draws the defects with Qt on the "offscreen" platform and writes a PNG (cli/defect_snapshot.h).
int snapshot_command(const std::vector<std::string>& args);

}  // namespace meshbridge::cli
