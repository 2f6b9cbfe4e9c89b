// SPDX-License-Identifier: GPL-3.0-or-later
#include "cmesh_adapter.h"

#include "meshbridge/polygon_triangles.h"

#include <vcg/complex/allocate.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>

namespace meshbridge::meshlab {
namespace {

constexpr int kEdgeFlags = CFaceO::BORDER012 | CFaceO::FAUX012;

std::uint64_t pair_key(Index a, Index b) {
  if (a > b)
    std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
}

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

//! A CMeshO position as the core's soups hold it.
Point widened(const CMeshO::CoordType& p) {
  return Point(double(p[0]), double(p[1]), double(p[2]));
}

}  // namespace

CMeshSoup soup_from_cmesh(CMeshO& m) {
  CMeshSoup out;
  std::vector<Index> index_of(m.vert.size(), kNoIndex);
  out.soup.reserve(std::size_t(m.vn), std::size_t(m.fn), 3 * std::size_t(m.fn));
  out.vertices.reserve(std::size_t(m.vn));
  out.faces.reserve(std::size_t(m.fn));
  for (auto vi = m.vert.begin(); vi != m.vert.end(); ++vi) {
    if (vi->IsD())
      continue;
    index_of[std::size_t(vi - m.vert.begin())] = out.soup.add_vertex(widened(vi->cP()));
    out.vertices.push_back(&*vi);
  }
  for (auto fi = m.face.begin(); fi != m.face.end(); ++fi) {
    if (fi->IsD())
      continue;
    Index corners[3];
    for (int k = 0; k < 3; ++k) {
      const CMeshO::VertexPointer v = fi->V(k);
      const std::size_t vi = std::size_t(v - &*m.vert.begin());
      if (v == nullptr || vi >= index_of.size() || index_of[vi] == kNoIndex) {
        throw std::invalid_argument("face " + std::to_string(fi - m.face.begin()) + " corner " +
                                    std::to_string(k) + " refers to a deleted or foreign vertex");
      }
      corners[k] = index_of[vi];
    }
    out.soup.add_polygon({corners[0], corners[1], corners[2]});
    out.faces.push_back(&*fi);
  }
  return out;
}

WriteBackReport write_repaired(CMeshO& m, const CMeshSoup& input, const IndexedMesh& repaired,
                               const std::vector<Index>& set_aside_faces,
                               const WriteBackOptions& options) {
  const Soup& in = input.soup;
  const Soup& out = repaired.soup;
  WriteBackReport report;
  report.faces_in = in.num_faces();
  report.vertices_in = in.num_vertices();

  // ---- Phase 1: plan and check everything; `m` is untouched until phase 2. ----
  auto fail = [](const std::string& what) {
    throw std::invalid_argument("write_repaired: " + what);
  };
  if (repaired.vertex_origin.size() != out.num_vertices())
    fail("vertex_origin size mismatch");
  if (repaired.face_origin.size() != out.num_faces())
    fail("face_origin size mismatch");
  if (repaired.corner_origin.size() != out.num_corners())
    fail("corner_origin size mismatch");
  if (input.vertices.size() != in.num_vertices() || input.faces.size() != in.num_faces()) {
    fail("input maps do not match the input soup");
  }
  // kNoIndex: a vertex repair added in the middle of an edge (RepairReport::
  // edges_split_to_stay_manifold), made from its position alone.
  for (std::size_t v = 0; v < out.num_vertices(); ++v) {
    const Index origin = repaired.vertex_origin[v];
    if (origin >= in.num_vertices() && origin != kNoIndex)
      fail("output vertex " + std::to_string(v) + " has no input vertex");
  }

  // Vertices: the core's, then copies needed by set-aside faces whose vertices the core dropped.
  std::vector<Index> vertex_source(repaired.vertex_origin.begin(), repaired.vertex_origin.end());
  std::vector<Index> first_copy(in.num_vertices(), kNoIndex);
  for (std::size_t v = 0; v < vertex_source.size(); ++v) {
    if (vertex_source[v] == kNoIndex)
      continue;
    Index& fc = first_copy[vertex_source[v]];
    if (fc == kNoIndex)
      fc = Index(v);
  }

  std::vector<Index> kept_aside;
  if (options.keep_set_aside_faces) {
    kept_aside = set_aside_faces;
    std::sort(kept_aside.begin(), kept_aside.end());
    kept_aside.erase(std::unique(kept_aside.begin(), kept_aside.end()), kept_aside.end());
    for (Index f : kept_aside) {
      if (f >= in.num_faces())
        fail("set-aside face " + std::to_string(f) + " out of range");
      for (Index v : in.polygon(f)) {
        if (first_copy[v] == kNoIndex) {
          first_copy[v] = Index(vertex_source.size());
          vertex_source.push_back(v);
        }
      }
    }
  }

  // Triangles, in face order: the core's output (which preserves input order) merged with the
  // set-aside faces at their input position.
  std::vector<TrianglePlan> plan;
  plan.reserve(out.num_faces() + kept_aside.size());
  std::size_t next_aside = 0;
  auto flush_aside_before = [&](Index origin) {
    while (next_aside < kept_aside.size() && kept_aside[next_aside] < origin) {
      const Index f = kept_aside[next_aside++];
      TrianglePlan t;
      t.origin = f;
      const PolygonView poly = in.polygon(f);
      for (int k = 0; k < 3; ++k)
        t.vertex[k] = first_copy[poly[std::size_t(k)]];
      plan.push_back(t);
      ++report.set_aside_faces_kept;
    }
  };
  const PolygonTriangles triangles = triangles_as_written(out);
  for (std::size_t f = 0; f < out.num_faces(); ++f) {
    const Index origin = repaired.face_origin[f];
    // kNoIndex: a face hole filling added (they come last, after every set-aside face).
    const bool added = origin == kNoIndex;
    if (origin >= in.num_faces() && !added)
      fail("output face " + std::to_string(f) + " has no input face");
    flush_aside_before(origin);
    const std::size_t arity = out.arity(f);
    if (arity < 3)
      fail("output face " + std::to_string(f) + " has fewer than 3 corners");
    std::vector<signed char> local(arity, -1);
    for (std::size_t k = 0; k < arity; ++k) {
      const Index c = repaired.corner_origin[out.face_begin[f] + k];
      if (added) {
        if (c != kNoIndex) {
          fail("corner " + std::to_string(k) + " of added face " + std::to_string(f) +
               " has an input corner");
        }
        continue;
      }
      const Index in_begin = in.face_begin[origin];
      const Index in_end = in.face_begin[origin + 1];
      if (c < in_begin || c >= in_end) {
        fail("corner " + std::to_string(k) + " of output face " + std::to_string(f) +
             " does not come from input face " + std::to_string(origin));
      }
      local[k] = static_cast<signed char>(c - in_begin);  // 0..2: input faces are triangles
    }
    if (added)
      ++report.faces_added;
    const PolygonView poly = out.polygon(f);
    if (arity > 3) {
      ++report.polygons_triangulated;
      report.triangles_added_by_triangulation += arity - 3;
    }
    // The core's triangles (as the STL and 3MF writers cut the polygon): an edge between two
    // corners that are not neighbours in the polygon is a diagonal, marked faux for MeshLab.
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
      plan.push_back(t);
    }
  }
  flush_aside_before(kNoIndex);

