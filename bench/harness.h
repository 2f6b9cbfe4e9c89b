// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file harness.h
//! The timing harness of meshbridge-bench: every run in a forked child (clean allocator state,
//! its own peak memory), a clock the method stops itself where its work ends, and one evaluator
//! that measures every method's output mesh the same way.

#include "meshbridge/mesh_types.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <functional>
#include <string>

namespace meshbridge::bench {

//! What one run of one method did. Plain data: it crosses the pipe from the child.
//! Counts are -1 when they do not apply (e.g. a detection-only method has no output mesh).
struct Outcome {
  double seconds = 0;      //!< wall time of the timed part
  double cpu_seconds = 0;  //!< user + system CPU time of the timed part (all threads)
  long peak_kb = 0;        //!< peak resident memory above the child's start (the soup is shared)
  long faces_in = -1;      //!< polygons the method started from, if not the soup's (triangulated)
  long faces = -1;         //!< polygons in the output
  long vertices = -1;      //!< vertices in the output (unreferenced ones included)
  long unreferenced_vertices = -1;
  long components = -1;  //!< connected through shared edges
  long boundary_edges = -1;
  long singular_edges = -1;      //!< edges with more than 2 polygon sides, left in the output
  long singular_vertices = -1;   //!< vertices on those, or with more than one fan
  long inconsistent_edges = -1;  //!< 2-sided edges whose sides run the same way
  long add_face_failures = -1;   //!< OpenMesh add_face refusals, for methods that build with it
  bool failed = false;           //!< the method threw; `note` holds the message
  char note[480] = {};           //!< what the method found or did, one line
};

//! Stops the timed part of a run. A method calls stop() where its work ends, before it
//! evaluates its output; if it never does, the harness stops the clock when the method returns.
class Clock {
 public:
  Clock();
  void stop();
  bool stopped() const { return stopped_; }
  double seconds() const { return seconds_; }
  double cpu_seconds() const { return cpu_seconds_; }
  long peak_kb() const { return peak_kb_; }
  //! Seconds since the start (or since the previous lap) while running, for sub-timings.
  double lap();

 private:
  double start_ = 0, last_lap_ = 0, seconds_ = 0, cpu_start_ = 0, cpu_seconds_ = 0;
  long base_kb_ = 0, peak_kb_ = 0;
  bool stopped_ = false;
};

//! A benchmarked method: reads the soup, does its work, stops the clock, fills the outcome.
using Method = std::function<void(const Soup& soup, Clock& clock, Outcome& outcome)>;

//! Fills the output counts of `outcome` from `result` (through detect_defects()).
void evaluate(const Soup& result, Outcome& outcome);

//! The polygons of an OpenMesh mesh as a soup (vertex handles as indices).
Soup to_soup(const PolyMesh& mesh);

//! Appends printf-style text to `outcome.note` (separated by "; ").
void add_note(Outcome& outcome, const char* format, ...) __attribute__((format(printf, 2, 3)));

//! Runs `method` once in a forked child. `evaluate_output` false skips the outcome counts
//! (the method sees it through Outcome::faces == -2 and may skip its evaluation).
Outcome run_in_child(const Soup& soup, const Method& method, bool evaluate_output);

//! Runs `method` `repeat` times (each in a fresh child): the best wall time (least disturbed by
//! other load on the machine) with that run's note, the best CPU time, the largest peak, the
//! counts of the first run.
Outcome measure(const Soup& soup, const Method& method, int repeat);

//! True when the method should evaluate its output (see run_in_child()).
inline bool wants_evaluation(const Outcome& outcome) {
  return outcome.faces != -2;
}

//! MemAvailable of /proc/meminfo.
long available_memory_kb();

//! The 1, 5 and 15 minute load averages of /proc/loadavg.
std::string load_average();

//! "nproc N, <CPU model>, <memory> GiB RAM".
std::string machine_description();

}  // namespace meshbridge::bench
