// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Shared checks for tests: the invariants every repaired or bridged mesh must satisfy.

#include "meshbridge/edge_bridges.h"
#include "meshbridge/mesh_types.h"
#include "meshbridge/repair.h"
#include "meshbridge/soup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>

namespace meshbridge::test_support {

//! Every edge has at most two sides, and two sides run in opposite directions.
inline ::testing::AssertionResult every_edge_manifold(const Soup& soup) {
  const std::vector<Index> corner_face = corner_faces(soup);
  const EdgeBridges bridges = group_sides(soup, corner_face);
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index k = bridges.num_contenders(e);
    if (k > 2) {
      const auto [v0, v1] = bridges.edge_vertices(e, soup, corner_face);
      return ::testing::AssertionFailure()
             << "edge " << v0 << "-" << v1 << " has " << k << " sides";
    }
    if (k == 2) {
      const Index a = bridges.contenders[bridges.begin[e]];
      const Index b = bridges.contenders[bridges.begin[e] + 1];
      if (soup.corner_vertices[a] == soup.corner_vertices[b]) {
        const auto [v0, v1] = bridges.edge_vertices(e, soup, corner_face);
        return ::testing::AssertionFailure()
               << "edge " << v0 << "-" << v1 << " has two sides one way";
      }
    }
  }
  return ::testing::AssertionSuccess();
}

//! OpenMesh accepts every polygon and every vertex is manifold.
inline ::testing::AssertionResult openmesh_accepts(const IndexedMesh& mesh) {
  const OpenMeshBuild build = to_openmesh(mesh);
  if (build.add_face_failures != 0) {
    return ::testing::AssertionFailure() << build.add_face_failures << " add_face failures";
  }
  if (build.mesh.n_faces() != mesh.soup.num_faces()) {
    return ::testing::AssertionFailure() << "OpenMesh holds " << build.mesh.n_faces() << " of "
                                         << mesh.soup.num_faces() << " faces";
  }
  for (auto v : build.mesh.vertices()) {
    if (!build.mesh.is_manifold(v)) {
      return ::testing::AssertionFailure() << "OpenMesh vertex " << v.idx() << " not manifold";
    }
  }
  return ::testing::AssertionSuccess();
}

