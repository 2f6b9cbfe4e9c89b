// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/repair_to_openmesh.h"

#include "meshbridge/validate.h"

#include "openmesh_streams.h"
#include "union_find.h"
#include "working_soup.h"

#include <cmath>
#include <new>
#include <vector>

namespace meshbridge {

namespace {

// Builds `soup` into `mesh` as it is; false at the first polygon OpenMesh refuses or that repeats
// a vertex, or if the result has a non-manifold vertex or an inward closed component.
bool build_if_already_manifold(const Soup& soup, PolyMesh& mesh) {
  mesh.reserve(soup.num_vertices(), soup.num_corners() / 2 + soup.num_vertices(), soup.num_faces());
  for (const Point& p : soup.positions)
    mesh.add_vertex(p);
  std::vector<OpenMesh::VertexHandle> handles;
  {
    detail::MutedOpenMeshErrors muted;
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      const PolygonView polygon = soup.polygon(f);
      if (detail::has_repeated_vertex(polygon))
        return false;
      handles.clear();
      for (Index v : polygon)
        handles.emplace_back(static_cast<int>(v));
      if (!mesh.add_face(handles).is_valid())
        return false;
    }
  }
  for (auto v : mesh.vertices()) {
    if (!mesh.is_manifold(v))
      return false;
  }
  // Closed components must not have negative volume (beyond rounding, as repair judges it).
  detail::UnionFind components(mesh.n_faces());
  std::vector<char> open(mesh.n_faces(), 0);
  for (auto e : mesh.edges()) {
    const auto h0 = mesh.halfedge_handle(e, 0);
    const auto h1 = mesh.halfedge_handle(e, 1);
    const auto f0 = mesh.face_handle(h0);
    const auto f1 = mesh.face_handle(h1);
    if (f0.is_valid() && f1.is_valid()) {
      components.unite(static_cast<Index>(f0.idx()), static_cast<Index>(f1.idx()));
    } else {
      open[(f0.is_valid() ? f0 : f1).idx()] = 1;
    }
  }
  std::vector<double> volume(mesh.n_faces(), 0.0), magnitude(mesh.n_faces(), 0.0);
  std::vector<char> component_open(mesh.n_faces(), 0);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const Index r = components.find(static_cast<Index>(f));
    component_open[r] |= open[f];
    const PolygonView p = soup.polygon(f);
    const Point& p0 = soup.positions[p[0]];
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      const double term =
          OpenMesh::dot(p0, OpenMesh::cross(soup.positions[p[i]], soup.positions[p[i + 1]]));
      volume[r] += term;
      magnitude[r] += std::abs(term);
    }
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (components.find(static_cast<Index>(f)) == f && !component_open[f] &&
        volume[f] < -1e-9 * magnitude[f])
      return false;
  }
  return true;
}

}  // namespace

OpenMeshRepair repair_to_openmesh(const Soup& soup, const RepairOptions& options) {
  validate_soup(soup);
  OpenMeshRepair result;
  const bool plain = !options.detect_before_after && !options.remove_duplicate_faces &&
                     !options.remove_degenerate_faces && !options.remove_isolated_vertices &&
                     options.orient;
  if (plain && build_if_already_manifold(soup, result.mesh)) {
    result.fast_path = true;
    OpenMesh::VPropHandleT<Index> vertex_origin;
    OpenMesh::FPropHandleT<Index> face_origin;
    result.mesh.add_property(vertex_origin, kVertexOriginProperty);
    result.mesh.add_property(face_origin, kFaceOriginProperty);
    for (auto v : result.mesh.vertices())
      result.mesh.property(vertex_origin, v) = static_cast<Index>(v.idx());
    for (auto f : result.mesh.faces())
      result.mesh.property(face_origin, f) = static_cast<Index>(f.idx());
    RepairReport& report = result.report;
    report.faces_in = report.faces_out = soup.num_faces();
    report.vertices_in = report.vertices_out = soup.num_vertices();
    return result;
  }
  // Free the abandoned attempt: OpenMesh's clear() keeps every buffer, and its meshes have no
  // move assignment, so destroy and rebuild the member in place.
  result.mesh.~PolyMesh();
  new (&result.mesh) PolyMesh();
  RepairResult repaired = repair(soup, options);
  result.add_face_failures = fill_openmesh(repaired.mesh, result.mesh);
  result.report = std::move(repaired.report);
  return result;
}

}  // namespace meshbridge
