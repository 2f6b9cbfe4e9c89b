// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file file_job.h
//! Batch repair, one file at a time: plan the jobs of a folder, then read -> repair -> write
//! each one. `meshbridge batch` and the Python batch both run these, in any order and in
//! parallel, and sort the records by `name`; so their output is byte-identical.

#include "meshbridge/repair.h"
#include "meshbridge/report_json.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace meshbridge {

//! What became of one file.
enum class FileStatus {
  //! read, had no defect; the mesh written as read (no vertex welded or removed, no face
  //! flipped, added or removed), in the output's format
  clean,
  repaired,  //!< read, had defects, repaired and written
  failed,    //!< could not be read, repaired or written (see FileJobResult::reason)
  skipped    //!< not attempted: output up to date (--resume) or input unreadable
};

//! "clean", "repaired", "failed" or "skipped".
const char* to_string(FileStatus status);

//! One file of a batch.
struct FileJob {
  std::string input;   //!< path of the mesh to read
  std::string output;  //!< path to write (its folder is created when missing)
  std::string name;    //!< the record's `file`: input relative to the batch's INDIR, '/'-separated
  std::string output_name;  //!< the record's `output`: relative to OUTDIR, '/'-separated
};

//! Options of plan_batch and run_file_job, every default documented.
struct FileJobOptions {
  RepairOptions repair;  //!< default: the full repair (see RepairOptions)
  //! Output format ("obj", "off", "ply", "stl" or "3mf", any case); empty (default): as the
  //! input.
  std::string format;
  //! Skip a file whose output exists and is newer than the input (default false).
  bool resume = false;
  //! Element lists in the record (default false: counts only), see ReportJsonOptions.
  bool elements = false;
  //! STL output: move the copies of split vertices apart (separate_copies_for_stl()) so that
  //! the file re-reads as repaired (default true; the record's `written.copies_moved` and
  //! `written.separation`). false keeps positions exact: the re-read welds the copies again.
  bool separate_stl_copies = true;
  //! The slicer preset of `repair --print` (RepairFileOptions::print; default false). With
  //! `print_keeps_weld` / `print_keeps_fill_holes` the repair options' own gap closing / hole
  //! filling stay (the user gave --weld / --fill-holes). The output format is the caller's
  //! (the CLI and the Dask batch write 3MF).
  bool print = false;
  bool print_keeps_weld = false;
  bool print_keeps_fill_holes = false;
  //! Also find the faces of each output as written that cross or overlap
  //! (RepairFileOptions::self_intersections; default false): the record's `self_intersections`.
  bool self_intersections = false;
};

//! What plan_batch found below a folder.
struct BatchPlan {
  std::vector<FileJob> jobs;  //!< sorted by name (byte order)
  //! Folders and files below INDIR that could not be listed or opened: path relative to INDIR
  //! ('/'-separated) and the OS reason. Their records are `skipped` (see skipped_record).
  struct Unreadable {
    std::string name;
    std::string reason;
  };
  std::vector<Unreadable> unreadable;
};

//! Lists every mesh file (is_supported_mesh_file) below `in_dir`, recursively, and maps each to
//! its output below `out_dir` at the same relative path; with `options.format` the extension is
//! replaced, and when two inputs would meet in one output (a.obj and a.off to a.ply) the later
//! one in name order becomes a-off.ply (a-off-2.ply, ... when that is another file's output). An
//! unreadable folder or file is noted in `unreadable` and skipped, never fatal. Folder symlinks are
//! not followed. `out_dir` equal to `in_dir` or inside it is refused unless `in_place`: then, when
//! equal, each output replaces its input (unless the format changes), and when inside, the walk
//! leaves `out_dir` out so earlier results are not taken as inputs. \throw std::invalid_argument
//! naming the path: `in_dir` missing or not a folder, `out_dir` equal to or inside `in_dir` without
//! `in_place`, a bad `options.format`
BatchPlan plan_batch(const std::string& in_dir, const std::string& out_dir,
                     const FileJobOptions& options, bool in_place = false);

//! The outcome of run_file_job.
struct FileJobResult {
  FileStatus status = FileStatus::failed;
  std::string reason;  //!< failed or skipped: why, naming the path; empty otherwise
  //! What became of the file's records (describe_reading()) when the reader did not keep every
  //! one as a simple polygon or found dangling edges or lone points; empty otherwise. The CLI
  //! warns with it, as `repair` does.
  std::string reading;
  //! Clean or repaired: what the output holds beyond the polygons (the record's `written`):
  //! polygons triangulated for STL/3MF, and what the output format left out (the CLI warns with
  //! each).
  WrittenOutput written;
  std::string record;   //!< the JSON Lines record (batch_record_json), no trailing newline
  RepairReport report;  //!< clean or repaired: what repair did; empty otherwise
  //! STL output only: detection on the written file as read back (STL keeps no shared vertices,
  //! so split vertex copies weld again); the record's `reread`. Empty for other formats.
  std::optional<DefectReport> reread;
  //! With `options.self_intersections`, clean or repaired: the output's crossing faces
  //! (find_self_intersections() of the mesh as written); the record's `self_intersections`.
  std::optional<SelfIntersectionReport> crossings;
};

//! Reads `job.input`, repairs it with `options.repair`, writes `job.output` atomically (creating
//! its folder); an STL output is read back and detected (FileJobResult::reread). Never throws for a
//! bad file: every error becomes a `failed` result whose reason names the path and the cause (OS
//! reason included). With `options.resume` an output newer than the input is `skipped`. An input
//! that cannot be opened (permission) is `skipped`. Thread-safe: jobs with distinct outputs may run
//! concurrently (MeshBridge's own readers and writers keep no shared state).
FileJobResult run_file_job(const FileJob& job, const FileJobOptions& options = {});

//! The `skipped` record of an unreadable entry from BatchPlan::unreadable.
std::string skipped_record(const BatchPlan::Unreadable& entry);

}  // namespace meshbridge
