// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The subcommands of `meshbridge`. Each add_*_command() declares its subcommand's arguments on
// the CLI11 app (every option with its default, shown by `meshbridge COMMAND --help`) and a
// callback that runs it and stores the exit code (see ExitCode) in `exit_code`. A callback
// throws UsageError or a meshbridge error for main() to print as one line.

#include "meshbridge/io.h"

#include <stdexcept>
#include <string>

namespace CLI {
class App;
}

namespace meshbridge::cli {

//! Exit codes every command uses.
enum ExitCode { kOk = 0, kDefectsFound = 1, kError = 2 };

//! A usage mistake found after parsing (e.g. an output name with an unknown extension): printed
//! as one line, exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

//! Tells on stderr, in one line (describe_reading), about every record of the file that is not
//! kept as one simple polygon: split, set aside, dangling edges, lone points. Silent otherwise.
void warn_about_reader(const std::string& path, const ReadInfo& info);
//! Tells on stderr, one line each, about the faults of the file among what the reader read past
//! (NotKept::fault: an index naming no record, numbers that are no colour...), for `check`, which
//! writes nothing and so never names them as left out of an output.
void warn_about_file_faults(const std::string& path, const MeshAttributes& attributes);

void add_check_command(CLI::App& app, int& exit_code);
void add_compare_command(CLI::App& app, int& exit_code);
void add_repair_command(CLI::App& app, int& exit_code);
void add_batch_command(CLI::App& app, int& exit_code);
//! Draws the defects with Qt on the "offscreen" platform and writes a PNG; Qt is loaded with the
//! meshbridge_pictures module for that only (cli/pictures.h, cli/defect_snapshot.h).
void add_snapshot_command(CLI::App& app, int& exit_code);
//! Prints what each line and word of the reports means (cli/explain_command.cpp).
void add_explain_command(CLI::App& app, int& exit_code);

}  // namespace meshbridge::cli
