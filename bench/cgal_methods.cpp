// SPDX-License-Identifier: GPL-3.0-or-later
#include "cgal_methods.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace meshbridge::bench {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point3>;
namespace PMP = CGAL::Polygon_mesh_processing;

Soup to_soup(const SurfaceMesh& mesh) {
  Soup soup;
  soup.reserve(mesh.number_of_vertices(), mesh.number_of_faces(), 3 * mesh.number_of_faces());
  std::vector<Index> index(mesh.num_vertices(), kNoIndex);
  for (auto v : mesh.vertices()) {
    const Point3& p = mesh.point(v);
    index[v.idx()] = soup.add_vertex(Point(p.x(), p.y(), p.z()));
  }
  std::vector<Index> polygon;
  for (auto f : mesh.faces()) {
    polygon.clear();
    for (auto v : CGAL::vertices_around_face(mesh.halfedge(f), mesh))
      polygon.push_back(index[v.idx()]);
    soup.add_polygon(polygon);
  }
  return soup;
}

//! The pipeline on polygons of type `Polygon` (std::array<std::size_t, 3> for triangle soups,
//! as CGAL recommends; std::vector<std::size_t> otherwise, as CGAL's soup readers return).
template <class Polygon>
void run_pipeline(const Soup& soup, Clock& clock, Outcome& outcome) {
  std::vector<Point3> points;
  points.reserve(soup.num_vertices());
  for (const Point& p : soup.positions)
    points.emplace_back(p[0], p[1], p[2]);
  std::vector<Polygon> polygons(soup.num_faces());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto poly = soup.polygon(f);
    Polygon& out = polygons[f];
    if constexpr (std::is_same_v<Polygon, std::vector<std::size_t>>)
      out.assign(poly.begin(), poly.end());
    else
      std::copy(poly.begin(), poly.end(), out.begin());
  }
  const double t_copy = clock.lap();
  const std::size_t polygons_in = polygons.size(), points_in = points.size();
  PMP::repair_polygon_soup(points, polygons);
  const double t_repair = clock.lap();
  const std::size_t polygons_repaired = polygons.size(), points_repaired = points.size();
  const bool oriented_without_duplication = PMP::orient_polygon_soup(points, polygons);
  const double t_orient = clock.lap();
  const std::size_t points_oriented = points.size();
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);
  const double t_mesh = clock.lap();
  const std::size_t duplicated = PMP::duplicate_non_manifold_vertices(mesh);
  clock.stop();
  add_note(outcome,
           "copy %.2f s, repair_polygon_soup %.2f s (%zu polygons, %zu points removed), "
           "orient_polygon_soup %.2f s (%zu points duplicated%s), to Surface_mesh %.2f s, "
           "duplicate_non_manifold_vertices %.2f s (%zu added)",
           t_copy, t_repair, polygons_in - polygons_repaired, points_in - points_repaired, t_orient,
           points_oriented - points_repaired,
           oriented_without_duplication ? "" : ", returned false", t_mesh, clock.lap(), duplicated);
  if (wants_evaluation(outcome))
    evaluate(to_soup(mesh), outcome);
}

}  // namespace

void cgal_soup_pipeline(const Soup& soup, Clock& clock, Outcome& outcome) {
  bool triangles = true;
  for (std::size_t f = 0; f < soup.num_faces() && triangles; ++f)
    triangles = soup.arity(f) == 3;
  if (triangles)
    run_pipeline<std::array<std::size_t, 3>>(soup, clock, outcome);
  else
    run_pipeline<std::vector<std::size_t>>(soup, clock, outcome);
}

}  // namespace meshbridge::bench
