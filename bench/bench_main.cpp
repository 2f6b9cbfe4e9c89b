// SPDX-License-Identifier: GPL-3.0-or-later
// Side-by-side timing and peak memory of OpenMesh's stock build and MeshBridge on one in-memory
// soup. Usage: meshbridge-bench [checkerboard N | torus N M] [--repeat R]
// Prints one row per method: median time of R runs (each in a fresh forked child), ratio to the
// stock build, peak memory above the soup, and result figures.

#include "meshbridge/bridged_mesh.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/edge_bridges.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"
#include "meshbridge/stock_build.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <stdexcept>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

using namespace meshbridge;

namespace {

long read_status_kb(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::string key = std::string(field) + ":";
  while (std::getline(status, line)) {
    if (line.compare(0, key.size(), key) == 0)
      return std::atol(line.c_str() + key.size());
  }
  return -1;
}

void reset_peak() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
}

struct Row {
  std::string method;
  double seconds = 0;
  long peak_kb = 0;
  std::string figures;
};

// Runs `run` in a forked child, so every run starts from the same allocator state and its peak
// memory is its own: peak = VmHWM (reset through clear_refs) minus VmRSS at the start.
struct Sample {
  double seconds = 0;
  long peak_kb = 0;
  char figures[512] = {};
};

Sample sample_in_child(const std::function<std::string()>& run) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    close(fds[0]);
    Sample sample;
    const long base = read_status_kb("VmRSS");
    reset_peak();
    const auto start = std::chrono::steady_clock::now();
    const std::string figures = run();
    const auto stop = std::chrono::steady_clock::now();
    sample.seconds = std::chrono::duration<double>(stop - start).count();
    sample.peak_kb = read_status_kb("VmHWM") - base;
    std::snprintf(sample.figures, sizeof sample.figures, "%s", figures.c_str());
    const ssize_t written = write(fds[1], &sample, sizeof sample);
    _exit(written == static_cast<ssize_t>(sizeof sample) ? 0 : 1);
  }
  close(fds[1]);
  Sample sample;
  const ssize_t got = read(fds[0], &sample, sizeof sample);
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (got != static_cast<ssize_t>(sizeof sample) || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw std::runtime_error("benchmark child failed");
  }
  return sample;
}

Row measure(const std::string& method, int repeat, const std::function<std::string()>& run) {
  Row row;
  row.method = method;
  std::vector<double> times;
  for (int i = 0; i < repeat; ++i) {
    const Sample sample = sample_in_child(run);
    times.push_back(sample.seconds);
    row.peak_kb = std::max(row.peak_kb, sample.peak_kb);
    row.figures = sample.figures;
  }
  std::sort(times.begin(), times.end());
  row.seconds = times[times.size() / 2];
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  std::string model = "checkerboard";
  int n = 56, m = 0, repeat = 3;
  std::vector<std::string> args(argv + 1, argv + argc);
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--repeat" && i + 1 < args.size()) {
      repeat = std::max(1, std::atoi(args[++i].c_str()));
    } else if (args[i] == "checkerboard" && i + 1 < args.size()) {
      model = args[i];
      n = std::atoi(args[++i].c_str());
    } else if (args[i] == "torus" && i + 2 < args.size()) {
      model = args[i];
      n = std::atoi(args[++i].c_str());
      m = std::atoi(args[++i].c_str());
    } else {
      std::cerr << "usage: meshbridge-bench [checkerboard N | torus N M] [--repeat R]\n";
      return 2;
    }
  }
  const Soup soup =
      model == "checkerboard" ? models::checkerboard_cubes(n) : models::torus_grid(n, m);
  std::printf("model %s %d%s%s: %zu vertices, %zu faces, %d run(s) per method (median)\n",
              model.c_str(), n, m ? " " : "", m ? std::to_string(m).c_str() : "",
              soup.num_vertices(), soup.num_faces(), repeat);

  std::vector<Row> rows;
  rows.push_back(measure("OpenMesh stock build (baseline)", repeat, [&] {
    const StockBuild stock = build_stock(soup);
    const auto& r = stock.report;
    return std::to_string(r.vertices_created) + " v, " + std::to_string(r.faces_kept) + " f, " +
           std::to_string(r.faces_detached) + " detached, " + std::to_string(r.boundary_edges) +
           " boundary edges, " + std::to_string(r.components) + " components";
  }));
  rows.push_back(measure("group sides (floor)", repeat, [&] {
    const std::vector<Index> corner_face = corner_faces(soup);
    const EdgeBridges bridges = group_sides(soup, corner_face);
    return std::to_string(bridges.num_edges()) + " edges";
  }));
  rows.push_back(measure("MeshBridge detection", repeat, [&] {
    const DefectReport r = detect_defects(soup);
    return std::to_string(r.singular_edges.size()) + " singular edges, " +
           std::to_string(r.num_singular_vertices()) + " singular vertices";
  }));
  rows.push_back(measure("MeshBridge bridged OpenMesh build", repeat, [&] {
    const BridgedMesh b = build_bridged_mesh(soup);
    return std::to_string(b.mesh.n_vertices()) + " v, " + std::to_string(b.mesh.n_faces()) +
           " f, " + std::to_string(b.add_face_failures) + " add_face failures";
  }));
  rows.push_back(measure("MeshBridge repair (indexed)", repeat, [&] {
    const RepairResult r = repair(soup);
    return std::to_string(r.mesh.soup.num_vertices()) + " v, " +
           std::to_string(r.mesh.soup.num_faces()) + " f, " +
           std::to_string(r.report.components_after) + " components, " +
           std::to_string(r.report.boundary_edges_after) + " boundary edges";
  }));
  rows.push_back(measure("MeshBridge repair + OpenMesh build", repeat, [&] {
    const RepairResult r = repair(soup);
    const OpenMeshBuild b = to_openmesh(r.mesh);
    return std::to_string(b.mesh.n_faces()) + " f, " + std::to_string(b.add_face_failures) +
           " add_face failures";
  }));

  const double base = rows.front().seconds;
  const long base_kb = rows.front().peak_kb;
  std::printf("\n| method | time s | time / stock | peak MiB | peak / stock | result |\n");
  std::printf("|---|---:|---:|---:|---:|---|\n");
  for (const Row& row : rows) {
    std::printf("| %s | %.3f | %.2f | %.0f | %.2f | %s |\n", row.method.c_str(), row.seconds,
                row.seconds / base, row.peak_kb / 1024.0, double(row.peak_kb) / base_kb,
                row.figures.c_str());
  }
  return 0;
}
