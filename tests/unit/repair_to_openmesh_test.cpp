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

// `part` appended to `soup`: its first `faces` polygons (all by default), scaled by `scale` about
// the origin, moved by `shift` along x, reversed if `inward`.
void append_part(Soup& soup, const Soup& part, double scale, double shift, bool inward,
                 std::size_t faces = std::size_t(-1)) {
  const Index base = static_cast<Index>(soup.num_vertices());
  for (const Point& p : part.positions)
    soup.add_vertex(p * scale + Point(shift, 0, 0));
  for (std::size_t f = 0; f < part.num_faces() && f < faces; ++f) {
    std::vector<Index> polygon;
    for (Index v : part.polygon(f))
      polygon.push_back(base + v);
    if (inward)
      std::reverse(polygon.begin(), polygon.end());
    soup.add_polygon(polygon);
  }
}

}  // namespace

TEST(RepairToOpenMesh, clean_input_takes_the_fast_path_and_matches_repair) {
  for (const Soup& soup : {models::icosphere(2), models::torus_grid(20, 13)}) {
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
    const bool clean = model.name == "icosphere";  // cube_with_hole is open: the full repair
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
  append_part(soup, sphere, 1.0, 0, false);
  append_part(soup, sphere, 1.0, 5, true);
  append_part(soup, sphere, 1.0, 10, true, 20);  // open: its orientation is kept
  const OpenMeshRepair r = repair_to_openmesh(soup, lean());
  EXPECT_FALSE(r.fast_path);
  EXPECT_EQ(r.report.faces_flipped, 80u);
  expect_same_as_reference(soup, r);

  Soup outward;  // the closed spheres both outward are clean
  append_part(outward, sphere, 1.0, 0, false);
  append_part(outward, sphere, 1.0, 5, false);
  EXPECT_TRUE(repair_to_openmesh(outward, lean()).fast_path);
}

TEST(RepairToOpenMesh, a_cavity_wound_outward_is_turned_inward_as_repair_does) {
  // A hollow ball: both shells outward, so the inner one faces into the material. Ambiguous
  // (an insert, or a cavity wound the wrong way): kept as written by default, turned inward
  // when asked for cavities, as repair does either way.
  Soup soup;
  append_part(soup, models::icosphere(1), 2.0, 0, false);
  append_part(soup, models::icosphere(1), 1.0, 0, false);
  RepairOptions cavity = lean();
  cavity.nested_shells = AmbiguousNesting::cavity;
  const OpenMeshRepair r = repair_to_openmesh(soup, cavity);
  EXPECT_FALSE(r.fast_path);
  EXPECT_EQ(r.report.faces_flipped, models::icosphere(1).num_faces());
  EXPECT_EQ(r.report.ambiguous_nested_shells, 1u);
  const OpenMeshRepair kept = repair_to_openmesh(soup, lean());
  EXPECT_EQ(kept.report.faces_flipped, 0u);
  expect_same_as_reference(soup, kept);
}

TEST(RepairToOpenMesh, a_crack_is_welded_as_repair_does) {
  // The open cube with its bottom rim cracked: the four side faces use copies of the bottom's
  // four vertices moved by 1e-9. Manifold as it stands; gap closing welds the copies back.
  Soup soup = models::cube_with_hole();
  const std::size_t n = soup.num_vertices();
  std::vector<Index> copy(n, kNoIndex);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    bool bottom = true;
    for (Index v : soup.polygon(f))
      bottom = bottom && soup.positions[v][2] == 0;
    if (bottom)
      continue;
    for (std::size_t k = soup.face_begin[f]; k < soup.face_begin[f + 1]; ++k) {
      const Index v = soup.corner_vertices[k];
      if (v >= n || soup.positions[v][2] != 0)
        continue;
      if (copy[v] == kNoIndex)
        copy[v] = soup.add_vertex(soup.positions[v] + Point(1e-9, 0, 0));
      soup.corner_vertices[k] = copy[v];
    }
  }
  ASSERT_EQ(soup.num_vertices(), n + 4);
  const OpenMeshRepair r = repair_to_openmesh(soup, lean());
  EXPECT_FALSE(r.fast_path);  // open: never the fast path
  EXPECT_EQ(r.report.gaps.vertices_welded, 4u);
  expect_same_as_reference(soup, r);
}

TEST(RepairToOpenMesh, an_open_part_wound_inward_gets_what_repair_gives) {
  Soup soup;
  append_part(soup, models::cube_with_hole(), 1.0, 0, true);
  const OpenMeshRepair r = repair_to_openmesh(soup, lean());
  EXPECT_FALSE(r.fast_path);
  expect_same_as_reference(soup, r);
}

TEST(RepairToOpenMesh, shells_whose_boxes_meet_take_the_full_repair_shells_apart_do_not) {
  // Two outward balls side by side whose boxes overlap (centres 1.5 apart, radius 1) but that
  // do not nest: the full repair finds nothing to do either.
  Soup near;
  append_part(near, models::icosphere(1), 1.0, 0, false);
  append_part(near, models::icosphere(1), 1.0, 1.5, false);
  const OpenMeshRepair r = repair_to_openmesh(near, lean());
  EXPECT_FALSE(r.fast_path);
  EXPECT_EQ(r.report.faces_flipped, 0u);
  expect_same_as_reference(near, r);
  // 30 balls in a row, 3 apart: no two boxes meet.
  Soup row;
  for (int k = 0; k < 30; ++k)
    append_part(row, models::icosphere(1), 1.0, 3.0 * k, false);
  const OpenMeshRepair apart = repair_to_openmesh(row, lean());
  EXPECT_TRUE(apart.fast_path);
  expect_same_as_reference(row, apart);
}
