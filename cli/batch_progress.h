// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The progress line of `batch` on stderr.

#include <chrono>
#include <cstddef>
#include <string>

namespace meshbridge::cli {

//! Files done / total / ETA on stderr: one line rewritten in place on a terminal, one line per
//! file elsewhere (only with --progress). On a terminal the line is erased (clear()) before
//! anything else is printed, so it never runs into a table row or a warning.
class BatchProgress {
 public:
  BatchProgress(std::size_t total, bool on, bool terminal)
      : total_(total),
        on_(on && total > 0),
        terminal_(terminal),
        start_(std::chrono::steady_clock::now()) {}
  //! `done` of the total finished (`failed` of them failed), the last one `name`.
  void file_done(const std::string& name, std::size_t done, std::size_t failed);
  //! Erases the line on a terminal (the next file_done draws it again).
  void clear();

 private:
  std::size_t total_;
  bool on_, terminal_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace meshbridge::cli
