// SPDX-License-Identifier: GPL-3.0-or-later
// Hole filling through CGAL PMP's triangulate_hole, on a CGAL::Surface_mesh built from the mesh.
// The only file of the core that includes CGAL (it is private to the core: no public header
// names it).
#include "meshbridge/fill_holes.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/validate.h"

#ifdef MESHBRIDGE_WITH_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/version.h>
#endif

#include <algorithm>
#include <cmath>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshbridge {

namespace {

std::string edge_name(const VertexPair& e) {
  return "(" + std::to_string(e.v0) + ", " + std::to_string(e.v1) + ")";
}

// The preconditions of fill_holes() that the halfedge mesh needs, checked by the project's own
// detection so that the message names the element.
void check_fillable(const IndexedMesh& mesh) {
  const Soup& soup = mesh.soup;
  validate_soup(soup);
  const std::size_t v = mesh.vertex_origin.size(), f = mesh.face_origin.size(),
                    c = mesh.corner_origin.size();
  const bool identity = v == 0 && f == 0 && c == 0;
  if (!identity && (v != soup.num_vertices() || f != soup.num_faces() || c != soup.num_corners())) {
    throw std::invalid_argument("fill_holes: the origin arrays have " + std::to_string(v) + ", " +
                                std::to_string(f) + " and " + std::to_string(c) +
                                " entries but the mesh has " + std::to_string(soup.num_vertices()) +
                                " vertices, " + std::to_string(soup.num_faces()) + " faces and " +
                                std::to_string(soup.num_corners()) + " corners");
  }
  const DefectReport defects = detect_defects(soup);
  const char* const repair_first = " (repair the mesh first)";
  if (!defects.degenerate_faces.empty()) {
    throw std::invalid_argument("fill_holes: face " + std::to_string(defects.degenerate_faces[0]) +
                                " repeats a vertex" + repair_first);
  }
  if (defects.keyhole_polygons_triangulated > 0)
    throw std::invalid_argument(std::string("fill_holes: a keyhole polygon repeats a vertex") +
                                repair_first);
  if (!defects.singular_edges.empty()) {
    throw std::invalid_argument(
        "fill_holes: edge " + edge_name(defects.singular_edges[0].vertices) + " has " +
        std::to_string(defects.singular_edges[0].contenders) + " sides" + repair_first);
  }
  if (!defects.pinch_vertices.empty()) {
    throw std::invalid_argument("fill_holes: vertex " + std::to_string(defects.pinch_vertices[0]) +
                                " is singular (its faces form more than one fan)" + repair_first);
  }
  if (!defects.inconsistent_edges.empty()) {
    throw std::invalid_argument("fill_holes: the two sides of edge " +
                                edge_name(defects.inconsistent_edges[0]) + " run the same way" +
                                repair_first);
  }
}

#ifdef MESHBRIDGE_WITH_CGAL

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using HalfedgeMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Face = HalfedgeMesh::Face_index;
using Halfedge = HalfedgeMesh::Halfedge_index;

// The halfedge mesh of `soup`: vertex v and face f keep their numbers.
HalfedgeMesh halfedge_mesh(const Soup& soup) {
  HalfedgeMesh out;
  out.reserve(static_cast<HalfedgeMesh::size_type>(soup.num_vertices()),
              static_cast<HalfedgeMesh::size_type>(soup.num_corners()),
              static_cast<HalfedgeMesh::size_type>(soup.num_faces()));
  for (const Point& p : soup.positions)
    out.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
  std::vector<HalfedgeMesh::Vertex_index> corners;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    corners.clear();
    for (Index v : soup.polygon(f))
      corners.emplace_back(v);
    // check_fillable() ruled out every reason for a refusal; one is a bug, not bad input.
    if (out.add_face(corners) == HalfedgeMesh::null_face())
      throw std::logic_error("fill_holes: the halfedge mesh refused face " + std::to_string(f));
  }
  return out;
}

// One border halfedge per boundary loop with its number of edges, in the order of the loops'
// lowest-numbered border halfedge.
struct Loop {
  Halfedge border;
  std::size_t edges = 0;
};

std::vector<Loop> boundary_loops(const HalfedgeMesh& mesh) {
  std::vector<Loop> loops;
  std::vector<char> seen(mesh.number_of_halfedges(), 0);
  for (Halfedge h : mesh.halfedges()) {
    if (seen[h.idx()] || !mesh.is_border(h))
      continue;
    Loop loop{h, 0};
    Halfedge walk = h;
    do {
      seen[walk.idx()] = 1;
      ++loop.edges;
      walk = mesh.next(walk);
    } while (walk != h);
    loops.push_back(loop);
  }
  return loops;
}

// Holes of at most this many edges are triangulated by CGAL's cubic search over all
// triangulations (Liepa 2003; about 10 ms at 100 edges, 1 s at 500), which depends on nothing
// but the hole. Longer ones restrict the
// search to the faces of a 3D Delaunay triangulation of the rim (CGAL's default, much faster
// there), whose result can depend on the order of memory CGAL allocated before (handles are
// compared by address): the same input repaired twice in one process could then differ.
constexpr std::size_t kExhaustiveSearchMaxEdges = 100;

// triangulate_hole: CGAL >= 5.6 takes the output as a named parameter (the positional form is
// deprecated there); bookworm's 5.5 has only the positional one.
std::vector<Face> triangulate(HalfedgeMesh& mesh, Halfedge border, std::size_t edges) {
  std::vector<Face> patch;
  namespace PMP = CGAL::Polygon_mesh_processing;
  const bool delaunay = edges > kExhaustiveSearchMaxEdges;
#if CGAL_VERSION_NR >= CGAL_VERSION_NUMBER(5, 6, 0)
  PMP::triangulate_hole(mesh, border,
                        CGAL::parameters::face_output_iterator(std::back_inserter(patch))
                            .use_delaunay_triangulation(delaunay));
#else
  PMP::triangulate_hole(mesh, border, std::back_inserter(patch),
                        CGAL::parameters::use_delaunay_triangulation(delaunay));
#endif
  return patch;
}

