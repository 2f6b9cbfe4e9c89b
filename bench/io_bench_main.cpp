// SPDX-License-Identifier: GPL-3.0-or-later
// meshbridge-io-bench: the single steps of the whole-process benchmark (scripts/bench.sh --io),
// each one process, so that a script times them side by side with /usr/bin/time:
//
//   make DIR                    writes the benchmark files: checkerboard 1M and 5M, clean torus
//                               1M, each as .obj .off .ply (binary) .stl (binary)
//   openmesh-read FILE          OpenMesh's stock read_mesh into a PolyMesh
//   openmesh-readwrite IN OUT   OpenMesh's read_mesh + write_mesh (binary PLY and STL)
//   parse FILE                  MeshBridge's read_soup (parse, validate, account)
//   floor FILE                  the floor: mmap + one pass over the bytes (text: every number
//                               through std::from_chars; binary: every 4-byte word summed)
//   split FILE [RUNS]           in one process, best of RUNS (5): floor, parse, detect, repair,
//                               write, so the parse/compute/write split and parse/floor ratio
//                               are measured side by side
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
#include <stdexcept>
#include <string>

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

//! In one process, alternating, best of `runs`: the floor, MeshBridge's parse (read_soup), and
//! the split of `repair IN OUT` into read, repair, write.
int split(const std::string& path, int runs) {
  const std::string ext = path.substr(path.find_last_of('.'));
  const std::string out = "/tmp/meshbridge_io_bench_split" + ext;
  double floor_s = 1e9, read_s = 1e9, repair_s = 1e9, write_s = 1e9, detect_s = 1e9;
  std::size_t numbers = 0, faces = 0;
  for (int r = 0; r < runs; ++r) {
    floor_s = std::min(floor_s, seconds_of([&] { floor_sum(path, numbers); }));
    Soup soup;
    read_s = std::min(read_s, seconds_of([&] { soup = read_soup(path); }));
    faces = soup.num_faces();
    detect_s = std::min(detect_s, seconds_of([&] { detect_defects(soup); }));
    RepairResult result;
    repair_s = std::min(repair_s, seconds_of([&] { result = repair(soup); }));
    write_s = std::min(write_s, seconds_of([&] { write_mesh(out, result.mesh); }));
  }
  std::remove(out.c_str());
  std::printf(
      "split %s (%zu faces, best of %d): floor %.4f s, parse %.4f s (%.2fx floor), "
      "detect %.4f s, repair %.4f s, write %.4f s\n",
      path.c_str(), faces, runs, floor_s, read_s, read_s / floor_s, detect_s, repair_s, write_s);
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
    if (command == "openmesh-read" && argc == 3)
      return openmesh_read(argv[2]);
    if (command == "openmesh-readwrite" && argc == 4)
      return openmesh_readwrite(argv[2], argv[3]);
    if (command == "parse" && argc == 3)
      return parse(argv[2]);
    if (command == "floor" && argc == 3)
      return floor_pass(argv[2]);
    if (command == "split" && (argc == 3 || argc == 4))
      return split(argv[2], argc == 4 ? std::atoi(argv[3]) : 5);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "meshbridge-io-bench %s: %s\n", command.c_str(), e.what());
    return 1;
  }
  std::fprintf(stderr,
               "usage: meshbridge-io-bench make DIR | openmesh-read FILE | "
               "openmesh-readwrite IN OUT | parse FILE | floor FILE | split FILE [RUNS]\n");
  return 2;
}
