// SPDX-License-Identifier: GPL-3.0-or-later
//! \file write_back.cpp
//! write_repaired() (cmesh_adapter.h): the repaired soup written back into the MeshLab layer, in
//! two phases. Phase 1 plans every vertex and triangle and checks the origin maps, leaving the
//! layer untouched (an error leaves it as it was); phase 2 rebuilds the layer from a snapshot of
//! its live elements.

#include "cmesh_adapter.h"

#include "meshbridge/polygon_triangles.h"

#include <vcg/complex/allocate.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace meshbridge::meshlab {
namespace {

constexpr int kEdgeFlags = CFaceO::BORDER012 | CFaceO::FAUX012;

//! Enables in `dst` the optional (ocf) components that are enabled in `src`, so that
//! ImportData() copies them. Adjacency is not data and stays as it is.
void enable_like(CMeshO& dst, const CMeshO& src) {
  if (src.vert.IsMarkEnabled())
    dst.vert.EnableMark();
  if (src.vert.IsTexCoordEnabled())
    dst.vert.EnableTexCoord();
  if (src.vert.IsCurvatureEnabled())
    dst.vert.EnableCurvature();
  if (src.vert.IsCurvatureDirEnabled())
    dst.vert.EnableCurvatureDir();
  if (src.vert.IsRadiusEnabled())
    dst.vert.EnableRadius();
  if (src.face.IsQualityEnabled())
    dst.face.EnableQuality();
  if (src.face.IsMarkEnabled())
    dst.face.EnableMark();
  if (src.face.IsColorEnabled())
    dst.face.EnableColor();
  if (src.face.IsCurvatureDirEnabled())
    dst.face.EnableCurvatureDir();
  if (src.face.IsWedgeTexCoordEnabled())
    dst.face.EnableWedgeTexCoord();
}

//! One triangle of the rebuilt mesh.
struct TrianglePlan {
  Index origin = kNoIndex;           //!< input (soup) face
  Index vertex[3] = {0, 0, 0};       //!< output vertices
  signed char local[3] = {0, 1, 2};  //!< input corner (0..2 within the input triangle) per corner;
                                     //!< -1: no input corner (no wedge origin)
  bool diagonal[3] = {false, false, false};  //!< edge k is a diagonal of a cut polygon
};

//! The input edge (0..2) that output edge (la -> lb) lies on, or -1 if none.
int input_edge(int la, int lb) {
  if (la < 0 || lb < 0)
    return -1;
  if (lb == (la + 1) % 3)
    return la;
  if (la == (lb + 1) % 3)
    return lb;
  return -1;
}

//! A face hole filling added (no input face): corners from `t`, no flags, the default colour
//! (opaque black, as the core's writers give it) and quality 0, wedge texture coordinates from
//! an input face's corner at the same vertex, and its geometric normal unless the caller
//! recomputes normals.
void write_added_face(CMeshO& m, CFaceO& f, const TrianglePlan& t,
                      const std::vector<std::pair<const CFaceO*, int>>& corner_at, bool wedge_tex,
                      const WriteBackOptions& options) {
  f.Flags() = 0;
  for (int k = 0; k < 3; ++k) {
    f.V(k) = &m.vert[t.vertex[k]];
    if (t.diagonal[k])
      f.SetF(k);
    const auto& [source, corner] = corner_at[t.vertex[k]];
    if (wedge_tex && source != nullptr)
      f.WT(k) = source->cWT(corner);
  }
  if (m.face.IsColorEnabled())
    f.C() = vcg::Color4b(0, 0, 0, 255);
  if (m.face.IsQualityEnabled())
    f.Q() = 0;
  if (!options.recompute_normals)
    f.N() = vcg::TriangleNormal(f).Normalize();
}

[[noreturn]] void fail(const std::string& what) {
  throw std::invalid_argument("write_repaired: " + what);
}

//! The state of one write-back: the vertex sources and triangle plan of phase 1, the report.
class WriteBack {
 public:
  WriteBack(const CMeshSoup& input, const IndexedMesh& repaired, const WriteBackOptions& options)
      : input_(input),
        in_(input.soup),
        repaired_(repaired),
        out_(repaired.soup),
        options_(options) {
    report_.faces_in = in_.num_faces();
    report_.vertices_in = in_.num_vertices();
  }

  //! Phase 1: the origin maps fit the input (else std::invalid_argument).
  void check_maps() const;
  //! Phase 1: the core's vertices, then copies needed by the set-aside faces put back whose
  //! vertices the core dropped.
  void plan_vertices(const std::vector<Index>& set_aside_faces);
  //! Phase 1: the triangles in face order: the core's output (which preserves input order)
  //! merged with the set-aside faces at their input position.
  void plan_triangles();
  //! Phase 2: replaces the content of `m`; returns the report.
  WriteBackReport rebuild(CMeshO& m);

 private:
  void plan_set_aside_before(Index origin);
  //! The triangles of output face f (as the STL and 3MF writers cut a polygon).
  void plan_face(std::size_t f, const PolygonTriangles& triangles);
  void write_vertices(CMeshO& m, const CMeshO& old, Soup& written) const;
  void write_faces(CMeshO& m, const CMeshO& old, Soup& written);

