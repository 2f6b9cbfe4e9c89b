// SPDX-License-Identifier: GPL-3.0-or-later
#include "arguments.h"

#include <algorithm>
#include <cmath>

namespace meshbridge::cli {

Arguments::Arguments(const std::vector<std::string>& args, const std::vector<std::string>& flags,
                     const std::vector<std::string>& options) {
  const auto known = [](const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
  };
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) {
      positionals_.push_back(arg);
      continue;
    }
    std::string name = arg.substr(2);
    std::string value;
    const auto eq = name.find('=');
    const bool inline_value = eq != std::string::npos;
    if (inline_value) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    }
    if (known(flags, name) && !inline_value) {
      flags_[name] = true;
    } else if (known(options, name)) {
      if (!inline_value) {
        if (i + 1 >= args.size())
          throw UsageError("--" + name + " needs a value");
        value = args[++i];
      }
      options_[name] = value;
    } else {
      throw UsageError("unknown option --" + name);
    }
  }
}

std::string Arguments::value(const std::string& name, const std::string& fallback) const {
  const auto it = options_.find(name);
  return it == options_.end() ? fallback : it->second;
}

double Arguments::number(const std::string& name, double fallback) const {
  const auto it = options_.find(name);
  if (it == options_.end())
    return fallback;
  std::size_t used = 0;
  double result = 0;
  try {
    result = std::stod(it->second, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != it->second.size() || !std::isfinite(result)) {
    throw UsageError("--" + name + " expects a number, got '" + it->second + "'");
  }
  return result;
}

void Arguments::expect_positionals(std::size_t count, const std::string& usage) const {
  if (positionals_.size() != count)
    throw UsageError("usage: " + usage);
}

}  // namespace meshbridge::cli