//! The invariants of a repair with cleanup off. Faces added by hole filling come last, with
//! origin kNoIndex for the face and each corner.
inline void expect_repair_invariants(const Soup& input, const RepairResult& result) {
  const IndexedMesh& mesh = result.mesh;
  const RepairReport& report = result.report;
  EXPECT_EQ(report.faces_out + report.faces_set_aside,
            input.num_faces() + report.faces_added_by_split + report.holes.faces_added);
  EXPECT_EQ(mesh.soup.num_faces(), report.faces_out);
  EXPECT_EQ(mesh.face_origin.size(), mesh.soup.num_faces());
  EXPECT_EQ(mesh.corner_origin.size(), mesh.soup.num_corners());
  ASSERT_EQ(mesh.vertex_origin.size(), mesh.soup.num_vertices());
  EXPECT_TRUE(every_edge_manifold(mesh.soup));
  EXPECT_TRUE(openmesh_accepts(mesh));
  EXPECT_TRUE(report.after.singular_edges.empty());
  EXPECT_EQ(report.after.num_singular_vertices(), 0u);
  EXPECT_TRUE(report.after.inconsistent_edges.empty());
  // Vertices with no origin: one at the middle of each edge split to stay manifold.
  std::size_t midpoints = 0;
  for (std::size_t v = 0; v < mesh.soup.num_vertices(); ++v) {
    if (mesh.vertex_origin[v] == kNoIndex) {
      ++midpoints;
      continue;
    }
    ASSERT_LT(mesh.vertex_origin[v], input.num_vertices());
    EXPECT_EQ(mesh.soup.positions[v], input.positions[mesh.vertex_origin[v]]);
  }
  EXPECT_EQ(midpoints, report.edges_split_to_stay_manifold);
  // Gap closing welds corners into a survivor within its tolerance and inserts T-junction
  // corners (which take the corner starting their side as origin); otherwise corners map exactly.
  std::size_t moved_corners = 0;
  const std::size_t first_added = mesh.soup.num_faces() - report.holes.faces_added;
  for (std::size_t f = first_added; f < mesh.soup.num_faces(); ++f) {
    EXPECT_EQ(mesh.face_origin[f], kNoIndex) << "added face " << f;
    for (Index c = mesh.soup.face_begin[f]; c < mesh.soup.face_begin[f + 1]; ++c)
      EXPECT_EQ(mesh.corner_origin[c], kNoIndex) << "corner " << c << " of added face " << f;
  }
  for (std::size_t c = 0; c < mesh.soup.face_begin[first_added]; ++c) {
    ASSERT_LT(mesh.corner_origin[c], input.num_corners());
    const Index from = input.corner_vertices[mesh.corner_origin[c]];
    const Index to = mesh.vertex_origin[mesh.soup.corner_vertices[c]];
    if (to == from || to == kNoIndex)  // kNoIndex: a midpoint corner, counted above
      continue;
    ++moved_corners;
    if ((input.positions[to] - input.positions[from]).norm() > report.gaps.tolerance)
      ++moved_corners;  // only an inserted corner may lie farther
  }
  if (!report.gaps.changed())
    EXPECT_EQ(moved_corners, 0u);
  else
    EXPECT_LE(moved_corners, 2 * report.gaps.t_junctions_closed + input.num_corners());
  // Faces keep their order.
  EXPECT_TRUE(std::is_sorted(mesh.face_origin.begin(), mesh.face_origin.end()));
}

//! One triangle (0,0,0), (1,0,0), (0,1,0): the smallest valid soup, for tests that break it.
inline Soup triangle() {
  Soup soup;
  soup.add_vertex({0, 0, 0});
  soup.add_vertex({1, 0, 0});
  soup.add_vertex({0, 1, 0});
  soup.add_polygon({0, 1, 2});
  return soup;
}

//! The same soup with faces shuffled and every polygon's start corner rotated (seeded).
inline Soup shuffled(const Soup& soup, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::vector<Index> order(soup.num_faces());
  for (std::size_t f = 0; f < order.size(); ++f)
    order[f] = static_cast<Index>(f);
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

//! Sets MESHBRIDGE_THREADS (the threads the core may use for one mesh) for its lifetime.
class ThreadsSetting {
 public:
  explicit ThreadsSetting(unsigned n) {
    setenv("MESHBRIDGE_THREADS", std::to_string(n).c_str(), 1);
  }
  ~ThreadsSetting() { unsetenv("MESHBRIDGE_THREADS"); }
  ThreadsSetting(const ThreadsSetting&) = delete;
  ThreadsSetting& operator=(const ThreadsSetting&) = delete;
};

//! Expects two meshes to be the same: positions, polygons and every origin.
inline void expect_same_mesh(const IndexedMesh& a, const IndexedMesh& b) {
  EXPECT_EQ(a.soup.positions, b.soup.positions);
  EXPECT_EQ(a.soup.face_begin, b.soup.face_begin);
  EXPECT_EQ(a.soup.corner_vertices, b.soup.corner_vertices);
  EXPECT_EQ(a.vertex_origin, b.vertex_origin);
  EXPECT_EQ(a.face_origin, b.face_origin);
  EXPECT_EQ(a.corner_origin, b.corner_origin);
}

}  // namespace meshbridge::test_support

