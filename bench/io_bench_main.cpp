// SPDX-License-Identifier: GPL-3.0-or-later
// meshbridge-io-bench: the single steps of the whole-process benchmark (scripts/bench.sh --io),
// each one process, so that a script times them side by side with /usr/bin/time:
//
//   make DIR                    writes the benchmark files: checkerboard 1M and 5M, clean torus
//                               1M, each as .obj .off .ply (binary) .stl (binary)
//   make-soup DIR               the 1M checkerboard as OBJ three ways: indexed, and written per
//                               face vertex (every triangle with its own 3 vertices), in file
//                               order and with the faces shuffled (scripts/bench_soup.sh)
//   openmesh-read FILE          OpenMesh's stock read_mesh into a PolyMesh
//   openmesh-readwrite IN OUT   OpenMesh's read_mesh + write_mesh (binary PLY and STL)
//   parse FILE                  MeshBridge's read_soup (parse, validate, account)
//   read FILE [RUNS]            read_soup without and with MeshAttributes (what repair_file
//                               reads), alternating RUNS (5) times in one process: best and
//                               median of each (the OBJ vt/vn cost, issue 31)
//   floor FILE                  the floor: mmap + one pass over the bytes (text: every number
//                               through std::from_chars; binary: every 4-byte word summed)
//   split FILE [RUNS]           in one process: floor, parse and parse with one thread
//                               (MESHBRIDGE_THREADS=1) alternating 3 x RUNS (5) times (fastest
//                               and median of each), then detect, repair and write,
//                               best of RUNS: the parse/floor ratio and the parse/compute/write
//                               split measured side by side
//   read-3mf DIR [RUNS] [F.3mf...] 3MF against binary STL (DESIGN.md section 9: "3MF read within
//                               2x of binary STL per face"): writes the clean 1M torus and the
//                               1M checkerboard as .3mf and .stl into DIR (once), and each F's
//                               triangles as DIR/F.stl; then reads every 3MF (its meshes read
//                               apart by the scan as the part is inflated, by the scan of the
//                               part inflated whole, by pugixml alone, and by lib3mf alone) and
//                               STL RUNS (5) times in one process, in a shuffled order every
//                               round; prints the best wall and CPU time per face of each and
//                               the 3MF/STL ratios per model
//
// Every command prints one line: what it did and a count, so a wrong run is visible.
#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <functional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using namespace meshbridge;
using OmMesh = OpenMesh::PolyMesh_ArrayKernelT<>;

int make(const std::string& dir) {
  struct Model {
    const char* name;
    Soup soup;
  };
  const auto torus = [] {  // 1,053,696 faces, as the comparison benchmark's clean control
    return models::torus_grid(1176, 448);
  };
  Model list[] = {{"checkerboard_1m", models::checkerboard_cubes(56)},
                  {"torus_1m", torus()},
                  {"checkerboard_5m", models::checkerboard_cubes(94)}};
  for (Model& m : list) {
    IndexedMesh mesh;
    mesh.soup = std::move(m.soup);
    for (const char* ext : {"obj", "off", "ply", "stl"}) {
      const std::string path = dir + "/" + m.name + "." + ext;
      write_mesh(path, mesh);
      std::printf("wrote %s (%zu faces)\n", path.c_str(), mesh.soup.num_faces());
    }
  }
  return 0;
}

int make_soup(const std::string& dir) {
  const Soup indexed = models::checkerboard_cubes(56);
  std::vector<Index> order(indexed.num_faces());
  for (std::size_t f = 0; f < order.size(); ++f)
    order[f] = static_cast<Index>(f);
  const auto per_face_vertex = [&](const std::vector<Index>& faces) {
    IndexedMesh mesh;
    for (Index f : faces) {
      std::vector<Index> polygon;
      for (Index v : indexed.polygon(f))
        polygon.push_back(mesh.soup.add_vertex(indexed.positions[v]));
      mesh.soup.add_polygon(polygon);
    }
    return mesh;
  };
  IndexedMesh mesh;
  mesh.soup = indexed;
  write_mesh(dir + "/checkerboard_1m.obj", mesh);
  write_mesh(dir + "/checkerboard_1m_soup.obj", per_face_vertex(order));
  std::mt19937 random(1);
  std::shuffle(order.begin(), order.end(), random);
  write_mesh(dir + "/checkerboard_1m_soup_shuffled.obj", per_face_vertex(order));
  std::printf("wrote 3 files of %zu faces to %s\n", indexed.num_faces(), dir.c_str());
  return 0;
}

