// SPDX-License-Identifier: GPL-3.0-or-later
#include "parallel_parts.h"

#include <sched.h>
#include <algorithm>
#include <cstdlib>
#include <exception>
#include <string_view>
#include <thread>
#include <vector>

namespace meshbridge::detail {

unsigned worker_threads() {
  const char* text = std::getenv("MESHBRIDGE_THREADS");
  if (text == nullptr || std::string_view(text) == "auto") {
    cpu_set_t set;
    CPU_ZERO(&set);
    int cpus = 1;
    if (sched_getaffinity(0, sizeof(set), &set) == 0)
      cpus = CPU_COUNT(&set);
    return static_cast<unsigned>(std::clamp(cpus, 1, 8));
  }
  char* end = nullptr;
  const long value = std::strtol(text, &end, 10);
  if (end != text && *end == '\0' && value >= 1)
    return static_cast<unsigned>(std::min(value, 64L));
  return 1;
}

void run_parts(unsigned n, const std::function<void(unsigned k)>& part) {
  if (n <= 1) {
    part(0);
    return;
  }
  std::vector<std::exception_ptr> errors(n);
  std::vector<std::thread> threads;
  threads.reserve(n - 1);
  const auto guarded = [&](unsigned k) {
    try {
      part(k);
    } catch (...) {
      errors[k] = std::current_exception();
    }
  };
  try {
    for (unsigned k = 1; k < n; ++k)
      threads.emplace_back(guarded, k);
  } catch (...) {  // no thread could be started: run the rest here
    for (unsigned k = static_cast<unsigned>(threads.size()) + 1; k < n; ++k)
      guarded(k);
  }
  guarded(0);
  for (std::thread& t : threads)
    t.join();
  for (const std::exception_ptr& e : errors) {
    if (e)
      std::rethrow_exception(e);
  }
}

}  // namespace meshbridge::detail
