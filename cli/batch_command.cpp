// SPDX-License-Identifier: GPL-3.0-or-later
#include "arguments.h"
#include "commands.h"

#include "meshbridge/io.h"
#include "meshbridge/repair.h"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>

namespace meshbridge::cli {

namespace {

namespace fs = std::filesystem;

struct BatchRow {
  std::string file;
  std::size_t faces = 0;
  std::size_t singular_edges = 0;
  std::size_t singular_vertices = 0;
  std::size_t faces_out = 0;
  std::size_t components_after = 0;
  bool manifold_after = false;
  double seconds = 0;
  std::string error;
};

std::vector<fs::path> mesh_files(const fs::path& dir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir))
    throw UsageError(dir.string() + ": not a directory");
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    if (entry.is_regular_file() && is_supported_mesh_file(entry.path().string())) {
      files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

int batch_command(const std::vector<std::string>& args) {
  const Arguments arguments(args, {"json", "quiet"}, {"format"});
  arguments.expect_positionals(
      2, "meshbridge batch INDIR OUTDIR [--format obj|off|ply|stl] [--json] [--quiet]");
  const fs::path in_dir = arguments.positionals()[0];
  const fs::path out_dir = arguments.positionals()[1];
  const std::string format = arguments.value("format", "");
  if (!format.empty() && !is_supported_mesh_file("x." + format)) {
    throw UsageError("--format must be obj, off, ply or stl, got '" + format + "'");
  }
  const std::vector<fs::path> files = mesh_files(in_dir);

  std::vector<BatchRow> rows;
  std::set<std::string> written;
  for (std::size_t i = 0; i < files.size(); ++i) {
    const fs::path relative = fs::relative(files[i], in_dir);
    if (!arguments.flag("quiet")) {
      std::cerr << "[" << i + 1 << "/" << files.size() << "] " << relative.string() << "\n";
    }
    BatchRow row;
    row.file = relative.string();
    const auto start = std::chrono::steady_clock::now();
    try {
      const Soup soup = read_soup(files[i].string());
      const RepairResult result = repair(soup);
      fs::path out = out_dir / relative;
      if (!format.empty()) {
        // a.obj and a.off both going to a.ply: the later one becomes a-off.ply.
        const std::string original = out.extension().string();
        out.replace_extension("." + format);
        if (!written.insert(out.string()).second) {
          out.replace_filename(out.stem().string() + "-" + original.substr(1) + "." + format);
          written.insert(out.string());
        }
      }
      fs::create_directories(out.parent_path());
      write_mesh(out.string(), result.mesh);
      row.faces = soup.num_faces();
      row.singular_edges = result.report.before.singular_edges.size();
      row.singular_vertices = result.report.before.num_singular_vertices();
      row.faces_out = result.report.faces_out;
      row.components_after = result.report.components_after;
      row.manifold_after = result.report.after.singular_edges.empty() &&
                           result.report.after.num_singular_vertices() == 0;
    } catch (const std::exception& error) {
      row.error = error.what();
    }
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rows.push_back(row);
  }

  std::size_t failed = 0;
  for (const BatchRow& row : rows)
    failed += row.error.empty() ? 0 : 1;
  if (arguments.flag("json")) {
    std::cout << "[";
    for (std::size_t i = 0; i < rows.size(); ++i) {
      const BatchRow& r = rows[i];
      std::ostringstream error;
      for (char ch : r.error)
        error << ((ch == '"' || ch == '\\') ? "\\" : "") << ch;
      std::cout << (i ? "," : "") << "\n{\"file\":\"" << r.file << "\",\"faces\":" << r.faces
                << ",\"singular_edges\":" << r.singular_edges
                << ",\"singular_vertices\":" << r.singular_vertices
                << ",\"faces_out\":" << r.faces_out
                << ",\"components_after\":" << r.components_after
                << ",\"manifold_after\":" << (r.manifold_after ? "true" : "false")
                << ",\"seconds\":" << r.seconds << ",\"error\":\"" << error.str() << "\"}";
    }
    std::cout << "\n]\n";
  } else {
    std::cout << std::fixed << std::setprecision(4);
    std::cout << "| file | faces | singular edges | singular vertices | faces out | components "
                 "after | manifold after | seconds |\n|---|---:|---:|---:|---:|---:|---|---:|\n";
    for (const BatchRow& r : rows) {
      if (!r.error.empty()) {
        std::cout << "| " << r.file << " | error: " << r.error << " | | | | | no | " << r.seconds
                  << " |\n";
        continue;
      }
      std::cout << "| " << r.file << " | " << r.faces << " | " << r.singular_edges << " | "
                << r.singular_vertices << " | " << r.faces_out << " | " << r.components_after
                << " | " << (r.manifold_after ? "yes" : "no") << " | " << r.seconds << " |\n";
    }
    std::cout << rows.size() << " file(s), " << rows.size() - failed << " repaired, " << failed
              << " failed\n";
  }
  return failed > 0 ? kError : kOk;
}

}  // namespace meshbridge::cli