namespace meshbridge::test_support {

//! Component label of every face, connected through shared edges (labels: smallest face index).
inline std::vector<Index> face_components(const Soup& soup) {
  const std::vector<Index> corner_face = corner_faces(soup);
  const EdgeBridges bridges = group_sides(soup, corner_face);
  std::vector<Index> parent(soup.num_faces());
  for (std::size_t f = 0; f < parent.size(); ++f)
    parent[f] = static_cast<Index>(f);
  const auto find = [&](Index x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    for (Index i = bridges.begin[e] + 1; i < bridges.begin[e + 1]; ++i) {
      Index a = find(corner_face[bridges.contenders[bridges.begin[e]]]);
      Index b = find(corner_face[bridges.contenders[i]]);
      if (a > b)
        std::swap(a, b);
      parent[b] = a;
    }
  }
  std::vector<Index> label(soup.num_faces());
  for (std::size_t f = 0; f < label.size(); ++f)
    label[f] = find(static_cast<Index>(f));
  return label;
}

//! Signed volume of the faces with the given component label (fan triangulation).
inline double signed_volume(const Soup& soup, const std::vector<Index>& label, Index component) {
  double volume = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (label[f] != component)
      continue;
    const PolygonView p = soup.polygon(f);
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      volume += OpenMesh::dot(soup.positions[p[0]],
                              OpenMesh::cross(soup.positions[p[i]], soup.positions[p[i + 1]]));
    }
  }
  return volume / 6;
}

//! Sum of the magnitudes of the terms of signed_volume(): the scale its rounding error has.
inline double volume_magnitude(const Soup& soup, const std::vector<Index>& label, Index component) {
  double magnitude = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (label[f] != component)
      continue;
    const PolygonView p = soup.polygon(f);
    for (std::size_t i = 1; i + 1 < p.size(); ++i) {
      magnitude += std::abs(OpenMesh::dot(
          soup.positions[p[0]], OpenMesh::cross(soup.positions[p[i]], soup.positions[p[i + 1]])));
    }
  }
  return magnitude / 6;
}

//! Generalized winding number of the faces labelled `component` at point p (solid angles of
//! their fan triangles, Van Oosterom and Strackee, over 4 pi).
inline double winding_number(const Soup& soup, const std::vector<Index>& label, Index component,
                             const Point& p) {
  double total = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (label[f] != component)
      continue;
    const PolygonView poly = soup.polygon(f);
    const Point a = soup.positions[poly[0]] - p;
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      const Point b = soup.positions[poly[i]] - p, c = soup.positions[poly[i + 1]] - p;
      const double la = a.norm(), lb = b.norm(), lc = c.norm();
      const double numerator = OpenMesh::dot(a, OpenMesh::cross(b, c));
      const double denominator = la * lb * lc + OpenMesh::dot(a, b) * lc +
                                 OpenMesh::dot(a, c) * lb + OpenMesh::dot(b, c) * la;
      if (std::abs(numerator) <= 1e-9 * la * lb * lc && denominator <= 0)
        return std::nan("");  // p lies on the face
      total += 2 * std::atan2(numerator, denominator);
    }
  }
  return total / (4 * 3.14159265358979323846);
}

//! True if component `inner` lies inside component `outer`: |winding number| of `outer` is
//! within 0.1 of 1 at the centroids of (up to) 8 faces spread over `inner`, except where the
//! centroid lies on `outer`, and at one of them at least.
inline bool lies_inside(const Soup& soup, const std::vector<Index>& label, Index inner,
                        Index outer) {
  std::vector<Index> faces;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    if (label[f] == inner)
      faces.push_back(static_cast<Index>(f));
  const std::size_t tries = std::min<std::size_t>(8, faces.size());
  bool decided = false;
  for (std::size_t k = 0; k < tries; ++k) {
    const PolygonView poly = soup.polygon(faces[k * faces.size() / tries]);
    Point centroid(0, 0, 0);
    for (Index v : poly)
      centroid += soup.positions[v];
    centroid /= static_cast<double>(poly.size());
    const double w = winding_number(soup, label, outer, centroid);
    if (std::isnan(w))
      continue;
    if (std::abs(std::abs(w) - 1) > 0.1)
      return false;
    decided = true;
  }
  return decided;
}

}  // namespace meshbridge::test_support
