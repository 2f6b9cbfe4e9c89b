// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Progress on stderr for long work: the stage of one file (read, group, pair, detect, write)
// with a bar. (`batch` shows files done / total / ETA with its own line, cli/batch_command.cpp.)
//
// On a terminal one line is redrawn in place (at most 5 times a second, by a background thread,
// so a long stage still shows its time running) and erased at the end. Elsewhere (a pipe, a
// log file; only when asked with --progress) each change is one line of its own. Nothing at all
// is printed for work that ends within `delay` (default 1 s, or MESHBRIDGE_PROGRESS_DELAY seconds
// when that environment variable holds a number >= 0; 0 shows progress from the start).

#include "meshbridge/progress.h"

#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <mutex>
#include <ostream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace meshbridge::cli {

//! Whether progress is drawn: `forced` (--progress) or stderr is a terminal; never with `quiet`.
bool progress_wanted(bool forced, bool quiet = false);

//! 1 s, or MESHBRIDGE_PROGRESS_DELAY seconds (a number >= 0) when set.
std::chrono::milliseconds progress_delay();

//! The stages a command runs, each with its share of the time (the shares need not add to 1).
using StagePlan = std::vector<std::pair<Stage, double>>;
//! read, group, pair, detect, write with the shares measured on a 5.3M-triangle repair.
StagePlan repair_plan();
//! read, detect (check).
StagePlan check_plan();
//! read, detect, write (snapshot: drawing and writing the PNG count as write).
StagePlan snapshot_plan();

class ProgressDisplay {
 public:
  //! `label` starts the line (e.g. the file name). Draws nothing when `enabled` is false.
  //! `interactive`: redraw one line in place (a terminal) instead of one line per change.
  //! `plan`: the stages stage() will be told of (see repair_plan()).
  ProgressDisplay(std::string label, bool enabled, bool interactive, StagePlan plan = repair_plan(),
                  std::chrono::milliseconds delay = progress_delay(), std::ostream* out = nullptr);
  //! finish().
  ~ProgressDisplay();
  //! Erases the line (interactive), stops the background thread; nothing is drawn afterwards.
  void finish();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  //! One file: `stage` has reached `fraction` (0 = started, 1 = done). The bar shows the whole
  //! file's estimated fraction from fixed stage weights. Thread-safe.
  void stage(Stage stage, double fraction);
  //! A callback for RepairOptions::progress that forwards to stage().
  ProgressCallback callback();

  //! The line as it would be drawn now (without "\r" or colours), for tests.
  std::string line() const;

 private:
  void draw_locked(bool changed);
  void run();

  double overall_locked() const;
  std::string line_locked() const;

  std::string label_;
  StagePlan plan_;
  bool enabled_;
  bool interactive_;
  std::chrono::milliseconds delay_;
  std::ostream* out_;
  std::chrono::steady_clock::time_point start_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool drawn_ = false;         // something is on the terminal line
  Stage stage_ = Stage::read;  // stage() mode
  double fraction_ = 0;        // of the current stage
  std::thread thread_;
};

//! "1:05", "12:00:07" for a duration in seconds (rounded down, at least 0).
std::string format_duration(double seconds);

}  // namespace meshbridge::cli
