// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/repair_to_openmesh.h"

#include "meshbridge/validate.h"

#include "geometry/signed_volume.h"
#include "openmesh_streams.h"
#include "union_find.h"
#include "working_soup.h"

#include <algorithm>
#include <cmath>
#include <new>
#include <vector>

namespace meshbridge {

namespace {

// True if no two components' bounding boxes meet, so that no closed component can lie inside
// another (a cavity, which repair turns inward). A sweep along x; false also when the sweep would
// compare more than 16 pairs per component (boxes strung along x), which only costs the fast path.
bool boxes_apart(const Soup& soup, const std::vector<Index>& component, std::size_t count) {
  if (count < 2)
    return true;
  struct Box {
    Point lo, hi;
  };
  std::vector<Box> boxes(count, Box{Point(HUGE_VAL), Point(-HUGE_VAL)});
  for (Index v : soup.corner_vertices) {  // vertices no face uses stay out of every box
    Box& b = boxes[component[v]];
    b.lo.minimize(soup.positions[v]);
    b.hi.maximize(soup.positions[v]);
  }
  std::vector<Index> order(count);
  for (std::size_t c = 0; c < count; ++c)
    order[c] = static_cast<Index>(c);
  std::sort(order.begin(), order.end(),
            [&](Index a, Index b) { return boxes[a].lo[0] < boxes[b].lo[0]; });
  std::vector<Index> active;  // boxes whose x range may still reach the next one
  std::size_t budget = 16 * count;
  for (Index c : order) {
    const Box& b = boxes[c];
    std::size_t kept = 0;
    for (Index a : active) {
      if (budget-- == 0)
        return false;
      const Box& o = boxes[a];
      if (o.hi[0] < b.lo[0])
        continue;  // ends before this one and every later one starts
      if (o.lo[1] <= b.hi[1] && b.lo[1] <= o.hi[1] && o.lo[2] <= b.hi[2] && b.lo[2] <= o.hi[2])
        return false;
      active[kept++] = a;
    }
    active.resize(kept);
    active.push_back(c);
  }
  return true;
}

// Builds `soup` into `mesh` as it is; false at the first polygon OpenMesh refuses or that repeats
// a vertex, or if the result has a boundary (gap closing and the open-orientation rules decide
// open parts), a non-manifold vertex, two components whose bounding boxes meet (one could be a
// cavity of the other) or an inward closed component.
//
// Everything beyond the stock build's add_vertex / add_face runs in linear passes (no vertex
// circulation) and needs one Index per vertex: components are joined through the polygons'
// vertices (in a closed mesh OpenMesh accepted, every vertex is manifold and vertex-connected is
// edge-connected), and boxes and volumes are summed per component.
bool build_if_already_manifold(const Soup& soup, PolyMesh& mesh) {
  mesh.reserve(soup.num_vertices(), soup.num_corners() / 2 + soup.num_vertices(), soup.num_faces());
  for (const Point& p : soup.positions)
    mesh.add_vertex(p);
  detail::UnionFind components(soup.num_vertices());
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
      for (std::size_t i = 1; i < polygon.size(); ++i)
        components.unite(polygon[0], polygon[i]);
    }
  }
  std::size_t num_components = 0;
  const std::vector<Index> component = std::move(components).take_labels([&](Index) {
    return static_cast<Index>(num_components++);
  });
  for (auto h : mesh.halfedges()) {
    if (mesh.is_boundary(h))
      return false;  // an open part: repair may weld a crack at it or turn it over
  }
  if (!boxes_apart(soup, component, num_components))
    return false;
  // Closed components must not have negative volume (beyond rounding, as repair judges it).
  std::vector<double> volume(num_components, 0.0), magnitude(num_components, 0.0);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    const Index c = component[polygon[0]];
    detail::add_fan_volume(soup, polygon, Point(0, 0, 0), volume[c], magnitude[c]);
  }
  for (std::size_t c = 0; c < num_components; ++c) {
    if (volume[c] < -1e-9 * magnitude[c])
      return false;
  }
  return true;
}

}  // namespace

OpenMeshRepair repair_to_openmesh(const Soup& soup, const RepairOptions& options) {
  validate_soup(soup);
  OpenMeshRepair result;
  const bool plain = !options.detect_before_after && !options.remove_duplicate_faces &&
                     !options.remove_degenerate_faces && !options.remove_zero_area_faces &&
                     !options.remove_isolated_vertices && options.orient &&
                     options.fill_holes.max_edges == 0;
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
  if (fill_openmesh(repaired.mesh, result.mesh) != 0)  // a repaired mesh is manifold: a bug
    throw std::logic_error("repair_to_openmesh: OpenMesh refused a face of the repaired mesh");
  result.report = std::move(repaired.report);
  return result;
}

}  // namespace meshbridge
