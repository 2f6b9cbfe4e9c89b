// SPDX-License-Identifier: GPL-3.0-or-later
#include "cmesh_adapter.h"

#include <vcg/complex/allocate.h>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <utility>

namespace meshbridge::meshlab {
namespace {

std::uint64_t pair_key(Index a, Index b) {
  if (a > b)
    std::swap(a, b);
  return (std::uint64_t(a) << 32) | b;
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
  auto add_edge = [&](Index a, Index b, vcg::Color4b color, float contenders) {
    CMeshO::VertexPointer ends[2];
    for (int k = 0; k < 2; ++k) {
      const Index src = checked(k == 0 ? a : b);
      vi->P() = input.vertices[src]->cP();
      vi->C() = color;
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
  auto add_marker = [&](Index v, vcg::Color4b color) {
    vi->P() = input.vertices[checked(v)]->cP();
    vi->C() = color;
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
                                    bool color_faces, vcg::Color4b singular_edge,
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
    if (color_faces)
      face.C() = on_edge ? singular_edge : pinch;
  }
  return result;
}

}  // namespace meshbridge::meshlab
