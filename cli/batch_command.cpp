// SPDX-License-Identifier: GPL-3.0-or-later
#include "batch_entry.h"
#include "batch_progress.h"
#include "batch_warnings.h"
#include "commands.h"
#include "printer_options.h"
#include "validators.h"

#include "meshbridge/batch_log.h"
#include "meshbridge/batch_warnings.h"
#include "meshbridge/file_job.h"

#include <CLI/CLI.hpp>

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace meshbridge::cli {

namespace {

//! The arguments of `batch` as parsed (defaults as documented in add_batch_command).
struct BatchArguments {
  std::string in_dir, out_dir;
  std::string format;  //!< "" = keep each file's format
  std::string pairing = "geometric";
  bool json = false;
  bool elements = false;
  bool quiet = false;
  bool progress = false;
  bool in_place = false;
  bool resume = false;
  bool print = false;               //!< as repair --print: the slicer preset, 3MF outputs
  bool self_intersections = false;  //!< count the crossing faces of each output
  bool weld_given = false, fill_holes_given = false;
  std::string log;                //!< "" = OUTDIR/.meshbridge-batch.jsonl
  std::string weld = "auto";      //!< as repair --weld
  std::string fill_holes;         //!< as repair --fill-holes ("" or "0" = off)
  std::string separate = "auto";  //!< STL output: "auto" moves split vertex copies apart, "0" not
  AmbiguousNesting nested_shells = AmbiguousNesting::material;  //!< as repair --nested-shells
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
};

//! A table row; with `crossings` (--self-intersections) a column of crossing face pairs.
void print_table_row(const Entry& e, bool crossings) {
  std::cout << "| " << e.name << " | " << to_string(e.status) << " | ";
  if (e.status == FileStatus::clean || e.status == FileStatus::repaired) {
    const TableRow& r = e.row;
    std::cout << r.faces_in << " | " << r.singular_edges << " | " << r.singular_vertices << " | "
              << r.faces_out << " | " << r.components_after << " | "
              << (r.watertight_after ? "yes" : "no") << " | ";
    if (crossings)
      std::cout << r.crossing_pairs << " | ";
    std::cout << "|\n";
  } else {  // failed or skipped: no counts, the reason in the last column
    std::cout << "| | | | | | " << (crossings ? "| " : "") << e.reason << " |\n";
  }
}

//! The entry's JSON record or table row on stdout; its warnings on stderr (BatchWarnings: lost
//! data per file, harmless kinds counted), in either mode.
void print_entry(const Entry& e, const BatchArguments& arguments, BatchWarnings& warnings) {
  warnings.file(e.name, e.warnings);
  if (arguments.json)
    std::cout << e.record << "\n";
  else
    print_table_row(e, arguments.self_intersections);
}

//! The summary line ("N file(s): ... clean, ... repaired, ... failed, ... skipped"): on stdout
//! under the table, on stderr with --json (not with --quiet). Returns whether every file was
//! read and written (skipped as up to date counts as written, unreadable does not).
bool print_summary(const std::vector<Entry>& entries, const BatchArguments& arguments) {
  std::size_t count[4] = {0, 0, 0, 0};
  std::size_t crossing = 0;  // files whose output has self-intersections (sought and found)
  bool all_written = true;
  for (const Entry& e : entries) {
    ++count[static_cast<int>(e.status)];
    crossing += e.row.crossing_pairs > 0 ? 1 : 0;
    // Skipped because up to date is fine; skipped because unreadable is not.
    if (e.status == FileStatus::failed || !e.job ||
        (e.status == FileStatus::skipped && !e.up_to_date))
      all_written = false;
  }
  std::ostringstream summary;
  summary << entries.size() << " file(s): " << count[int(FileStatus::clean)] << " clean, "
          << count[int(FileStatus::repaired)] << " repaired, " << count[int(FileStatus::failed)]
          << " failed, " << count[int(FileStatus::skipped)] << " skipped";
  if (arguments.self_intersections)
    summary << "; " << crossing << " with self-intersections";
  summary << "\n";
  if (arguments.json) {
    if (!arguments.quiet)
      std::cerr << summary.str();
  } else {
    std::cout << summary.str();
  }
  return all_written;
}

//! The file jobs' options from the arguments. \throws UsageError for --print with a --format
//! other than 3MF
FileJobOptions job_options(const BatchArguments& arguments) {
  FileJobOptions options;
  options.format = arguments.format;
  options.repair.close_gaps = parse_weld(arguments.weld);
  options.repair.fill_holes.max_edges = parse_fill_holes(arguments.fill_holes);
  options.elements = arguments.elements;
  options.separate_stl_copies = arguments.separate == "auto";
  options.repair.nested_shells = arguments.nested_shells;
  options.repair.pairing = arguments.pairing == "combinatorial" ? PairingPolicy::combinatorial
                                                                : PairingPolicy::geometric;
  if (arguments.print) {
    if (!options.format.empty() && options.format != "3mf") {  // (--format is lower case)
      throw UsageError(
          "--print writes 3MF, the format slicers read with units, objects and no "
          "re-weld; leave out --format " +
          options.format + " (or give --format 3mf)");
    }
    options.format = "3mf";
    options.print = true;
    options.print_keeps_weld = arguments.weld_given;
    options.print_keeps_fill_holes = arguments.fill_holes_given;
  }
  options.self_intersections = arguments.self_intersections;
  return options;
}

int run_batch(const BatchArguments& arguments) {
  const FileJobOptions options = job_options(arguments);
  BatchPlan plan;
  try {
    plan = plan_batch(arguments.in_dir, arguments.out_dir, options, arguments.in_place);
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
  // One error before any work, not one failed row per file.
  std::error_code error;
  std::filesystem::create_directories(arguments.out_dir, error);
  if (error) {
    throw UsageError(arguments.out_dir + ": cannot create the output folder (" + error.message() +
                     ")");
  }
  if (::access(arguments.out_dir.c_str(), W_OK) != 0) {
    throw UsageError(arguments.out_dir + ": cannot write in the output folder (" +
                     std::strerror(errno) + ")");
  }

  // The log: with --resume, a file whose last line says it was done with these options from
  // this input is skipped; every other file (failed, skipped, changed, new) is done again.
  const std::string log_path =
      arguments.log.empty() ? (std::filesystem::path(arguments.out_dir) / kBatchLogName).string()
                            : arguments.log;
  std::map<std::string, std::string> logged;
  try {
    logged = read_batch_log(log_path);
  } catch (const std::runtime_error& bad) {
    throw UsageError(bad.what());
  }
  std::vector<std::string> kept;
  std::vector<Entry> entries;
  for (const FileJob& job : plan.jobs) {
    Entry entry;
    entry.name = job.name;
    entry.job = &job;
    const auto line = logged.find(to_valid_utf8(job.name));
    if (arguments.resume && line != logged.end() && is_done_in_log(line->second, job, options)) {
      entry.up_to_date = true;
      entry.status = FileStatus::skipped;
      entry.reason = job.output + " is up to date (same input and options as its last run)";
      entry.record = batch_record_json(job.name, job.output_name, "skipped", entry.reason, nullptr);
      kept.push_back(line->second);
    }
    entries.push_back(std::move(entry));
  }
  write_batch_log(log_path, kept);
  std::ofstream log(log_path, std::ios::app | std::ios::binary);
  const auto log_entry = [&](const Entry& e) {
    if (e.up_to_date)
      return;
    const FileJob job = e.job ? *e.job : FileJob{arguments.in_dir + "/" + e.name, "", e.name, ""};
    log << batch_log_line(e.record, job, options) << '\n' << std::flush;
  };
  for (const BatchPlan::Unreadable& u : plan.unreadable) {
    Entry entry;
    entry.name = u.name;
    entry.status = FileStatus::skipped;
    entry.reason = u.reason;
    entry.record = skipped_record(u);
    log_entry(entry);
    entries.push_back(std::move(entry));
    if (!arguments.quiet) {
      std::cerr << "meshbridge: warning: skipped " << u.name << " in " << arguments.in_dir << ": "
                << u.reason << "\n";
    }
  }
  std::stable_sort(entries.begin(), entries.end(),
                   [](const Entry& a, const Entry& b) { return a.name < b.name; });

  // Files are taken in name order; records are printed in name order as soon as every earlier
  // one is done, so the output is the same for any --jobs.
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  const std::size_t to_do = static_cast<std::size_t>(std::count_if(
      entries.begin(), entries.end(), [](const Entry& e) { return e.job && !e.up_to_date; }));
  BatchProgress progress(to_do, !arguments.quiet && (terminal || arguments.progress), terminal);
  if (!arguments.json) {
    std::cout << "| file | status | faces | singular edges | singular vertices | faces out | "
                 "components after | watertight after | "
              << (arguments.self_intersections ? "self-intersecting pairs | " : "")
              << "note |\n|---|---|---:|---:|---:|---:|---:|---|"
              << (arguments.self_intersections ? "---:|" : "") << "---|\n";
  }
  std::vector<char> done(entries.size(), 0);
  for (std::size_t i = 0; i < entries.size(); ++i)
    done[i] = entries[i].job && !entries[i].up_to_date ? 0 : 1;
  BatchWarnings warnings(arguments.quiet);
  std::size_t next_to_print = 0, files_done = 0, failed_so_far = 0;
  const auto finished = [&](std::size_t i) {
    failed_so_far += entries[i].status == FileStatus::failed ? 1 : 0;
    done[i] = 1;
    log_entry(entries[i]);
    progress.clear();
    for (; next_to_print < entries.size() && done[next_to_print]; ++next_to_print)
      print_entry(entries[next_to_print], arguments, warnings);
    std::cout.flush();
    progress.file_done(entries[i].name, ++files_done, failed_so_far);
  };
  for (; next_to_print < entries.size() && done[next_to_print]; ++next_to_print)
    print_entry(entries[next_to_print], arguments, warnings);
  std::cout.flush();

  if (arguments.jobs <= 1) {
    for (std::size_t i = 0; i < entries.size(); ++i) {
      if (entries[i].job && !done[i]) {
        take_result(entries[i], run_file_job(*entries[i].job, options), *entries[i].job);
        finished(i);
      }
    }
  } else {
    run_in_child_processes(entries, done, options, arguments.jobs, finished);
  }

  progress.clear();
  std::cout.flush();
  warnings.finish();
  return print_summary(entries, arguments) ? kOk : kError;
}

}  // namespace

void add_batch_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<BatchArguments>();
  CLI::App* command = app.add_subcommand(
      "batch",
      "Repair every mesh below INDIR into OUTDIR (same relative paths); a table, or JSON Lines,\n"
      "in file name order on stdout. Exit 0 = every file read and written, 2 = some failed or\n"
      "could not be read.");
  command->add_option("INDIR", arguments->in_dir, "folder searched recursively for meshes")
      ->required();
  command->add_option("OUTDIR", arguments->out_dir, "folder the repaired meshes go to")->required();
  command
      ->add_option("--format", arguments->format,
                   "write every result in this format (default: each file's own)")
      ->transform(CLI::IsMember({"obj", "off", "ply", "stl", "3mf"}, CLI::ignore_case));
  command->add_option("--weld", arguments->weld, "TOL|auto, as in repair")
      ->capture_default_str()
      ->check(distance_or_auto());
  add_fill_holes_option(*command, arguments->fill_holes);
  command
      ->add_option("--separate", arguments->separate,
                   "auto|0: for STL outputs, auto moves the copies of split vertices apart by the "
                   "smallest distance a reader's weld keeps (as repair does); 0 keeps positions "
                   "exact, and the STL re-reads with the split vertices welded again")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "0"}));
  add_nested_shells_option(*command, arguments->nested_shells);
  command->add_option("--pairing", arguments->pairing, "as in repair")
      ->capture_default_str()
      ->transform(CLI::IsMember({"geometric", "combinatorial"}, CLI::ignore_case));
  command->add_flag("--json", arguments->json,
                    "print one JSON object per file (JSON Lines, docs/report-schema.md) instead "
                    "of the table; the summary goes to stderr");
  command->add_flag("--elements", arguments->elements,
                    "with --json: also list the defective elements; default counts only");
  command->add_flag("--quiet", arguments->quiet,
                    "errors only on stderr: no warnings, no progress, no summary");
  command->add_flag("--progress", arguments->progress,
                    "show progress on stderr even when it is not a terminal");
  command->add_flag("--in-place", arguments->in_place,
                    "allow OUTDIR to be INDIR or inside it (originals are replaced)");
  command->add_flag("--resume", arguments->resume,
                    "skip files done before with the same options from the same input (as the "
                    "log says); failed files are retried");
  command->add_option("--log", arguments->log,
                      "JSON Lines log of finished files, with the options and input of each "
                      "(default: OUTDIR/.meshbridge-batch.jsonl)");
  command
      ->add_option("--jobs,-j", arguments->jobs,
                   "files repaired in parallel, each in a process of its own (default: cores)")
      ->capture_default_str()
      ->check(whole_number_in(1, 1024));
  command->add_flag("--print", arguments->print,
                    "the slicer route of `repair --print` for every file: gap closing as wide "
                    "as PrusaSlicer's load-time repair (unless --weld), duplicate and zero-area "
                    "faces removed unless that opens the surface, holes of up to 32 edges filled "
                    "(unless --fill-holes), every output written as 3MF");
  command->add_flag("--self-intersections", arguments->self_intersections,
                    "also count the faces of each output that cross or overlap (as repair "
                    "--self-intersections): a table column, the records' self_intersections, "
                    "and the files with some in the summary");
  command->callback([arguments, command, &exit_code] {
    arguments->weld_given = command->count("--weld") > 0;
    arguments->fill_holes_given = command->count("--fill-holes") > 0;
    exit_code = run_batch(*arguments);
  });
}

}  // namespace meshbridge::cli
