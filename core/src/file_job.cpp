// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/file_job.h"
#include "meshbridge/preview_repair.h"
#include "meshbridge/repair_file.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/polygon_triangles.h"
#include "meshbridge/read_accounting.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <new>
#include <set>
#include <stdexcept>
#include <system_error>

namespace meshbridge {

namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  for (auto& ch : text)
    ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return text;
}

//! True if `inner` is `outer` or lies below it (both absolute and normalised).
bool is_within(const fs::path& inner, const fs::path& outer) {
  auto i = inner.begin();
  for (auto o = outer.begin(); o != outer.end(); ++o, ++i) {
    if (o->empty())  // trailing separator
      continue;
    if (i == inner.end() || *i != *o)
      return false;
  }
  return true;
}

fs::path normalised(const fs::path& path) {
  std::error_code error;
  fs::path result = fs::weakly_canonical(fs::absolute(path, error), error);
  return error ? fs::absolute(path).lexically_normal() : result;
}

//! `path` below `root` as batch names it: by the names in the folder, not by where a symbolic
//! link leads ('/'-separated).
std::string name_below(const fs::path& path, const fs::path& root) {
  return path.lexically_relative(root).generic_string();
}

//! Depth-first walk that notes every folder it cannot list instead of stopping there. Folder
//! symlinks are not followed (no cycles) and are noted; file symlinks are read, under the link's
//! own name. An entry with a mesh extension that is no readable regular file (a link to nothing,
//! a link loop, a FIFO or device) is noted too, never passed over.
void walk(const fs::path& root, const fs::path& dir, const fs::path& leave_out,
          std::vector<fs::path>& files, std::vector<BatchPlan::Unreadable>& unreadable) {
  std::error_code error;
  fs::directory_iterator it(dir, error);
  if (error) {
    unreadable.push_back(
        {name_below(dir, root), "cannot list the folder (" + error.message() + ")"});
    return;
  }
  for (; it != fs::directory_iterator(); it.increment(error)) {
    if (error)
      break;
    const fs::directory_entry& entry = *it;
    std::error_code link_error, status_error;
    const bool link = entry.is_symlink(link_error);
    const fs::file_status target = fs::status(entry.path(), status_error);
    if (!link && fs::is_directory(target)) {
      if (leave_out.empty() || normalised(entry.path()) != leave_out)
        walk(root, entry.path(), leave_out, files, unreadable);
    } else if (link && fs::is_directory(target)) {
      unreadable.push_back({name_below(entry.path(), root),
                            "a symbolic link to a folder, not followed (batch walks the folder "
                            "itself, so that no folder is read twice or in a loop)"});
    } else if (is_supported_mesh_file(entry.path().string())) {
      if (fs::is_regular_file(target)) {
        files.push_back(entry.path());
      } else if (link && target.type() == fs::file_type::not_found) {
        unreadable.push_back({name_below(entry.path(), root),
                              "a symbolic link to nothing: its target does not exist"});
      } else if (status_error) {
        unreadable.push_back({name_below(entry.path(), root),
                              (link ? "cannot follow the symbolic link (" : "cannot read it (") +
                                  status_error.message() + ")"});
      } else {
        unreadable.push_back({name_below(entry.path(), root),
                              "not a regular file (a FIFO, socket or device): not read"});
      }
    }
  }
  if (error) {
    unreadable.push_back(
        {name_below(dir, root), "cannot list the whole folder (" + error.message() + ")"});
  }
}

}  // namespace

const char* to_string(FileStatus status) {
  switch (status) {
    case FileStatus::clean:
      return "clean";
    case FileStatus::repaired:
      return "repaired";
    case FileStatus::failed:
      return "failed";
    case FileStatus::skipped:
      return "skipped";
  }
  return "failed";
}