  const CMeshSoup& input_;
  const Soup& in_;
  const IndexedMesh& repaired_;
  const Soup& out_;
  const WriteBackOptions& options_;
  std::vector<Index> vertex_source_;  //!< input vertex of each layer vertex (kNoIndex: new)
  std::vector<Index> first_copy_;     //!< first layer vertex of each input vertex
  std::vector<Index> kept_aside_;     //!< set-aside faces put back, sorted
  std::size_t next_aside_ = 0;
  std::vector<TrianglePlan> plan_;
  WriteBackReport report_;
};

void WriteBack::check_maps() const {
  if (repaired_.vertex_origin.size() != out_.num_vertices())
    fail("vertex_origin size mismatch");
  if (repaired_.face_origin.size() != out_.num_faces())
    fail("face_origin size mismatch");
  if (repaired_.corner_origin.size() != out_.num_corners())
    fail("corner_origin size mismatch");
  if (input_.vertices.size() != in_.num_vertices() || input_.faces.size() != in_.num_faces())
    fail("input maps do not match the input soup");
  // kNoIndex: a vertex repair added in the middle of an edge (RepairReport::
  // edges_split_to_stay_manifold), made from its position alone.
  for (std::size_t v = 0; v < out_.num_vertices(); ++v) {
    const Index origin = repaired_.vertex_origin[v];
    if (origin >= in_.num_vertices() && origin != kNoIndex)
      fail("output vertex " + std::to_string(v) + " has no input vertex");
  }
}

void WriteBack::plan_vertices(const std::vector<Index>& set_aside_faces) {
  vertex_source_.assign(repaired_.vertex_origin.begin(), repaired_.vertex_origin.end());
  first_copy_.assign(in_.num_vertices(), kNoIndex);
  for (std::size_t v = 0; v < vertex_source_.size(); ++v) {
    if (vertex_source_[v] == kNoIndex)
      continue;
    Index& fc = first_copy_[vertex_source_[v]];
    if (fc == kNoIndex)
      fc = Index(v);
  }
  if (!options_.keep_set_aside_faces)
    return;
  kept_aside_ = set_aside_faces;
  std::sort(kept_aside_.begin(), kept_aside_.end());
  kept_aside_.erase(std::unique(kept_aside_.begin(), kept_aside_.end()), kept_aside_.end());
  for (Index f : kept_aside_) {
    if (f >= in_.num_faces())
      fail("set-aside face " + std::to_string(f) + " out of range");
    for (Index v : in_.polygon(f)) {
      if (first_copy_[v] == kNoIndex) {
        first_copy_[v] = Index(vertex_source_.size());
        vertex_source_.push_back(v);
      }
    }
  }
}

void WriteBack::plan_triangles() {
  plan_.reserve(out_.num_faces() + kept_aside_.size());
  const PolygonTriangles triangles = triangles_as_written(out_);
  for (std::size_t f = 0; f < out_.num_faces(); ++f)
    plan_face(f, triangles);
  plan_set_aside_before(kNoIndex);
}

void WriteBack::plan_set_aside_before(Index origin) {
  while (next_aside_ < kept_aside_.size() && kept_aside_[next_aside_] < origin) {
    const Index f = kept_aside_[next_aside_++];
    TrianglePlan t;
    t.origin = f;
    const PolygonView poly = in_.polygon(f);
    for (int k = 0; k < 3; ++k)
      t.vertex[k] = first_copy_[poly[std::size_t(k)]];
    plan_.push_back(t);
    ++report_.degenerate_faces_kept;
  }
}

void WriteBack::plan_face(std::size_t f, const PolygonTriangles& triangles) {
  const Index origin = repaired_.face_origin[f];
  // kNoIndex: a face hole filling added (they come last, after every set-aside face).
  const bool added = origin == kNoIndex;
  if (origin >= in_.num_faces() && !added)
    fail("output face " + std::to_string(f) + " has no input face");
  plan_set_aside_before(origin);
  const std::size_t arity = out_.arity(f);
  if (arity < 3)
    fail("output face " + std::to_string(f) + " has fewer than 3 corners");
  std::vector<signed char> local(arity, -1);
  for (std::size_t k = 0; k < arity; ++k) {
    const Index c = repaired_.corner_origin[out_.face_begin[f] + k];
    if (added) {
      if (c != kNoIndex) {
        fail("corner " + std::to_string(k) + " of added face " + std::to_string(f) +
             " has an input corner");
      }
      continue;
    }
    const Index in_begin = in_.face_begin[origin];
    const Index in_end = in_.face_begin[origin + 1];
    if (c < in_begin || c >= in_end) {
      fail("corner " + std::to_string(k) + " of output face " + std::to_string(f) +
           " does not come from input face " + std::to_string(origin));
    }
    local[k] = static_cast<signed char>(c - in_begin);  // 0..2: input faces are triangles
  }
  if (added)
    ++report_.faces_added;
  const PolygonView poly = out_.polygon(f);
  if (arity > 3) {
    ++report_.polygons_triangulated;
    report_.triangles_added_by_triangulation += arity - 3;
  }
  // An edge between two corners that are not neighbours in the polygon is a diagonal, marked
  // faux for MeshLab.
  for (Index i = triangles.first[f]; i < triangles.first[f + 1]; ++i) {
    TrianglePlan t;
    t.origin = origin;
    const auto& idx = triangles.corners[i];
    for (int j = 0; j < 3; ++j) {
      t.vertex[j] = poly[idx[j]];
      t.local[j] = local[idx[j]];
    }
    for (int j = 0; j < 3; ++j) {
      const std::size_t a = idx[j], b = idx[(j + 1) % 3];
      t.diagonal[j] = (a + 1) % arity != b && (b + 1) % arity != a;
    }
    plan_.push_back(t);
  }
}

WriteBackReport WriteBack::rebuild(CMeshO& m) {
  CMeshO old;  // a snapshot of the live elements
  enable_like(old, m);
  {
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(old, input_.vertices.size());
    for (const CMeshO::VertexPointer v : input_.vertices)
      (vi++)->ImportData(*v);
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(old, input_.faces.size());
    for (const CMeshO::FacePointer f : input_.faces)
      (fi++)->ImportData(*f);
  }
  Soup written;
  if (options_.keep_soup)
    written.reserve(vertex_source_.size(), plan_.size(), 3 * plan_.size());
  const vcg::Color4b mesh_color = m.C();
  m.Clear();  // keeps enabled components, textures, transform and user attributes' handles
  m.C() = mesh_color;
  write_vertices(m, old, written);
  write_faces(m, old, written);
  report_.faces_out = std::size_t(m.fn);
  report_.vertices_out = std::size_t(m.vn);
  if (options_.keep_soup)
    report_.soup = std::move(written);
  return report_;
}

void WriteBack::write_vertices(CMeshO& m, const CMeshO& old, Soup& written) const {
  if (vertex_source_.empty())
    return;
  auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, vertex_source_.size());
  for (std::size_t v = 0; v < vertex_source_.size(); ++v) {
    const Index src = vertex_source_[v];
    if (src == kNoIndex) {
      const Point& p = out_.positions[v];
      vi->P() = CMeshO::CoordType(CMeshO::ScalarType(p[0]), CMeshO::ScalarType(p[1]),
                                  CMeshO::ScalarType(p[2]));
    } else {
      vi->ImportData(old.vert[src]);
    }
    vi->ClearB();
    if (options_.keep_soup)
      written.add_vertex(widened(vi->cP()));
    ++vi;
  }
}

