// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Running parts of one job side by side: how many threads MeshBridge may use for one mesh, and
// one call that runs part k of n on its own thread and passes on the first part's error.

#include <algorithm>
#include <cstddef>
#include <functional>

namespace meshbridge::detail {

//! Threads MeshBridge may use for one mesh (readers in parts, repair's steps in shares): the
//! environment variable MESHBRIDGE_THREADS when it holds a whole number >= 1 (at most 64);
//! unset or "auto": the CPUs this process may run on (its affinity mask, so under
//! `taskset -c 0` it is 1), at most 8; anything else: 1. Every count gives the same result.
//! Read on every call, so a test may change it.
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