Kernel::Vector_3 face_normal(const HalfedgeMesh& mesh, Face f) {
  const Halfedge h = mesh.halfedge(f);
  const Kernel::Point_3& a = mesh.point(mesh.source(h));
  const Kernel::Point_3& b = mesh.point(mesh.target(h));
  const Kernel::Point_3& c = mesh.point(mesh.target(mesh.next(h)));
  return CGAL::cross_product(b - a, c - a);
}

// Why a patch CGAL made for a loop must not stay ("" when it may): a triangle of no area, a
// triangle with the corners of the face across one of its edges (the back of a sheet: the
// outline of one triangle filled), or a triangle that folds back onto the face across its edge,
// lying on it (dihedral angle under kFoldDegrees: the outline of a flat sheet filled, a second
// layer behind it).
std::string refused_patch(const HalfedgeMesh& mesh, const std::vector<Face>& patch) {
  constexpr double kFoldDegrees = 1.0;
  const double fold_cos = std::cos(kFoldDegrees * 3.14159265358979323846 / 180.0);
  std::set<std::size_t> in_patch;
  for (Face f : patch)
    in_patch.insert(f.idx());
  for (Face f : patch) {
    const Kernel::Vector_3 n = face_normal(mesh, f);
    double longest = 0;
    for (Halfedge h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      longest = std::max(
          longest, CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h))));
    if (!(std::sqrt(n.squared_length()) > 1e-12 * longest))
      return "a triangle of no area";
    for (Halfedge h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
      const Halfedge across = mesh.opposite(h);
      const Face g = mesh.face(across);
      if (g == HalfedgeMesh::null_face() || in_patch.count(g.idx()) > 0)
        continue;
      const auto apex = mesh.target(mesh.next(h));        // the patch triangle's third corner
      const auto other = mesh.target(mesh.next(across));  // the face's next corner after h
      if (mesh.degree(g) == 3 && apex == other)
        return "a triangle over an existing face (the back of a sheet)";
      // The dihedral angle at h: the directions from the edge to the two third corners.
      const Kernel::Point_3& u = mesh.point(mesh.source(h));
      const Kernel::Vector_3 e = mesh.point(mesh.target(h)) - u;
      const auto across_edge = [&](const Kernel::Point_3& q) {
        const Kernel::Vector_3 d = q - u;
        return d - e * ((d * e) / e.squared_length());
      };
      const Kernel::Vector_3 dp = across_edge(mesh.point(apex));
      const Kernel::Vector_3 dq = across_edge(mesh.point(other));
      const double lengths = std::sqrt(dp.squared_length() * dq.squared_length());
      if (lengths > 0 && (dp * dq) > fold_cos * lengths)
        return "a triangle folded back onto the surface (the outline of an open sheet)";
    }
  }
  return "";
}

#endif  // MESHBRIDGE_WITH_CGAL

}  // namespace

bool has_hole_filling() {
#ifdef MESHBRIDGE_WITH_CGAL
  return true;
#else
  return false;
#endif
}

FillHolesReport fill_holes(IndexedMesh& mesh, const FillHolesOptions& options) {
  FillHolesReport report;
  report.max_edges = options.max_edges;
  if (options.max_edges == 0)
    return report;
  check_fillable(mesh);
#ifndef MESHBRIDGE_WITH_CGAL
  throw std::runtime_error(
      "fill_holes: this build of MeshBridge has no hole filling (it was built without CGAL, "
      "Debian libcgal-dev)");
#else
  Soup& soup = mesh.soup;
  if (mesh.face_origin.empty() && soup.num_faces() > 0) {  // identity: write it out
    for (std::size_t v = 0; v < soup.num_vertices(); ++v)
      mesh.vertex_origin.push_back(static_cast<Index>(v));
    for (std::size_t f = 0; f < soup.num_faces(); ++f)
      mesh.face_origin.push_back(static_cast<Index>(f));
    for (std::size_t c = 0; c < soup.num_corners(); ++c)
      mesh.corner_origin.push_back(static_cast<Index>(c));
  }
  HalfedgeMesh halfedges = halfedge_mesh(soup);
  for (const Loop& loop : boundary_loops(halfedges)) {
    if (loop.edges > options.max_edges) {
      ++report.holes_left;
      continue;
    }
    const std::vector<Face> patch = triangulate(halfedges, loop.border, loop.edges);
    if (patch.empty()) {  // CGAL found no patch; it left the mesh as it was
      ++report.holes_left;
      continue;
    }
    if (!refused_patch(halfedges, patch).empty()) {  // taken out again: the loop stays open
      for (Face f : patch)
        CGAL::Euler::remove_face(halfedges.halfedge(f), halfedges);
      ++report.holes_left;
      ++report.patches_refused;
      continue;
    }
    ++report.holes_filled;
    for (Face f : patch) {
      const Halfedge first = halfedges.halfedge(f);
      Halfedge h = first;
      do {
        soup.corner_vertices.push_back(static_cast<Index>(halfedges.target(h).idx()));
        mesh.corner_origin.push_back(kNoIndex);
        h = halfedges.next(h);
      } while (h != first);
      soup.face_begin.push_back(static_cast<Index>(soup.corner_vertices.size()));
      mesh.face_origin.push_back(kNoIndex);
      ++report.faces_added;
    }
  }
  return report;
#endif
}

}  // namespace meshbridge