  // ---- Phase 2: rebuild `m` from a snapshot of its live elements. ----
  CMeshO old;
  enable_like(old, m);
  {
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(old, input.vertices.size());
    for (const CMeshO::VertexPointer v : input.vertices)
      (vi++)->ImportData(*v);
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(old, input.faces.size());
    for (const CMeshO::FacePointer f : input.faces)
      (fi++)->ImportData(*f);
  }

  Soup written;
  if (options.keep_soup)
    written.reserve(vertex_source.size(), plan.size(), 3 * plan.size());
  const vcg::Color4b mesh_colour = m.C();
  m.Clear();  // keeps enabled components, textures, transform and user attributes' handles
  m.C() = mesh_colour;

  if (!vertex_source.empty()) {
    auto vi = vcg::tri::Allocator<CMeshO>::AddVertices(m, vertex_source.size());
    for (std::size_t v = 0; v < vertex_source.size(); ++v) {
      const Index src = vertex_source[v];
      if (src == kNoIndex) {
        const Point& p = out.positions[v];
        vi->P() = CMeshO::CoordType(CMeshO::ScalarType(p[0]), CMeshO::ScalarType(p[1]),
                                    CMeshO::ScalarType(p[2]));
      } else {
        vi->ImportData(old.vert[src]);
      }
      vi->ClearB();
      if (options.keep_soup)
        written.add_vertex(widened(vi->cP()));
      ++vi;
    }
  }
  if (!plan.empty()) {
    auto fi = vcg::tri::Allocator<CMeshO>::AddFaces(m, plan.size());
    const bool wedge_tex = m.face.IsWedgeTexCoordEnabled();
    // A corner of an input face at each vertex: added faces take its wedge texture coordinate.
    std::vector<std::pair<const CFaceO*, int>> corner_at(vertex_source.size(), {nullptr, 0});
    for (const TrianglePlan& t : plan) {
      CFaceO& f = *fi++;
      if (options.keep_soup)
        written.add_polygon({t.vertex[0], t.vertex[1], t.vertex[2]});
      if (t.origin == kNoIndex) {
        write_added_face(m, f, t, corner_at, wedge_tex, options);
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
        ++report.faces_flipped;
        if (!options.recompute_normals)
          f.N() = -src.cN();
      }
    }
  }
  report.faces_out = std::size_t(m.fn);
  report.vertices_out = std::size_t(m.vn);
  if (options.keep_soup)
    report.soup = std::move(written);
  return report;
}

