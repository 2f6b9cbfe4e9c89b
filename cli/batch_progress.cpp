// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_progress.h"

#include <cstdio>
#include <iostream>
#include <sstream>

namespace meshbridge::cli {

namespace {

std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

}  // namespace

void BatchProgress::file_done(const std::string& name, std::size_t done, std::size_t failed) {
  if (!on_)
    return;
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double eta = done ? elapsed / done * (total_ - done) : 0;
  std::ostringstream line;
  line << "[" << done << "/" << total_ << "] "
       << (failed ? std::to_string(failed) + " failed, " : "") << "elapsed " << clock_text(elapsed)
       << ", ETA " << clock_text(eta) << "  " << name;
  std::string text = line.str();
  if (terminal_) {
    if (text.size() > 100)
      text = text.substr(0, 97) + "...";
    std::cerr << "\r\033[K" << text << std::flush;  // erased at the end (clear())
    shown_ = true;
  } else {
    std::cerr << text << "\n";
  }
}

void BatchProgress::clear() {
  if (shown_)
    std::cerr << "\r\033[K" << std::flush;
  shown_ = false;
}

}  // namespace meshbridge::cli
