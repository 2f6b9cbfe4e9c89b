// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/stl_round_trip.h"

#include "geometry/triangulate.h"

#include "meshbridge/close_gaps.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/separate_copies.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace meshbridge {

namespace {

struct FloatPointHash {
  std::size_t operator()(const std::array<float, 3>& p) const {
    std::size_t h = 0;
    for (float x : p)
      h = h * 0x9e3779b97f4a7c15ULL + std::hash<float>()(x);
    return h;
  }
};

}  // namespace

Soup stl_round_trip(const Soup& soup) {
  Soup out;
  std::unordered_map<std::array<float, 3>, Index, FloatPointHash> index;
  index.reserve(soup.num_vertices());
  const auto weld = [&](Index v) {
    const Point& p = soup.positions[v];
    const std::array<float, 3> key{static_cast<float>(p[0]), static_cast<float>(p[1]),
                                   static_cast<float>(p[2])};
    const auto [it, inserted] = index.try_emplace(key, static_cast<Index>(out.num_vertices()));
    if (inserted)
      out.add_vertex(Point(key[0], key[1], key[2]));
    return it->second;
  };
  detail::Triangulation t;  // as the STL writer cuts polygons
  detail::avoid_existing_edges(soup, t);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    detail::triangulate_polygon(soup, f, t);
    for (const auto& [a, b, c] : t.triangles)
      out.add_polygon({weld(a), weld(b), weld(c)});
  }
  return out;
}

std::size_t singular_elements_after_stl_round_trip(const Soup& soup) {
  const DefectReport report = detect_defects(stl_round_trip(soup));
  return report.singular_edges.size() + report.num_singular_vertices();
}

namespace {

//! The first u * 2^k (see smallest_stl_separation()) after which `survives(moved soup)` holds; 0
//! when `mesh` has no split vertex.
template <class Survives>
double smallest_separation(const IndexedMesh& mesh, const char* caller, Survives survives,
                           double at_least = 0) {
  if (mesh.vertex_origin.size() != mesh.soup.num_vertices()) {
    throw std::invalid_argument(std::string(caller) + ": vertex_origin has " +
                                std::to_string(mesh.vertex_origin.size()) + " entries for " +
                                std::to_string(mesh.soup.num_vertices()) + " vertices");
  }
  std::map<Index, Index> copies;
  for (Index o : mesh.vertex_origin) {
    if (o != kNoIndex)  // a vertex repair added (a midpoint) is no copy
      ++copies[o];
  }
  bool any = false;
  for (std::size_t v = 0; v < mesh.soup.num_vertices() && !any; ++v)
    any = mesh.vertex_origin[v] != kNoIndex && copies[mesh.vertex_origin[v]] >= 2;
  if (!any)
    return 0;
  // The model's scale, not the copies' own coordinates: copies at the origin would otherwise be
  // moved by a float32 denormal (1.4e-45), which any tool that welds with a tolerance undoes.
  double largest = 0;
  for (const Point& p : mesh.soup.positions)
    for (int a = 0; a < 3; ++a)
      largest = std::max(largest, std::abs(p[a]));
  const float at = static_cast<float>(largest);
  const double ulp = static_cast<double>(std::nextafter(at, 2 * at + 1.0f)) - at;
  // Steps below `at_least` cannot survive: they are not tried (each costs a round trip).
  int first = 0;
  while (first < 60 && std::ldexp(ulp, first + 1) <= at_least)
    ++first;
  for (int k = first; k <= 60; ++k) {
    const double distance = std::ldexp(ulp, k);
    IndexedMesh moved = mesh;
    separate_split_vertices(moved, distance);
    if (survives(moved.soup))
      return distance;
  }
  throw std::invalid_argument(
      "no separation distance makes this mesh survive STL: float32 coordinates merge vertices "
      "that are not copies of one split vertex; write OBJ, OFF, PLY or 3MF instead");
}

}  // namespace

double smallest_stl_separation(const IndexedMesh& mesh) {
  return smallest_separation(mesh, "smallest_stl_separation", [](const Soup& moved) {
    return singular_elements_after_stl_round_trip(moved) == 0;
  });
}

double stl_separation_surviving_weld(const IndexedMesh& mesh, const CloseGapsOptions& weld) {
  // Copies of one split vertex, as lists of vertices (groups of 2 or more).
  std::map<Index, std::vector<Index>> groups;
  for (std::size_t v = 0; v < mesh.vertex_origin.size(); ++v)
    if (mesh.vertex_origin[v] != kNoIndex)
      groups[mesh.vertex_origin[v]].push_back(static_cast<Index>(v));
  const auto as_float = [](const Point& p) {
    return Point(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
  };
  // Two copies move apart by at most twice the distance (plus float rounding): distances below
  // a quarter of the tolerance cannot keep them beyond it, and are not tried.
  const double tolerance_before =
      weld.tolerance < 0 ? default_weld_tolerance(mesh.soup, true) : weld.tolerance;
  return smallest_separation(
      mesh, "stl_separation_surviving_weld",
      [&](const Soup& moved) {
        // Gap closing welds vertices closer than its tolerance: no two copies may be that close
        // once rounded to the floats of the file. (Checked first: it is the cheap test.)
        const double tolerance = weld.tolerance < 0 ? default_weld_tolerance(moved, true)
                                                    : weld.tolerance;  // STL: floats
        for (const auto& [origin, copies] : groups) {
          for (std::size_t i = 0; i < copies.size(); ++i) {
            for (std::size_t j = i + 1; j < copies.size(); ++j) {
              const Point d =
                  as_float(moved.positions[copies[i]]) - as_float(moved.positions[copies[j]]);
              if (d.norm() <= tolerance)
                return false;
            }
          }
        }
        return singular_elements_after_stl_round_trip(moved) == 0;
      },
      tolerance_before / 4);
}

StlSeparation separate_copies_for_stl(IndexedMesh& mesh) {
  StlSeparation done;
  try {
    done.distance = stl_separation_surviving_weld(mesh);
  } catch (const std::invalid_argument& failure) {
    if (mesh.vertex_origin.size() != mesh.soup.num_vertices())
      throw;  // a broken precondition, not a mesh that float32 cannot separate
    done.kept_reason = failure.what();
    return done;
  }
  if (done.distance > 0) {
    const std::vector<Point> before = mesh.soup.positions;
    done.vertices_moved = separate_split_vertices(mesh, done.distance);
    // The moved copies land on the float32 positions the file will hold (the distance was
    // chosen for exactly those), so writing them rounds nothing more than the input had.
    for (std::size_t v = 0; v < before.size(); ++v) {
      Point& p = mesh.soup.positions[v];
      if (p[0] != before[v][0] || p[1] != before[v][1] || p[2] != before[v][2]) {
        for (int a = 0; a < 3; ++a) {
          // Through a volatile float: GCC 12 at -O3 with -frounding-math folded this rounding
          // away for two of the three coordinates.
          volatile float rounded = static_cast<float>(p[a]);
          p[a] = rounded;
        }
      }
    }
  }
  if (done.vertices_moved == 0)
    done.distance = 0;
  return done;
}

}  // namespace meshbridge