DefectLayerCounts build_defect_layer(const CMeshSoup& input, const DefectReport& report,
                                     CMeshO& layer, const DefectColors& colors) {
  using Alloc = vcg::tri::Allocator<CMeshO>;
  layer.Clear();
  DefectLayerCounts counts;
  const std::size_t nv = input.vertices.size();
  auto checked = [nv](Index v) {
    if (v >= nv)
      throw std::invalid_argument("defect report names vertex " + std::to_string(v) +
                                  " of a soup with " + std::to_string(nv));
    return v;
  };
  const std::size_t edge_count = report.singular_edges.size() + report.boundary_edges.size();
  const std::size_t marker_count =
      report.singular_edge_vertices.size() + report.pinch_vertices.size();
  if (edge_count + marker_count == 0)
    return counts;

  auto vi = Alloc::AddVertices(layer, 2 * edge_count + marker_count);
  auto ei = edge_count ? Alloc::AddEdges(layer, edge_count) : layer.edge.end();
  auto add_edge = [&](Index a, Index b, vcg::Color4b colour, float contenders) {
    CMeshO::VertexPointer ends[2];
    for (int k = 0; k < 2; ++k) {
      const Index src = checked(k == 0 ? a : b);
      vi->P() = input.vertices[src]->cP();
      vi->C() = colour;
      vi->Q() = contenders;
      ends[k] = &*vi++;
    }
    ei->V(0) = ends[0];
    ei->V(1) = ends[1];
    ++ei;
  };
  for (const SingularEdge& e : report.singular_edges) {
    add_edge(e.vertices.v0, e.vertices.v1, colors.singular_edge, float(e.contenders));
    ++counts.singular_edges;
  }
  for (const VertexPair& e : report.boundary_edges) {
    add_edge(e.v0, e.v1, colors.boundary_edge, 1.0f);
    ++counts.boundary_edges;
  }
  auto add_marker = [&](Index v, vcg::Color4b colour) {
    vi->P() = input.vertices[checked(v)]->cP();
    vi->C() = colour;
    vi->Q() = 0.0f;
    vi->SetS();
    ++vi;
    ++counts.singular_vertex_markers;
  };
  for (Index v : report.singular_edge_vertices)
    add_marker(v, colors.singular_edge_vertex);
  for (Index v : report.pinch_vertices)
    add_marker(v, colors.pinch_vertex);
  return counts;
}

DefectSelection select_defect_faces(CMeshSoup& input, const DefectReport& report, bool select,
                                    bool colour_faces, vcg::Color4b singular_edge,
                                    vcg::Color4b pinch) {
  DefectSelection result;
  const Soup& soup = input.soup;
  std::unordered_set<std::uint64_t> singular_pairs;
  singular_pairs.reserve(report.singular_edges.size() * 2);
  for (const SingularEdge& e : report.singular_edges) {
    singular_pairs.insert(pair_key(e.vertices.v0, e.vertices.v1));
  }
  std::vector<char> is_pinch(soup.num_vertices(), 0);
  for (Index v : report.pinch_vertices) {
    if (v < is_pinch.size())
      is_pinch[v] = 1;
  }

  if (select) {
    for (const CMeshO::VertexPointer v : input.vertices)
      v->ClearS();
    for (const CMeshO::FacePointer f : input.faces)
      f->ClearS();
    for (Index v : report.singular_edge_vertices) {
      if (v < input.vertices.size())
        input.vertices[v]->SetS();
    }
    for (Index v : report.pinch_vertices) {
      if (v < input.vertices.size())
        input.vertices[v]->SetS();
    }
    for (const CMeshO::VertexPointer v : input.vertices)
      result.vertices += v->IsS() ? 1 : 0;
  }

  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView poly = soup.polygon(f);
    bool on_edge = false;
    bool at_pinch = false;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Index a = poly[k];
      const Index b = poly[(k + 1) % poly.size()];
      if (!singular_pairs.empty() && singular_pairs.count(pair_key(a, b)))
        on_edge = true;
      if (is_pinch[a])
        at_pinch = true;
    }
    if (!on_edge && !at_pinch)
      continue;
    ++result.faces;
    CFaceO& face = *input.faces[f];
    if (select)
      face.SetS();
    if (colour_faces)
      face.C() = on_edge ? singular_edge : pinch;
  }
  return result;
}

}  // namespace meshbridge::meshlab
