// SPDX-License-Identifier: GPL-3.0-or-later
#include "progress.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace meshbridge::cli {

namespace {

constexpr int kBarWidth = 24;
constexpr auto kRedrawEvery = std::chrono::milliseconds(200);

std::string bar(double fraction) {
  const int filled = static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * kBarWidth));
  return "[" + std::string(filled, '#') + std::string(kBarWidth - filled, '.') + "]";
}

}  // namespace

bool progress_wanted(bool forced, bool quiet) {
  return !quiet && (forced || ::isatty(STDERR_FILENO));
}

std::chrono::milliseconds progress_delay() {
  const char* text = std::getenv("MESHBRIDGE_PROGRESS_DELAY");
  if (text && *text) {
    char* end = nullptr;
    const double seconds = std::strtod(text, &end);
    if (*end == '\0' && seconds >= 0 && seconds < 1e6)
      return std::chrono::milliseconds(static_cast<long>(seconds * 1000));
  }
  return std::chrono::seconds(1);
}

// Shares of `repair` of the 5.3M-triangle checkerboard (96^3 cells, OFF in and out, Release
// build, 100 s on a loaded 2-core machine): read 38 s, group 14, pair 18, detect 9, write 21.
StagePlan repair_plan() {
  return {{Stage::read, 0.38},
          {Stage::group, 0.14},
          {Stage::pair, 0.18},
          {Stage::detect, 0.09},
          {Stage::write, 0.21}};
}
StagePlan check_plan() {
  return {{Stage::read, 0.6}, {Stage::detect, 0.4}};
}
StagePlan snapshot_plan() {
  return {{Stage::read, 0.5}, {Stage::detect, 0.3}, {Stage::write, 0.2}};
}

std::string format_duration(double seconds) {
  const long total = seconds > 0 ? static_cast<long>(seconds) : 0;
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

ProgressDisplay::ProgressDisplay(std::string label, bool enabled, bool interactive, StagePlan plan,
                                 std::chrono::milliseconds delay, std::ostream* out)
    : label_(std::move(label)),
      plan_(std::move(plan)),
      enabled_(enabled),
      interactive_(interactive),
      delay_(delay),
      out_(out ? out : &std::cerr),
      start_(std::chrono::steady_clock::now()) {
  if (enabled_)
    thread_ = std::thread([this] { run(); });
}

ProgressDisplay::~ProgressDisplay() {
  finish();
}

void ProgressDisplay::finish() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    if (drawn_ && interactive_)
      *out_ << "\r\033[K" << std::flush;  // erase the line: the command's own output follows
    drawn_ = false;
  }
  wake_.notify_all();
  if (thread_.joinable())
    thread_.join();
}

void ProgressDisplay::stage(Stage stage, double fraction) {
  const std::lock_guard<std::mutex> lock(mutex_);
  const bool changed = stage != stage_;
  stage_ = stage;
  fraction_ = fraction;
  if (enabled_)
    draw_locked(changed);
}

ProgressCallback ProgressDisplay::callback() {
  return [this](Stage stage, double fraction) { this->stage(stage, fraction); };
}

double ProgressDisplay::overall_locked() const {
  double total = 0, before = 0, share = 0;
  bool found = false;
  for (const auto& [stage, weight] : plan_) {
    total += weight;
    if (stage == stage_) {
      found = true;
      share = weight;
    } else if (!found) {
      before += weight;
    }
  }
  if (!found || total <= 0)
    return 0;
  return (before + share * std::clamp(fraction_, 0.0, 1.0)) / total;
}

std::string ProgressDisplay::line() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return line_locked();
}

std::string ProgressDisplay::line_locked() const {
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::ostringstream text;
  const double fraction = overall_locked();
  text << label_ << "  " << bar(fraction) << " " << static_cast<int>(fraction * 100) << "%  "
       << to_string(stage_) << "  " << format_duration(elapsed);
  return text.str();
}

void ProgressDisplay::draw_locked(bool changed) {
  if (stopping_ || std::chrono::steady_clock::now() - start_ < delay_)
    return;
  const std::string text = line_locked();
  if (interactive_) {
    *out_ << "\r" << text << "\033[K" << std::flush;
    drawn_ = true;
  } else if (changed || !drawn_) {
    *out_ << text << "\n" << std::flush;
    drawn_ = true;
  }
}

void ProgressDisplay::run() {
  std::unique_lock<std::mutex> lock(mutex_);
  if (wake_.wait_for(lock, delay_, [this] { return stopping_; }))
    return;
  draw_locked(false);  // non-interactive: only when nothing was printed yet
  while (!wake_.wait_for(lock, kRedrawEvery, [this] { return stopping_; })) {
    if (interactive_)
      draw_locked(false);  // the elapsed time moves on even while a stage runs long
  }
}

}  // namespace meshbridge::cli
