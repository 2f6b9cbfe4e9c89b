// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One file's line in the outcome of `batch`, and running the files in child processes.

#include "meshbridge/file_job.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace meshbridge::cli {

//! The figures of one table row (from the repair report of a clean or repaired file).
struct TableRow {
  std::size_t faces_in = 0, singular_edges = 0, singular_vertices = 0, faces_out = 0;
  std::size_t components_after = 0;
  bool watertight_after = false;
  long long crossing_pairs = -1;  //!< self-intersecting face pairs of the output; -1: not sought
};

//! One line of the outcome: a job's result, or an unreadable entry found while listing.
struct Entry {
  std::string name;
  const FileJob* job = nullptr;  //!< null: unreadable, the status, reason and record are final
  FileStatus status = FileStatus::failed;
  std::string reason;
  //! Warnings for stderr, one per line: FileJobResult::reading, then what the output format
  //! left out (FileJobResult::written.left_out), or empty.
  std::string warnings;
  std::string record;
  TableRow row;
  bool up_to_date = false;  //!< skipped by --resume: the log says it is done, nothing changed
};

//! Fills `entry` from the result of its `job`.
void take_result(Entry& entry, const FileJobResult& result, const FileJob& job);

//! Runs the job of every entry i with `!done[i]`, each in a child process of its own, at most
//! `jobs` at once, in index order; calls `finished(i)` in the parent as each ends, with entry i
//! filled (a child that crashed or ran out of memory gives a `failed` entry naming why). A file
//! that crashes its child fails alone instead of ending the run, and each child's memory goes
//! back to the system when it ends. \throws std::runtime_error if no process can be started
void run_in_child_processes(std::vector<Entry>& entries, const std::vector<char>& done,
                            const FileJobOptions& options, unsigned jobs,
                            const std::function<void(std::size_t)>& finished);

}  // namespace meshbridge::cli
