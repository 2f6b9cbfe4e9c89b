// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// CLI11 validators shared by the subcommands; each error names the value it refuses.

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

namespace meshbridge::cli {

//! Accepts a finite decimal number >= `minimum` (so "nan", "inf" and "1e999" are refused).
inline CLI::Validator finite_at_least(double minimum) {
  std::ostringstream shown;
  shown << minimum;
  const std::string minimum_text = shown.str();
  return CLI::Validator(
      [minimum, minimum_text](std::string& text) {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) ||
            value < minimum) {
          return "expects a finite number >= " + minimum_text + ", got '" + text + "'";
        }
        return std::string();
      },
      "NUMBER>=" + minimum_text);
}

//! Accepts "auto" or a finite number >= 0 (a distance in model units; --weld, --separate).
inline CLI::Validator distance_or_auto() {
  return CLI::Validator(
      [](std::string& text) {
        if (text == "auto")
          return std::string();
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value) ||
            value < 0) {
          return "expects auto or a finite number >= 0, got '" + text + "'";
        }
        return std::string();
      },
      "NUMBER>=0|auto");
}

//! Accepts a whole number from `low` to `high`.
inline CLI::Validator whole_number_in(long low, long high) {
  return CLI::Validator(
      [low, high](std::string& text) {
        char* end = nullptr;
        const long value = std::strtol(text.c_str(), &end, 10);
        if (text.empty() || end != text.c_str() + text.size() || value < low || value > high) {
          return "expects a whole number from " + std::to_string(low) + " to " +
                 std::to_string(high) + ", got '" + text + "'";
        }
        return std::string();
      },
      "INT in [" + std::to_string(low) + " - " + std::to_string(high) + "]");
}

}  // namespace meshbridge::cli
