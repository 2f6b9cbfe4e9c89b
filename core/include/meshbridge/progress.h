// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file progress.h
//! A progress hook for long work: the stages a file goes through and a callback told when each
//! one starts. The core calls it at stage boundaries only (never per element), so its cost is
//! nil; a command-line tool draws a progress bar from it.

#include <functional>

namespace meshbridge {

//! The stages of reading, repairing and writing one file, in the order they run.
enum class Stage {
  read,    //!< parsing the file into a soup (the caller reports this one)
  group,   //!< grouping polygon sides into edges, and detection on the input
  pair,    //!< pairing contenders, splitting fans, orienting, stitching
  detect,  //!< detection on the result
  write    //!< writing the output file (the caller reports this one)
};

//! "read", "group", "pair", "detect" or "write".
const char* to_string(Stage stage);

//! Called with a stage and the fraction of it done, in [0, 1]: (stage, 0) when it starts,
//! (stage, 1) when it ends. Runs on the calling thread; must not throw. Empty: not called.
using ProgressCallback = std::function<void(Stage stage, double fraction)>;

}  // namespace meshbridge