BatchPlan plan_batch(const std::string& in_dir, const std::string& out_dir,
                     const FileJobOptions& options, bool in_place) {
  std::error_code error;
  if (!fs::exists(in_dir, error))
    throw std::invalid_argument(in_dir + ": no such folder");
  if (!fs::is_directory(in_dir, error))
    throw std::invalid_argument(in_dir + ": not a folder");
  const std::string format = lower(options.format);
  if (!format.empty() && !is_supported_mesh_file("x." + format))
    throw std::invalid_argument("format must be obj, off, ply, stl or 3mf, got '" + options.format +
                                "'");
  const fs::path in_abs = normalised(in_dir), out_abs = normalised(out_dir);
  if (!in_place && is_within(out_abs, in_abs)) {
    throw std::invalid_argument(
        out_dir + (out_abs == in_abs ? ": is the input folder" : ": is inside the input folder ") +
        (out_abs == in_abs ? "" : in_dir) +
        "; the repaired files would replace or mix with the originals (use --in-place to "
        "overwrite the originals on purpose)");
  }

  BatchPlan plan;
  std::vector<fs::path> files;
  const bool out_inside = is_within(out_abs, in_abs) && out_abs != in_abs;
  walk(in_dir, in_dir, out_inside ? out_abs : fs::path(), files, plan.unreadable);
  std::vector<std::pair<std::string, fs::path>> named;
  for (const fs::path& file : files) {
    const std::string name = name_below(file, in_dir);
    if (::access(file.c_str(), R_OK) != 0) {
      plan.unreadable.push_back(
          {name, "cannot open the file (" + std::string(std::strerror(errno)) + ")"});
      continue;
    }
    named.emplace_back(name, file);
  }
  std::sort(named.begin(), named.end());
  std::sort(plan.unreadable.begin(), plan.unreadable.end(),
            [](const auto& a, const auto& b) { return a.name < b.name; });

  // Every output as its input alone names it: a renamed output must not take one of these.
  const auto in_format = [&format](const std::string& name) {
    fs::path relative = name;
    if (!format.empty())
      relative.replace_extension("." + format);
    return relative;
  };
  std::set<std::string> natural, taken;
  for (const auto& named_file : named)
    natural.insert(in_format(named_file.first).generic_string());
  // A file already in the output format keeps its own name: with --in-place its result replaces
  // it, never another file's (a.obj and a.ply to PLY: a.ply stays a.ply, a.obj becomes a-obj.ply).
  for (const auto& named_file : named) {
    if (in_format(named_file.first).generic_string() == named_file.first)
      taken.insert(named_file.first);
  }
  for (const auto& [name, file] : named) {
    FileJob job;
    job.input = file.string();
    job.name = name;
    fs::path relative = in_format(name);
    const bool own_name = relative.generic_string() == name;
    if (!own_name && taken.count(relative.generic_string()) > 0) {
      // a.obj and a.off both going to a.ply: the later one becomes a-off.ply, or a-off-2.ply
      // (-3, ...) when a-off.ply is another file's output (or a file of the folder).
      const std::string base =
          relative.stem().string() + "-" + fs::path(name).extension().string().substr(1);
      relative.replace_filename(base + "." + format);
      for (int n = 2; taken.count(relative.generic_string()) > 0 ||
                      natural.count(relative.generic_string()) > 0;
           ++n)
        relative.replace_filename(base + "-" + std::to_string(n) + "." + format);
    }
    taken.insert(relative.generic_string());
    job.output_name = relative.generic_string();
    job.output = (fs::path(out_dir) / relative).string();
    plan.jobs.push_back(job);
  }
  return plan;
}

FileJobResult run_file_job(const FileJob& job, const FileJobOptions& options) {
  FileJobResult result;
  const ReportJsonOptions json{options.elements, -1};
  const auto finish = [&](FileStatus status, const std::string& reason, const RepairReport* report,
                          const ReadInfo* read) {
    result.status = status;
    result.reason = reason;
    result.record =
        batch_record_json(job.name, job.output_name, to_string(status), reason, report, read, json,
                          report != nullptr && result.reread ? &*result.reread : nullptr,
                          report != nullptr ? &result.written : nullptr,
                          report != nullptr && result.crossings ? &*result.crossings : nullptr);
    return result;
  };

  std::error_code error;
  if (options.resume && fs::exists(job.output, error) && job.output != job.input) {
    const auto out_time = fs::last_write_time(job.output, error);
    const auto in_time = fs::last_write_time(job.input, error);
    if (!error && out_time > in_time)
      return finish(FileStatus::skipped, job.output + " is newer than the input", nullptr, nullptr);
  }
  if (::access(job.input.c_str(), R_OK) != 0) {
    return finish(FileStatus::skipped,
                  job.input + ": cannot open the file (" + std::strerror(errno) + ")", nullptr,
                  nullptr);
  }
  RepairedFile file;
  // What the reader found, once the file was read (a failure after reading names it too).
  const auto read_info = [&file]() -> const ReadInfo* { return file.read ? &file.info : nullptr; };
  try {
    RepairFileOptions file_options;
    file_options.repair = options.repair;
    file_options.separation = options.separate_stl_copies ? kAutoSeparation : 0;
    file_options.create_folder = true;
    file_options.print = options.print;
    file_options.print_keeps_weld = options.print_keeps_weld;
    file_options.print_keeps_fill_holes = options.print_keeps_fill_holes;
    file_options.self_intersections = options.self_intersections;
    repair_file(job.input, job.output, file_options, file);
    if (file.info.changed_anything())
      result.reading = describe_reading(file.info);
    result.written = std::move(file.written);
    result.reread = std::move(file.reread);
    result.crossings = std::move(file.crossings);
    result.report = std::move(file.report);
    const RepairReport& r = result.report;
    // Clean: repair changed nothing (as `check` exits 0), the mesh is written as read, every
    // vertex and face in place; an open surface it leaves as it is is clean too.
    const bool clean = !repair_changes_input(r) && !file.info.changed_anything();
    return finish(clean ? FileStatus::clean : FileStatus::repaired, "", &r, &file.info);
  } catch (const std::bad_alloc&) {
    return finish(FileStatus::failed, job.input + ": out of memory", nullptr, read_info());
  } catch (const std::exception& failure) {
    return finish(FileStatus::failed, failure.what(), nullptr, read_info());
  }
}

std::string skipped_record(const BatchPlan::Unreadable& entry) {
  return batch_record_json(entry.name, "", to_string(FileStatus::skipped), entry.reason, nullptr);
}

}  // namespace meshbridge