void WriteBack::write_faces(CMeshO& m, const CMeshO& old, Soup& written) {
  if (plan_.empty())
    return;
  auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, plan_.size());
  const bool wedge_tex = m.face.IsWedgeTexCoordEnabled();
  // A corner of an input face at each vertex: added faces take its wedge texture coordinate.
  std::vector<std::pair<const CFaceO*, int>> corner_at(vertex_source_.size(), {nullptr, 0});
  for (const TrianglePlan& t : plan_) {
    CFaceO& f = *fi++;
    if (options_.keep_soup)
      written.add_polygon({t.vertex[0], t.vertex[1], t.vertex[2]});
    if (t.origin == kNoIndex) {
      write_added_face(m, f, t, corner_at, wedge_tex, options_);
      continue;
    }
    const CFaceO& src = old.face[t.origin];
    f.ImportData(src);
    f.Flags() &= ~kEdgeFlags;
    for (int k = 0; k < 3; ++k)
      f.V(k) = &m.vert[t.vertex[k]];
    // Orientation relative to the input triangle: reversed if the corners run backwards.
    bool flipped = false;
    for (int k = 0; k < 3; ++k) {
      const int la = t.local[k], lb = t.local[(k + 1) % 3];
      if (la >= 0 && lb >= 0 && la == (lb + 1) % 3)
        flipped = true;
    }
    for (int k = 0; k < 3; ++k) {
      if (corner_at[t.vertex[k]].first == nullptr)
        corner_at[t.vertex[k]] = {&f, k};
      if (wedge_tex && t.local[k] >= 0)
        f.WT(k) = src.cWT(t.local[k]);
      const int e = input_edge(t.local[k], t.local[(k + 1) % 3]);
      if (t.diagonal[k] || (e >= 0 && src.IsF(e)))
        f.SetF(k);
    }
    if (flipped) {
      ++report_.faces_flipped;
      if (!options_.recompute_normals)
        f.N() = -src.cN();
    }
  }
}

}  // namespace

WriteBackReport write_repaired(CMeshO& m, const CMeshSoup& input, const IndexedMesh& repaired,
                               const std::vector<Index>& set_aside_faces,
                               const WriteBackOptions& options) {
  WriteBack write_back(input, repaired, options);
  write_back.check_maps();
  write_back.plan_vertices(set_aside_faces);
  write_back.plan_triangles();
  return write_back.rebuild(m);  // `m` is untouched until here
}

}  // namespace meshbridge::meshlab
