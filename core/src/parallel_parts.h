// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Running a reader's parts side by side: how many threads reading may use, and one call that
// runs part k of n on its own thread and passes on the first part's error.

#include <algorithm>
#include <cstddef>
#include <functional>

namespace meshbridge::detail {

//! Threads a reader may use: the environment variable MESHBRIDGE_THREADS when it holds a whole
//! number >= 1 (at most 64); "auto": the CPUs this process may run on (its affinity mask, so
//! under `taskset -c 0` it is 1), at most 8; unset or anything else: 1. One is the default
//! because two threads gave no gain on the 2-core machines this was measured on, shared with
//! other work (see the commit that made it so). Read on every call, so a test may change it.
unsigned worker_threads();

//! Runs `part(k)` for every k in [0, n): part 0 on the calling thread, each other one on a thread
//! of its own; returns when all have ended. If parts throw, the exception of the lowest k is
//! rethrown (for parts in file order: the error a one-thread reader would have met first).
//! n == 1 calls part(0) directly.
void run_parts(unsigned n, const std::function<void(unsigned k)>& part);

//! [first, last) of part k when `count` items are cut into n parts of nearly equal size.
inline std::size_t part_begin(std::size_t count, unsigned n, unsigned k) {
  return count / n * k + std::min<std::size_t>(k, count % n);
}

}  // namespace meshbridge::detail
