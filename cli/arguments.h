// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Command-line arguments: positionals and --flags, with typed lookups that name bad input.

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshbridge::cli {

//! Exit codes every command uses.
enum ExitCode { kOk = 0, kDefectsFound = 1, kError = 2 };

//! A usage mistake: printed as one line, exit code 2.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class Arguments {
 public:
  //! `flags` take no value; `options` take one (`--name VALUE` or `--name=VALUE`).
  Arguments(const std::vector<std::string>& args, const std::vector<std::string>& flags,
            const std::vector<std::string>& options);

  const std::vector<std::string>& positionals() const { return positionals_; }
  bool flag(const std::string& name) const { return flags_.count(name) > 0; }
  bool has(const std::string& name) const { return options_.count(name) > 0; }
  std::string value(const std::string& name, const std::string& fallback = "") const;
  double number(const std::string& name, double fallback) const;
  //! Throws UsageError unless there are exactly `count` positionals.
  void expect_positionals(std::size_t count, const std::string& usage) const;

 private:
  std::vector<std::string> positionals_;
  std::map<std::string, bool> flags_;
  std::map<std::string, std::string> options_;
};

}  // namespace meshbridge::cli
