// SPDX-License-Identifier: GPL-3.0-or-later
#include "harness.h"

#include "meshbridge/detect_defects.h"

#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <sched.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace meshbridge::bench {

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

//! Resets VmHWM to the current resident size (Linux >= 4.0).
void reset_peak() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

//! User + system CPU seconds of this process so far.
double cpu_time() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}

}  // namespace

Clock::Clock() {
  base_kb_ = read_status_kb("VmRSS");
  reset_peak();
  cpu_start_ = cpu_time();
  start_ = last_lap_ = now();
}

void Clock::stop() {
  if (stopped_)
    return;
  seconds_ = now() - start_;
  cpu_seconds_ = cpu_time() - cpu_start_;
  peak_kb_ = read_status_kb("VmHWM") - base_kb_;
  stopped_ = true;
}

double Clock::lap() {
  const double t = now();
  const double lap = t - last_lap_;
  last_lap_ = t;
  return lap;
}

void evaluate(const Soup& result, Outcome& outcome) {
  const DefectReport report = detect_defects(result);
  outcome.faces = static_cast<long>(result.num_faces());
  outcome.vertices = static_cast<long>(result.num_vertices());
  outcome.unreferenced_vertices = static_cast<long>(report.isolated_vertices.size());
  outcome.components = static_cast<long>(report.num_components);
  outcome.boundary_edges = static_cast<long>(report.boundary_edges.size());
  outcome.singular_edges = static_cast<long>(report.singular_edges.size());
  outcome.singular_vertices = static_cast<long>(report.num_singular_vertices());
  outcome.inconsistent_edges = static_cast<long>(report.inconsistent_edges.size());
}

Soup to_soup(const PolyMesh& mesh) {
  Soup soup;
  soup.reserve(mesh.n_vertices(), mesh.n_faces(), mesh.n_halfedges() / 2 + 3 * mesh.n_faces());
  for (auto v : mesh.all_vertices())
    soup.add_vertex(mesh.point(v));
  std::vector<Index> polygon;
  for (auto f : mesh.faces()) {
    polygon.clear();
    for (auto v : mesh.fv_range(f))
      polygon.push_back(static_cast<Index>(v.idx()));
    soup.add_polygon(polygon);
  }
  return soup;
}

void add_note(Outcome& outcome, const char* format, ...) {
  std::size_t used = std::strlen(outcome.note);
  if (used + 3 >= sizeof outcome.note)
    return;
  if (used > 0) {
    std::strcat(outcome.note, "; ");
    used += 2;
  }
  va_list args;
  va_start(args, format);
  std::vsnprintf(outcome.note + used, sizeof outcome.note - used, format, args);
  va_end(args);
}

Outcome run_in_child(const Soup& soup, const Method& method, bool evaluate_output) {
  int fds[2];
  if (pipe(fds) != 0)
    throw std::runtime_error("pipe failed");
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t child = fork();
  if (child < 0)
    throw std::runtime_error("fork failed");
  if (child == 0) {
    close(fds[0]);
    Outcome outcome;
    if (!evaluate_output)
      outcome.faces = -2;
    try {
      Clock clock;
      method(soup, clock, outcome);
      clock.stop();
      outcome.seconds = clock.seconds();
      outcome.cpu_seconds = clock.cpu_seconds();
      outcome.peak_kb = clock.peak_kb();
    } catch (const std::exception& error) {
      outcome.failed = true;
      std::snprintf(outcome.note, sizeof outcome.note, "failed: %s", error.what());
    }
    if (outcome.faces == -2)
      outcome.faces = -1;
    const ssize_t written = write(fds[1], &outcome, sizeof outcome);
    _exit(written == static_cast<ssize_t>(sizeof outcome) ? 0 : 1);
  }
  close(fds[1]);
  Outcome outcome;
  std::size_t got = 0;
  while (got < sizeof outcome) {
    const ssize_t n = read(fds[0], reinterpret_cast<char*>(&outcome) + got, sizeof outcome - got);
    if (n <= 0)
      break;
    got += static_cast<std::size_t>(n);
  }
  close(fds[0]);
  int status = 0;
  waitpid(child, &status, 0);
  if (got != sizeof outcome || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    Outcome crashed;
    crashed.failed = true;
    std::snprintf(crashed.note, sizeof crashed.note, "failed: child %s %d",
                  WIFSIGNALED(status) ? "killed by signal" : "exited with status",
                  WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
    return crashed;
  }
  return outcome;
}

Outcome measure(const Soup& soup, const Method& method, int repeat) {
  Outcome first = run_in_child(soup, method, /*evaluate_output=*/true);
  if (first.failed)
    return first;
  for (int i = 1; i < repeat; ++i) {
    const Outcome again = run_in_child(soup, method, /*evaluate_output=*/false);
    if (again.failed)
      return again;
    first.peak_kb = std::max(first.peak_kb, again.peak_kb);
    first.cpu_seconds = std::min(first.cpu_seconds, again.cpu_seconds);
    if (again.seconds < first.seconds) {
      first.seconds = again.seconds;
      std::memcpy(first.note, again.note, sizeof first.note);  // its sub-timings
    }
  }
  return first;
}

long available_memory_kb() {
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  long kb = 0;
  while (meminfo >> key >> kb) {
    if (key == "MemAvailable:")
      return kb;
    meminfo.ignore(256, '\n');
  }
  return 0;
}

std::string load_average() {
  std::ifstream loadavg("/proc/loadavg");
  std::string one, five, fifteen;
  loadavg >> one >> five >> fifteen;
  return one + " " + five + " " + fifteen;
}

std::string machine_description() {
  std::string cpu = "unknown CPU";
  {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line;
    while (std::getline(cpuinfo, line)) {
      if (line.compare(0, 10, "model name") == 0) {
        const auto colon = line.find(':');
        if (colon != std::string::npos)
          cpu = line.substr(line.find_first_not_of(" \t", colon + 1));
        break;
      }
    }
  }
  long mem_kb = 0;
  {
    std::ifstream meminfo("/proc/meminfo");
    std::string key;
    meminfo >> key >> mem_kb;  // "MemTotal: N kB"
  }
  // nproc: the CPUs this process may run on.
  cpu_set_t set;
  CPU_ZERO(&set);
  const int nproc = sched_getaffinity(0, sizeof set, &set) == 0
                        ? CPU_COUNT(&set)
                        : static_cast<int>(std::thread::hardware_concurrency());
  char text[512];
  std::snprintf(text, sizeof text, "nproc %d, %s, %.1f GiB RAM", nproc, cpu.c_str(),
                mem_kb / (1024.0 * 1024.0));
  return text;
}

}  // namespace meshbridge::bench
