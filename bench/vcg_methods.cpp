// SPDX-License-Identifier: GPL-3.0-or-later
#include "vcg_methods.h"

#include <vcg/complex/complex.h>

#include <vcg/complex/algorithms/clean.h>
#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <vector>

namespace meshbridge::bench {

namespace {

class VcgVertex;
class VcgFace;
struct VcgUsedTypes
    : public vcg::UsedTypes<vcg::Use<VcgVertex>::AsVertexType, vcg::Use<VcgFace>::AsFaceType> {};
class VcgVertex : public vcg::Vertex<VcgUsedTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f,
                                     vcg::vertex::BitFlags, vcg::vertex::VFAdj, vcg::vertex::Mark> {
};
class VcgFace
    : public vcg::Face<VcgUsedTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::BitFlags,
                       vcg::face::FFAdj, vcg::face::VFAdj, vcg::face::Mark> {};
class VcgMesh : public vcg::tri::TriMesh<std::vector<VcgVertex>, std::vector<VcgFace>> {};

using Clean = vcg::tri::Clean<VcgMesh>;
using Topology = vcg::tri::UpdateTopology<VcgMesh>;

//! The soup as a vcg mesh, polygons fan-triangulated; returns the number of triangles added
//! beyond one per polygon.
long build(const Soup& soup, VcgMesh& mesh) {
  std::size_t triangles = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    triangles += soup.arity(f) - 2;
  auto vi = vcg::tri::Allocator<VcgMesh>::AddVertices(mesh, soup.num_vertices());
  for (const Point& p : soup.positions) {
    vi->P() =
        vcg::Point3f(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
    ++vi;
  }
  auto fi = vcg::tri::Allocator<VcgMesh>::AddFaces(mesh, triangles);
  VcgVertex* base = &mesh.vert[0];
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto poly = soup.polygon(f);
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      fi->V(0) = base + poly[0];
      fi->V(1) = base + poly[i];
      fi->V(2) = base + poly[i + 1];
      ++fi;
    }
  }
  return static_cast<long>(triangles - soup.num_faces());
}

//! The live part of the vcg mesh as a soup (vertices renumbered in order).
Soup to_soup(const VcgMesh& mesh) {
  Soup soup;
  std::vector<Index> index(mesh.vert.size(), kNoIndex);
  soup.reserve(static_cast<std::size_t>(mesh.vn), static_cast<std::size_t>(mesh.fn),
               3 * static_cast<std::size_t>(mesh.fn));
  for (std::size_t v = 0; v < mesh.vert.size(); ++v) {
    if (mesh.vert[v].IsD())
      continue;
    const auto& p = mesh.vert[v].cP();
    index[v] = soup.add_vertex(Point(p[0], p[1], p[2]));
  }
  for (const VcgFace& f : mesh.face) {
    if (f.IsD())
      continue;
    soup.add_polygon({index[f.cV(0) - &mesh.vert[0]], index[f.cV(1) - &mesh.vert[0]],
                      index[f.cV(2) - &mesh.vert[0]]});
  }
  return soup;
}

//! Fan triangulation changes the face count the method starts from: say so, count from there.
void note_fan_triangles(const Soup& soup, Outcome& outcome, long extra) {
  if (extra > 0) {
    outcome.faces_in = static_cast<long>(soup.num_faces()) + extra;
    add_note(outcome, "input fan-triangulated into %ld triangles", outcome.faces_in);
  }
}

}  // namespace

void vcg_topology_counts(const Soup& soup, Clock& clock, Outcome& outcome) {
  VcgMesh mesh;
  const long extra = build(soup, mesh);
  const double t_build = clock.lap();
  Topology::FaceFace(mesh);
  const double t_ff = clock.lap();
  const int edges = Clean::CountNonManifoldEdgeFF(mesh);
  const int vertices = Clean::CountNonManifoldVertexFF(mesh);
  clock.stop();
  add_note(outcome, "build %.2f s, FF topology %.2f s, counts %.2f s", t_build, t_ff, clock.lap());
  add_note(outcome,
           "found %d non-manifold edges, %d non-manifold vertices (vcg counts only "
           "vertices off non-manifold edges)",
           edges, vertices);
  note_fan_triangles(soup, outcome, extra);
  if (wants_evaluation(outcome))
    evaluate(to_soup(mesh), outcome);
}

void vcg_remove_faces(const Soup& soup, Clock& clock, Outcome& outcome, bool then_split_vertices) {
  VcgMesh mesh;
  const long extra = build(soup, mesh);
  Topology::FaceFace(mesh);
  const double t_prepare = clock.lap();
  const int removed = Clean::RemoveNonManifoldFace(mesh);
  const double t_remove = clock.lap();
  int split = 0;
  if (then_split_vertices) {
    Topology::FaceFace(mesh);
    split = Clean::SplitNonManifoldVertex(mesh, 0.0f);
  }
  clock.stop();
  add_note(outcome, "build + FF %.2f s, RemoveNonManifoldFace %.2f s: %d faces deleted", t_prepare,
           t_remove, removed);
  if (then_split_vertices)
    add_note(outcome, "SplitNonManifoldVertex %.2f s: %d vertices split", clock.lap(), split);
  note_fan_triangles(soup, outcome, extra);
  if (wants_evaluation(outcome))
    evaluate(to_soup(mesh), outcome);
}

void vcg_split_components(const Soup& soup, Clock& clock, Outcome& outcome) {
  VcgMesh mesh;
  const long extra = build(soup, mesh);
  Topology::FaceFace(mesh);
  const double t_prepare = clock.lap();
  const std::size_t components = Clean::SplitManifoldComponents(mesh);
  clock.stop();
  add_note(outcome, "build + FF %.2f s, SplitManifoldComponents %.2f s: %zu components", t_prepare,
           clock.lap(), components);
  note_fan_triangles(soup, outcome, extra);
  if (wants_evaluation(outcome))
    evaluate(to_soup(mesh), outcome);
}

}  // namespace meshbridge::bench
