// SPDX-License-Identifier: GPL-3.0-or-later
// meshbridge-self-intersections-bench: the steps of the self-intersection benchmark
// (bench/self_intersections.sh), each one process, so that the script times whole processes:
//
//   make FACES SEED OUT.off      a clean closed torus of about FACES triangles (as the
//                                comparison benchmark's torus), faces shuffled and start corners
//                                rotated with SEED, written as OFF
//   make-crossing FACES OUT.off  two such tori, the second moved so that they cross
//   cgal FILE                    CGAL's way: read the OFF into a Surface_mesh (Epick) with
//                                CGAL::IO::read_polygon_mesh, then PMP::does_self_intersect
//   cgal-count FILE              the same read, then PMP::self_intersections: the face pairs
//   ours-count FILE              MeshBridge's read_soup and find_self_intersections: the pairs
//
// Every command prints one line with what it found and its times, so a wrong run is visible.
#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/self_intersections.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <iterator>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace meshbridge;
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

//! A clean torus of about `faces` triangles: n * m = faces / 2 with n about 4 m.
Soup torus_like(std::size_t faces) {
  const long nm = static_cast<long>(faces / 2);
  const long target = std::max(3L, std::lround(std::sqrt(nm / 4.0)));
  for (long m = target; m >= std::max(3L, target / 2); --m) {
    if (nm % m == 0)
      return models::torus_grid(static_cast<int>(nm / m), static_cast<int>(m));
  }
  return models::torus_grid(static_cast<int>(nm / target), static_cast<int>(target));
}

//! `soup` with its faces shuffled and each start corner rotated (seeded).
Soup shuffled(const Soup& soup, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<Index> order(soup.num_faces());
  std::iota(order.begin(), order.end(), Index(0));
  std::shuffle(order.begin(), order.end(), random);
  Soup out;
  out.positions = soup.positions;
  std::vector<Index> polygon;
  for (Index f : order) {
    const PolygonView p = soup.polygon(f);
    const std::size_t shift = random() % p.size();
    polygon.clear();
    for (std::size_t i = 0; i < p.size(); ++i)
      polygon.push_back(p[(i + shift) % p.size()]);
    out.add_polygon(polygon);
  }
  return out;
}

void write_off(const std::string& path, Soup soup) {
  IndexedMesh mesh;
  mesh.vertex_origin.resize(soup.num_vertices());
  std::iota(mesh.vertex_origin.begin(), mesh.vertex_origin.end(), Index(0));
  mesh.face_origin.resize(soup.num_faces());
  std::iota(mesh.face_origin.begin(), mesh.face_origin.end(), Index(0));
  mesh.corner_origin.resize(soup.num_corners());
  std::iota(mesh.corner_origin.begin(), mesh.corner_origin.end(), Index(0));
  mesh.soup = std::move(soup);
  write_mesh(path, mesh);
  std::cout << "wrote " << path << ": " << mesh.soup.num_vertices() << " vertices, "
            << mesh.soup.num_faces() << " faces\n";
}

CgalMesh read_cgal(const std::string& path, double& seconds) {
  const auto start = Clock::now();
  CgalMesh mesh;
  if (!CGAL::IO::read_polygon_mesh(path, mesh))
    throw std::runtime_error("CGAL could not read " + path);
  seconds = since(start);
  return mesh;
}

int run(const std::vector<std::string>& args) {
  if (args.size() == 4 && args[0] == "make") {
    write_off(args[3], shuffled(torus_like(std::stoul(args[1])), std::stoul(args[2])));
    return 0;
  }
  if (args.size() == 3 && args[0] == "make-crossing") {
    Soup soup = torus_like(std::stoul(args[1]) / 2);
    const Soup second = soup;
    const Index base = static_cast<Index>(soup.num_vertices());
    for (const Point& p : second.positions)
      soup.add_vertex(p + Point(0.13, 0.07, 0.05));
    std::vector<Index> polygon;
    for (std::size_t f = 0; f < second.num_faces(); ++f) {
      polygon.clear();
      for (Index v : second.polygon(f))
        polygon.push_back(v + base);
      soup.add_polygon(polygon);
    }
    write_off(args[2], shuffled(soup, 1));
    return 0;
  }
  if (args.size() == 2 && (args[0] == "cgal" || args[0] == "cgal-count")) {
    double read = 0;
    const CgalMesh mesh = read_cgal(args[1], read);
    const auto start = Clock::now();
    namespace PMP = CGAL::Polygon_mesh_processing;
    if (args[0] == "cgal") {
      const bool found = PMP::does_self_intersect(mesh);
      std::cout << "CGAL does_self_intersect: " << (found ? "yes" : "no") << "; "
                << mesh.num_faces() << " faces; read " << read << " s, test " << since(start)
                << " s\n";
    } else {
      std::vector<std::pair<CgalMesh::Face_index, CgalMesh::Face_index>> pairs;
      PMP::self_intersections(mesh, std::back_inserter(pairs));
      std::cout << "CGAL self_intersections: " << pairs.size() << " face pairs; read " << read
                << " s, test " << since(start) << " s\n";
    }
    return 0;
  }
  if (args.size() == 2 && args[0] == "ours-count") {
    auto start = Clock::now();
    const Soup soup = read_soup(args[1]);
    const double read = since(start);
    start = Clock::now();
    const SelfIntersectionReport report = find_self_intersections(soup);
    std::cout << "MeshBridge find_self_intersections: " << report.face_pairs.size()
              << " face pairs, " << report.faces.size() << " faces, "
              << report.component_pairs.size() << " component pairs; read " << read << " s, test "
              << since(start) << " s\n";
    return 0;
  }
  std::cerr << "usage: meshbridge-self-intersections-bench make FACES SEED OUT.off | "
               "make-crossing FACES OUT.off | cgal FILE | cgal-count FILE | ours-count FILE\n";
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& error) {
    std::cerr << "meshbridge-self-intersections-bench: " << error.what() << "\n";
    return 2;
  }
}