int openmesh_read(const std::string& path) {
  OmMesh mesh;
  OpenMesh::IO::Options options;
  if (!OpenMesh::IO::read_mesh(mesh, path, options)) {
    std::fprintf(stderr, "OpenMesh could not read %s\n", path.c_str());
    return 1;
  }
  std::printf("openmesh-read %s: %zu vertices, %zu faces\n", path.c_str(), mesh.n_vertices(),
              mesh.n_faces());
  return 0;
}

int openmesh_readwrite(const std::string& in, const std::string& out) {
  OmMesh mesh;
  OpenMesh::IO::Options options;
  if (!OpenMesh::IO::read_mesh(mesh, in, options)) {
    std::fprintf(stderr, "OpenMesh could not read %s\n", in.c_str());
    return 1;
  }
  OpenMesh::IO::Options write_options = OpenMesh::IO::Options::Binary;
  if (!OpenMesh::IO::write_mesh(mesh, out, write_options, 17)) {
    std::fprintf(stderr, "OpenMesh could not write %s\n", out.c_str());
    return 1;
  }
  std::printf("openmesh-readwrite %s -> %s: %zu faces\n", in.c_str(), out.c_str(), mesh.n_faces());
  return 0;
}

int parse(const std::string& path) {
  ReadInfo info;
  const Soup soup = read_soup(path, &info);
  std::printf("parse %s: %zu vertices, %zu faces\n", path.c_str(), soup.num_vertices(),
              soup.num_faces());
  return 0;
}

double seconds_of(const std::function<void()>& step);
std::pair<double, double> min_and_median(std::vector<double>& samples);

int read_twice(const std::string& path, int runs) {
  std::vector<double> plain, attributed;
  std::size_t faces = 0, corners = 0;
  for (int run = 0; run < runs; ++run) {
    plain.push_back(seconds_of([&] {
      ReadInfo info;
      faces = read_soup(path, &info).num_faces();
    }));
    attributed.push_back(seconds_of([&] {
      ReadInfo info;
      MeshAttributes attributes;
      corners = read_soup(path, &info, &attributes).num_corners();
    }));
  }
  const auto [plain_best, plain_median] = min_and_median(plain);
  const auto [attributed_best, attributed_median] = min_and_median(attributed);
  std::printf(
      "read %s (%zu faces, %zu corners): without attributes best %.4f s (median %.4f), "
      "with attributes best %.4f s (median %.4f), %d runs\n",
      path.c_str(), faces, corners, plain_best, plain_median, attributed_best, attributed_median,
      runs);
  return 0;
}

bool is_text(const char* data, std::size_t size, const std::string& path) {
  const std::string ext = path.substr(path.find_last_of('.') + 1);
  if (ext == "obj" || ext == "off")
    return true;
  if (ext == "ply")
    return std::string(data, std::min<std::size_t>(size, 200)).find("format ascii") !=
           std::string::npos;
  return size < 84 || std::memcmp(data, "solid", 5) == 0;  // stl
}

double floor_sum(const std::string& path, std::size_t& numbers);

int floor_pass(const std::string& path) {
  std::size_t numbers = 0;
  const double sum = floor_sum(path, numbers);
  std::printf("floor %s: %zu numbers, sum %g\n", path.c_str(), numbers, sum);
  return 0;
}

