// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/repair_to_openmesh.h"
#include "meshbridge/models/canonical_models.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

using namespace meshbridge;

namespace {

RepairOptions lean() {
  RepairOptions options;
  options.detect_before_after = false;
  return options;
}

// Same vertices (positions, in order) and same polygons as the reference path.
void expect_same_as_reference(const Soup& soup, const OpenMeshRepair& got) {
  const RepairResult reference = repair(soup, lean());
  const OpenMeshBuild expected = to_openmesh(reference.mesh);
  EXPECT_EQ(got.add_face_failures, 0u);
  ASSERT_EQ(got.mesh.n_vertices(), expected.mesh.n_vertices());
  ASSERT_EQ(got.mesh.n_faces(), expected.mesh.n_faces());
  for (auto v : got.mesh.vertices())
    EXPECT_EQ(got.mesh.point(v), expected.mesh.point(v));
  for (auto f : got.mesh.faces()) {
    std::vector<int> a, b;
    for (auto v : got.mesh.fv_range(f))
      a.push_back(v.idx());
    for (auto v : expected.mesh.fv_range(expected.mesh.face_handle(f.idx())))
      b.push_back(v.idx());
    EXPECT_EQ(a, b) << "face " << f.idx();
  }
  OpenMesh::VPropHandleT<Index> vertex_origin;
  OpenMesh::FPropHandleT<Index> face_origin;
  ASSERT_TRUE(got.mesh.get_property_handle(vertex_origin, kVertexOriginProperty));
  ASSERT_TRUE(got.mesh.get_property_handle(face_origin, kFaceOriginProperty));
  for (auto v : got.mesh.vertices()) {
    EXPECT_EQ(got.mesh.property(vertex_origin, v), reference.mesh.vertex_origin[v.idx()]);
  }
  for (auto f : got.mesh.faces()) {
    EXPECT_EQ(got.mesh.property(face_origin, f), reference.mesh.face_origin[f.idx()]);
  }
  for (auto v : got.mesh.vertices())
    EXPECT_TRUE(got.mesh.is_manifold(v));
}

}  // namespace

TEST(RepairToOpenMesh, clean_input_takes_the_fast_path_and_matches_repair) {
  for (const Soup& soup :
       {models::icosphere(2), models::torus_grid(20, 13), models::cube_with_hole()}) {
    const OpenMeshRepair r = repair_to_openmesh(soup, lean());
    EXPECT_TRUE(r.fast_path);
    EXPECT_EQ(r.report.faces_out, soup.num_faces());
    expect_same_as_reference(soup, r);
  }
}

TEST(RepairToOpenMesh, every_canonical_case_matches_repair) {
  for (const auto& model : models::canonical_models()) {
    SCOPED_TRACE(model.name);
    const OpenMeshRepair r = repair_to_openmesh(model.soup, lean());
    expect_same_as_reference(model.soup, r);
    const bool clean = model.name == "icosphere" || model.name == "cube_with_hole";
    EXPECT_EQ(r.fast_path, clean);
  }
}

TEST(RepairToOpenMesh, inward_closed_mesh_is_flipped_by_the_full_repair) {
  Soup soup = models::icosphere(1);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    std::swap(soup.corner_vertices[soup.face_begin[f] + 1],
              soup.corner_vertices[soup.face_begin[f] + 2]);
  }
  const OpenMeshRepair r = repair_to_openmesh(soup, lean());
  EXPECT_FALSE(r.fast_path);
  EXPECT_EQ(r.report.faces_flipped, 80u);
  expect_same_as_reference(soup, r);
}

TEST(RepairToOpenMesh, with_reports_the_full_repair_runs) {
  const Soup soup = models::icosphere(1);
  const OpenMeshRepair r = repair_to_openmesh(soup);
  EXPECT_FALSE(r.fast_path);
  EXPECT_TRUE(r.report.after.watertight);
  EXPECT_EQ(r.mesh.n_faces(), 80u);
}

// Two closed solids on one vertex: in no face order may the fast path accept the pinch (its
// linear checks count boundary halfedges; OpenMesh refuses the face that would close the second
// fan around the shared vertex).
TEST(RepairToOpenMesh, pinched_solids_never_take_the_fast_path_in_any_face_order) {
  const Soup hourglass = models::hourglass();
  std::vector<std::size_t> order(hourglass.num_faces());
  for (std::size_t f = 0; f < order.size(); ++f)
    order[f] = f;
  std::size_t orders = 0;
  do {
    Soup soup;
    soup.positions = hourglass.positions;
    for (std::size_t f : order)
      soup.add_polygon(hourglass.polygon(f));
    const OpenMeshRepair r = repair_to_openmesh(soup, lean());
    ASSERT_FALSE(r.fast_path) << "order " << orders;
    ASSERT_EQ(r.mesh.n_vertices(), 8u);
    ++orders;
  } while (std::next_permutation(order.begin(), order.end()));
  EXPECT_EQ(orders, 40320u);
}

// Components are judged one by one: an inward closed sphere next to an outward one (and an open
// patch) sends the soup to the full repair, which flips exactly the inward one.
TEST(RepairToOpenMesh, one_inward_component_among_others_is_flipped) {
  const Soup sphere = models::icosphere(1);
  Soup soup;
  const auto append = [&](const Soup& part, double shift, bool inward, std::size_t faces) {
    const Index base = static_cast<Index>(soup.num_vertices());
    for (const Point& p : part.positions)
      soup.add_vertex(p + Point(shift, 0, 0));
    for (std::size_t f = 0; f < faces; ++f) {
      std::vector<Index> polygon;
      for (Index v : part.polygon(f))
        polygon.push_back(base + v);
      if (inward)
        std::reverse(polygon.begin(), polygon.end());
      soup.add_polygon(polygon);
    }
  };
  append(sphere, 0, false, sphere.num_faces());
  append(sphere, 5, true, sphere.num_faces());
  append(sphere, 10, true, 20);  // open: its orientation is kept
  const OpenMeshRepair r = repair_to_openmesh(soup, lean());
  EXPECT_FALSE(r.fast_path);
  EXPECT_EQ(r.report.faces_flipped, 80u);
  expect_same_as_reference(soup, r);

  Soup outward;  // the same without the inward sphere is clean
  std::swap(soup, outward);
  append(sphere, 0, false, sphere.num_faces());
  append(sphere, 10, true, 20);
  EXPECT_TRUE(repair_to_openmesh(soup, lean()).fast_path);
}
