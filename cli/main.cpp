// SPDX-License-Identifier: GPL-3.0-or-later
// meshbridge: check, compare, repair and picture non-manifold polygon meshes.

#include "commands.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <new>
#include <string>

#ifndef MESHBRIDGE_VERSION
#define MESHBRIDGE_VERSION "unknown"
#endif

namespace {

//! "meshbridge" or "meshbridge repair": the command a parse error belongs to.
std::string command_name(const CLI::App& app) {
  const auto chosen = app.get_subcommands();
  return chosen.empty() ? app.get_name() : app.get_name() + " " + chosen.front()->get_name();
}

//! `text` broken into lines of at most `width` characters at spaces (CLI11 indents each line
//! under the option's column), keeping the line breaks already in it.
std::string wrapped(const std::string& text, std::size_t width) {
  std::string result, line, word;
  const auto flush_word = [&] {
    if (word.empty())
      return;
    if (!line.empty() && line.size() + 1 + word.size() > width) {
      result += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
    word.clear();
  };
  for (const char ch : text) {
    if (ch == ' ') {
      flush_word();
    } else if (ch == '\n') {
      flush_word();
      result += line + "\n";
      line.clear();
    } else {
      word += ch;
    }
  }
  flush_word();
  return result + line;
}

//! Wraps every option's description to fit an 100-column terminal beside the option column.
void wrap_descriptions(CLI::App& app) {
  for (CLI::App* command : app.get_subcommands({})) {
    for (CLI::Option* option : command->get_options())
      option->description(wrapped(option->get_description(), 62));
    std::string text = command->get_description();  // re-flowed: its own breaks were guesses
    std::replace(text.begin(), text.end(), '\n', ' ');
    command->description(wrapped(text, 62));
  }
}

//! MESHBRIDGE_THREADS as the core takes it: unset, `auto` or a whole number >= 1. The core
//! reads anything else as 1; the tool says so instead of ignoring a typo.
bool threads_variable_is_valid() {
  const char* text = std::getenv("MESHBRIDGE_THREADS");
  if (text == nullptr || std::string(text) == "auto")
    return true;
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  return end != text && *end == '\0' && value >= 1;
}

//! MESHBRIDGE_PROGRESS_DELAY, if set, is seconds before the progress line shows (see
//! progress_delay()): a number from 0 to below 1e6.
bool progress_delay_variable_is_valid() {
  const char* text = std::getenv("MESHBRIDGE_PROGRESS_DELAY");
  if (text == nullptr || *text == '\0')
    return true;
  char* end = nullptr;
  const double seconds = std::strtod(text, &end);
  return end != text && *end == '\0' && seconds >= 0 && seconds < 1e6;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace meshbridge::cli;
  CLI::App app(
      "Check, repair and picture non-manifold polygon meshes (OBJ, OFF, PLY, STL, 3MF).\n"
      "Exit codes: 0 = done (check: repair would change nothing), 1 = check: repair would change\n"
      "the mesh, snapshot: defects drawn, 2 = error.\n"
      "`meshbridge COMMAND --help` lists a command's options; `meshbridge explain` tells what\n"
      "the words in the reports mean.",
      "meshbridge");
  app.set_version_flag("--version", std::string("meshbridge ") + MESHBRIDGE_VERSION);
  app.require_subcommand(1);
  app.option_defaults()->always_capture_default();
  app.get_formatter()->column_width(34);

  int exit_code = kOk;
  add_check_command(app, exit_code);
  add_repair_command(app, exit_code);
  add_batch_command(app, exit_code);
  add_snapshot_command(app, exit_code);
  add_compare_command(app, exit_code);
  add_explain_command(app, exit_code);
  wrap_descriptions(app);

  if (argc < 2) {
    std::cerr << app.help();
    return kError;
  }
  if (!threads_variable_is_valid()) {
    std::cerr << "meshbridge: error: MESHBRIDGE_THREADS=" << std::getenv("MESHBRIDGE_THREADS")
              << ": expected a whole number >= 1 or 'auto'\n";
    return kError;
  }
  if (!progress_delay_variable_is_valid()) {
    std::cerr << "meshbridge: error: MESHBRIDGE_PROGRESS_DELAY="
              << std::getenv("MESHBRIDGE_PROGRESS_DELAY")
              << ": expected seconds, a number from 0 to below 1000000\n";
    return kError;
  }
  if (argv[1][0] != '-') {
    try {
      app.get_subcommand(argv[1]);
    } catch (const CLI::OptionNotFound&) {
      std::string names;
      for (const CLI::App* command : app.get_subcommands({}))
        names += (names.empty() ? "" : ", ") + command->get_name();
      std::cerr << "meshbridge: error: unknown command '" << argv[1] << "' (commands: " << names
                << "; see `meshbridge --help`)\n";
      return kError;
    }
  }
  try {
    app.parse(argc, argv);
    // A report or table that could not reach standard output (a full disk, a closed pipe) is
    // lost: that is an error, as for a --report file that cannot be written.
    std::cout.flush();
    if (!std::cout) {
      std::cerr << command_name(app) << ": error: cannot write to standard output ("
                << std::strerror(errno != 0 ? errno : EIO) << ")\n";
      return kError;
    }
    return exit_code;
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForVersion& version) {
    return app.exit(version);
  } catch (const CLI::ParseError& error) {
    const std::string command = command_name(app);
    std::cerr << command << ": error: " << error.what() << " (see `" << command << " --help`)\n";
    return kError;
  } catch (const UsageError& error) {
    std::cerr << command_name(app) << ": error: " << error.what() << "\n";
  } catch (const std::bad_alloc&) {
    std::cerr << command_name(app) << ": error: out of memory\n";
  } catch (const std::exception& error) {
    std::cerr << command_name(app) << ": error: " << error.what() << "\n";
  }
  return kError;
}