double seconds_of(const std::function<void()>& step) {
  const auto start = std::chrono::steady_clock::now();
  step();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//! The smallest and the middle of `samples` (sorted in place).
std::pair<double, double> min_and_median(std::vector<double>& samples) {
  std::sort(samples.begin(), samples.end());
  return {samples.front(), samples[samples.size() / 2]};
}

//! In one process: first the floor and MeshBridge's parse (read_soup) alternating, 3 x `runs`
//! times each (nothing else runs in between, so both meet the same caches and the same machine
//! load), then the split of `repair IN OUT` into read, detect, repair, write, best of `runs`.
int split(const std::string& path, int runs) {
  const std::string ext = path.substr(path.find_last_of('.'));
  const std::string out = "/tmp/meshbridge_io_bench_split" + ext;
  std::vector<double> floor_s, parse_s, one_thread_s;
  std::size_t numbers = 0, faces = 0;
  const char* threads = std::getenv("MESHBRIDGE_THREADS");
  const std::string chosen = threads != nullptr ? threads : "";
  for (int r = 0; r < 3 * runs; ++r) {
    floor_s.push_back(seconds_of([&] { floor_sum(path, numbers); }));
    parse_s.push_back(seconds_of([&] { faces = read_soup(path).num_faces(); }));
    setenv("MESHBRIDGE_THREADS", "1", 1);
    one_thread_s.push_back(seconds_of([&] { read_soup(path); }));
    if (threads != nullptr)
      setenv("MESHBRIDGE_THREADS", chosen.c_str(), 1);
    else
      unsetenv("MESHBRIDGE_THREADS");
  }
  const auto [floor_min, floor_median] = min_and_median(floor_s);
  const auto [parse_min, parse_median] = min_and_median(parse_s);
  const double one_thread_min = min_and_median(one_thread_s).first;
  double repair_s = 1e9, write_s = 1e9, detect_s = 1e9;
  for (int r = 0; r < runs; ++r) {
    const Soup soup = read_soup(path);
    detect_s = std::min(detect_s, seconds_of([&] { detect_defects(soup); }));
    RepairResult result;
    repair_s = std::min(repair_s, seconds_of([&] { result = repair(soup); }));
    write_s = std::min(write_s, seconds_of([&] { write_mesh(out, result.mesh); }));
  }
  std::remove(out.c_str());
  std::printf(
      "split %s (%zu faces): floor %.4f s, parse %.4f s (%.2fx floor; medians of %d: %.4f s, "
      "%.4f s, %.2fx; one thread %.4f s, %.2fx), detect %.4f s, repair %.4f s, write %.4f s "
      "(best of %d)\n",
      path.c_str(), faces, floor_min, parse_min, parse_min / floor_min, 3 * runs, floor_median,
      parse_median, parse_median / floor_median, one_thread_min, one_thread_min / floor_min,
      detect_s, repair_s, write_s, runs);
  return 0;
}

//! See the usage at the top: the best read time per face of 3MF (its meshes read apart by the
//! scan, by pugixml alone, and by lib3mf alone) and of binary STL, side by side; wall and CPU.
int read_3mf(const std::string& dir, int runs, const std::vector<std::string>& given) {
  const std::vector<std::pair<std::string, std::function<Soup()>>> models = {
      {"torus_1m", [] { return models::torus_grid(1176, 448); }},
      {"checkerboard_1m", [] { return models::checkerboard_cubes(56); }}};
  std::vector<std::pair<std::string, std::string>> pairs;  // 3MF, binary STL
  for (const auto& [name, make_soup] : models) {
    const std::string base = dir + "/" + name;
    if (access((base + ".3mf").c_str(), R_OK) != 0 || access((base + ".stl").c_str(), R_OK) != 0) {
      IndexedMesh mesh;
      mesh.soup = make_soup();
      write_mesh(base + ".stl", mesh);
      write_mesh(base + ".3mf", mesh);
    }
    pairs.emplace_back(base + ".3mf", base + ".stl");
  }
  for (const std::string& path : given) {  // a real file, against its own triangles as STL
    const std::size_t slash = path.find_last_of('/');
    const std::string stem = path.substr(slash == std::string::npos ? 0 : slash + 1);
    const std::string stl = dir + "/" + stem.substr(0, stem.find_last_of('.')) + ".stl";
    IndexedMesh mesh;
    mesh.soup = read_soup(path);
    write_mesh(stl, mesh);
    pairs.emplace_back(path, stl);
  }
  // Each read: a file and its MESHBRIDGE_3MF_MESHES route (nullptr: the default).
  const char* routes[] = {nullptr, "whole", "pugixml", "lib3mf", nullptr};
  constexpr std::size_t kReads = 5;  // streamed scan, whole scan, pugixml, lib3mf, STL
  std::vector<std::pair<std::string, const char*>> reads;
  for (const auto& [three_mf, stl] : pairs) {
    for (std::size_t r = 0; r < kReads; ++r)
      reads.emplace_back(r + 1 < kReads ? three_mf : stl, routes[r]);
  }
  std::vector<double> best(reads.size(), 1e30), best_cpu(reads.size(), 1e30);
  std::vector<std::size_t> faces(reads.size(), 0);
  std::vector<std::size_t> order(reads.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::mt19937 random(7);
  const auto cpu_now = [] {
    struct rusage usage {};
    getrusage(RUSAGE_SELF, &usage);
    return double(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           1e-6 * double(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
  };
  for (int r = 0; r < runs; ++r) {
    std::shuffle(order.begin(), order.end(), random);
    for (std::size_t i : order) {
      if (reads[i].second != nullptr)
        setenv("MESHBRIDGE_3MF_MESHES", reads[i].second, 1);
      const double cpu = cpu_now();
      best[i] =
          std::min(best[i], seconds_of([&] { faces[i] = read_soup(reads[i].first).num_faces(); }));
      best_cpu[i] = std::min(best_cpu[i], cpu_now() - cpu);
      unsetenv("MESHBRIDGE_3MF_MESHES");
    }
  }
  const auto us = [&](const std::vector<double>& t, std::size_t i) {
    return t[i] / double(faces[i]) * 1e6;
  };
  for (std::size_t i = 0; i + kReads - 1 < reads.size(); i += kReads) {
    const std::size_t stl = i + kReads - 1;
    std::printf("read-3mf %s (%zu faces), best of %d, shuffled; wall (CPU) per face:\n",
                reads[i].first.c_str(), faces[i], runs);
    const char* names[] = {"3MF stream", "3MF whole", "3MF pugixml", "3MF lib3mf", "binary STL"};
    for (std::size_t r = 0; r < kReads; ++r) {
      std::printf("  %-11s %.4f s (CPU %.4f s): %.3f us/face (CPU %.3f), %.2fx STL (CPU %.2fx)\n",
                  names[r], best[i + r], best_cpu[i + r], us(best, i + r), us(best_cpu, i + r),
                  us(best, i + r) / us(best, stl), us(best_cpu, i + r) / us(best_cpu, stl));
    }
  }
  return 0;
}

double floor_sum(const std::string& path, std::size_t& numbers) {
  const int fd = ::open(path.c_str(), O_RDONLY);
  struct stat status {};
  if (fd < 0 || fstat(fd, &status) != 0 || status.st_size == 0) {
    throw std::runtime_error("cannot open " + path);
  }
  const std::size_t size = static_cast<std::size_t>(status.st_size);
  numbers = 0;
  void* map = mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  ::close(fd);
  if (map == MAP_FAILED)
    throw std::runtime_error("cannot map " + path);
  const char* p = static_cast<const char*>(map);
  const char* end = p + size;
  double sum = 0;
  if (is_text(p, size, path)) {
    while (p < end) {
      const char c = *p;
      if ((c >= '0' && c <= '9') || c == '-' || c == '.') {
        double value = 0;
        const auto result = std::from_chars(p, end, value);
        if (result.ec == std::errc()) {
          sum += value;
          ++numbers;
          p = result.ptr;
          continue;
        }
      }
      ++p;
    }
  } else {
    for (std::size_t i = 0; i + 4 <= size; i += 4) {
      float value;
      std::memcpy(&value, p + i, 4);
      sum += std::isfinite(value) ? value : 0;
      ++numbers;
    }
  }
  munmap(map, size);
  return sum;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string command = argc > 1 ? argv[1] : "";
  try {
    if (command == "make" && argc == 3)
      return make(argv[2]);
    if (command == "make-soup" && argc == 3)
      return make_soup(argv[2]);
    if (command == "openmesh-read" && argc == 3)
      return openmesh_read(argv[2]);
    if (command == "openmesh-readwrite" && argc == 4)
      return openmesh_readwrite(argv[2], argv[3]);
    if (command == "parse" && argc == 3)
      return parse(argv[2]);
    if (command == "read" && (argc == 3 || argc == 4))
      return read_twice(argv[2], std::max(1, argc == 4 ? std::atoi(argv[3]) : 5));
    if (command == "floor" && argc == 3)
      return floor_pass(argv[2]);
    if (command == "read-3mf" && argc >= 3) {
      return read_3mf(argv[2], std::max(1, argc >= 4 ? std::atoi(argv[3]) : 5),
                      std::vector<std::string>(argv + std::min(argc, 4), argv + argc));
    }
    if (command == "split" && (argc == 3 || argc == 4))
      return split(argv[2], std::max(1, argc == 4 ? std::atoi(argv[3]) : 5));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "meshbridge-io-bench %s: %s\n", command.c_str(), e.what());
    return 1;
  }
  std::fprintf(stderr,
               "usage: meshbridge-io-bench make DIR | make-soup DIR | openmesh-read FILE | "
               "openmesh-readwrite IN OUT | parse FILE | read FILE [RUNS] | floor FILE | split "
               "FILE [RUNS] | "
               "read-3mf DIR [RUNS] [FILE.3mf...]\n");
  return 2;
}
