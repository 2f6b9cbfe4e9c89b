// SPDX-License-Identifier: GPL-3.0-or-later
#include "commands.h"
#include "validators.h"

#include "meshbridge/file_job.h"

#include <CLI/CLI.hpp>

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <memory>
#include <mutex>
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
  unsigned jobs = std::max(1u, std::thread::hardware_concurrency());
};

//! One line of the outcome: a job's result, or an unreadable entry found while listing.
struct Entry {
  std::string name;
  const FileJob* job = nullptr;  //!< null: unreadable, `result` is already final
  FileJobResult result;
};

std::string clock_text(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  char text[32];
  std::snprintf(text, sizeof text, "%ld:%02ld", s / 60, s % 60);
  return text;
}

//! Files done / total / ETA on stderr: one line rewritten in place on a terminal, one line per
//! file elsewhere (only with --progress).
class BatchProgress {
 public:
  BatchProgress(std::size_t total, bool on, bool terminal)
      : total_(total),
        on_(on && total > 0),
        terminal_(terminal),
        start_(std::chrono::steady_clock::now()) {}
  void file_done(const std::string& name, std::size_t done, std::size_t failed) {
    if (!on_)
      return;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const double eta = done ? elapsed / done * (total_ - done) : 0;
    std::ostringstream line;
    line << "[" << done << "/" << total_ << "] "
         << (failed ? std::to_string(failed) + " failed, " : "") << "elapsed "
         << clock_text(elapsed) << ", ETA " << clock_text(eta) << "  " << name;
    std::string text = line.str();
    if (terminal_) {
      if (text.size() > 100)
        text = text.substr(0, 97) + "...";
      std::cerr << "\r\033[K" << text << (done == total_ ? "\n" : "") << std::flush;
    } else {
      std::cerr << text << "\n";
    }
  }

 private:
  std::size_t total_;
  bool on_, terminal_;
  std::chrono::steady_clock::time_point start_;
};

void print_table_row(const Entry& e) {
  const FileJobResult& r = e.result;
  std::cout << "| " << e.name << " | " << to_string(r.status) << " | ";
  if (r.status == FileStatus::clean || r.status == FileStatus::repaired) {
    const RepairReport& p = r.report;
    std::cout << p.faces_in << " | " << p.before.singular_edges.size() << " | "
              << p.before.num_singular_vertices() << " | " << p.faces_out << " | "
              << p.after.num_components << " | " << (p.after.watertight ? "yes" : "no") << " |\n";
  } else {
    std::cout << r.reason << " | | | | | |\n";
  }
}

