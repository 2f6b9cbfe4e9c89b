// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The subcommands of `meshbridge`. Each returns an exit code (see ExitCode) and throws
// UsageError or a meshbridge error for main() to print.

#include <string>
#include <vector>

namespace meshbridge::cli {

int check_command(const std::vector<std::string>& args);
int compare_command(const std::vector<std::string>& args);
int repair_command(const std::vector<std::string>& args);

}  // namespace meshbridge::cli