int run_batch(const BatchArguments& arguments) {
  FileJobOptions options;
  options.format = arguments.format;
  options.resume = arguments.resume;
  options.elements = arguments.elements;
  options.repair.pairing = arguments.pairing == "combinatorial" ? PairingPolicy::combinatorial
                                                                : PairingPolicy::geometric;
  BatchPlan plan;
  try {
    plan = plan_batch(arguments.in_dir, arguments.out_dir, options, arguments.in_place);
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }

  std::vector<Entry> entries;
  for (const FileJob& job : plan.jobs)
    entries.push_back({job.name, &job, {}});
  for (const BatchPlan::Unreadable& u : plan.unreadable) {
    Entry entry{u.name, nullptr, {}};
    entry.result.status = FileStatus::skipped;
    entry.result.reason = u.reason;
    entry.result.record = skipped_record(u);
    entries.push_back(std::move(entry));
    std::cerr << "meshbridge: warning: skipped " << u.name << " in " << arguments.in_dir << ": "
              << u.reason << "\n";
  }
  std::stable_sort(entries.begin(), entries.end(),
                   [](const Entry& a, const Entry& b) { return a.name < b.name; });

  // Workers take files in name order; records are printed in name order as soon as every
  // earlier one is done, so the output is the same for any --jobs.
  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  BatchProgress progress(plan.jobs.size(), !arguments.quiet && (terminal || arguments.progress),
                         terminal);
  if (!arguments.json) {
    std::cout << "| file | status | faces | singular edges | singular vertices | faces out | "
                 "components after | watertight after |\n"
                 "|---|---|---:|---:|---:|---:|---:|---|\n";
  }
  std::vector<char> done(entries.size(), 0);
  for (std::size_t i = 0; i < entries.size(); ++i)
    done[i] = entries[i].job ? 0 : 1;
  std::mutex lock;
  std::size_t next_to_print = 0, files_done = 0, failed_so_far = 0;
  const auto print_ready = [&] {  // under `lock`
    for (; next_to_print < entries.size() && done[next_to_print]; ++next_to_print) {
      if (arguments.json) {
        std::cout << entries[next_to_print].result.record << "\n";
      } else {
        print_table_row(entries[next_to_print]);
      }
    }
    std::cout.flush();
  };
  std::atomic<std::size_t> next_job{0};
  const auto work = [&] {
    for (;;) {
      const std::size_t i = next_job.fetch_add(1);
      if (i >= entries.size())
        return;
      if (!entries[i].job)
        continue;
      FileJobResult result = run_file_job(*entries[i].job, options);
      const std::lock_guard<std::mutex> guard(lock);
      failed_so_far += result.status == FileStatus::failed ? 1 : 0;
      entries[i].result = std::move(result);
      done[i] = 1;
      progress.file_done(entries[i].name, ++files_done, failed_so_far);
      print_ready();
    }
  };
  {
    const std::lock_guard<std::mutex> guard(lock);
    print_ready();  // unreadable entries before the first job
  }
  const unsigned threads = static_cast<unsigned>(
      std::min<std::size_t>(arguments.jobs, std::max<std::size_t>(1, plan.jobs.size())));
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < threads; ++t)
    pool.emplace_back(work);
  work();
  for (std::thread& thread : pool)
    thread.join();

  std::size_t count[4] = {0, 0, 0, 0};
  bool all_written = true;
  for (const Entry& e : entries) {
    ++count[static_cast<int>(e.result.status)];
    // Skipped because up to date is fine; skipped because unreadable is not.
    if (e.result.status == FileStatus::failed || !e.job) {
      all_written = false;
    } else if (e.result.status == FileStatus::skipped &&
               e.result.reason.find("is newer than the input") == std::string::npos) {
      all_written = false;
    }
  }
  std::ostringstream summary;
  summary << entries.size() << " file(s): " << count[int(FileStatus::clean)] << " clean, "
          << count[int(FileStatus::repaired)] << " repaired, " << count[int(FileStatus::failed)]
          << " failed, " << count[int(FileStatus::skipped)] << " skipped\n";
  if (arguments.json) {
    if (!arguments.quiet)
      std::cerr << summary.str();
  } else {
    std::cout << summary.str();
  }
  return all_written ? kOk : kError;
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
      ->transform(CLI::IsMember({"obj", "off", "ply", "stl"}, CLI::ignore_case));
  command->add_option("--pairing", arguments->pairing, "as in repair")
      ->capture_default_str()
      ->transform(CLI::IsMember({"geometric", "combinatorial"}, CLI::ignore_case));
  command->add_flag("--json", arguments->json,
                    "print one JSON object per file (JSON Lines, docs/report-schema.md) instead "
                    "of the table; the summary goes to stderr");
  command->add_flag("--elements", arguments->elements,
                    "with --json: also list the defective elements; default counts only");
  command->add_flag("--quiet", arguments->quiet, "no progress and no summary on stderr");
  command->add_flag("--progress", arguments->progress,
                    "show progress on stderr even when it is not a terminal");
  command->add_flag("--in-place", arguments->in_place,
                    "allow OUTDIR to be INDIR or inside it (originals are replaced)");
  command->add_flag("--resume", arguments->resume,
                    "skip files whose output exists and is newer than the input");
  command->add_option("--jobs,-j", arguments->jobs, "files repaired in parallel (default: cores)")
      ->capture_default_str()
      ->check(whole_number_in(1, 1024));
  command->callback([arguments, &exit_code] { exit_code = run_batch(*arguments); });
}

}  // namespace meshbridge::cli
