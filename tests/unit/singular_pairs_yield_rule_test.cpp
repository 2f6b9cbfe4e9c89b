// SPDX-License-Identifier: GPL-3.0-or-later
// Rule of "no new defects" (DESIGN 8a) at orientation: where the pairs made at singular edges make
// a component non-orientable although its faces orient consistently through the input's own
// two-sided edges, those pairs yield (and stitching glues their sides where orientation allows);
// the input's edges are not cut. The kind of Cura's printer platforms (leapfrog_bolt_pro,
// rigidbot, rigidbotbig): a fan wound against its neighbours as written, paired by its written
// winding at an edge with three faces.

#include "rule_support.h"

#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace meshbridge;
using namespace meshbridge::rule_test;

namespace {

// Reduced from leapfrog_bolt_pro_platform.3mf: a fan of three triangles (0-2) in the plane x = 0,
// a bent strip of three (3-5) leaving its edge 0-4, and a long strip of two (6, 7) leaving the
// same edge, so that edge 0-4 has three faces (2, 3, 6). Every other edge has one or two; one
// (0-1, faces 0 and 7) runs the same way in both, so the eight faces orient consistently only
// with 6 and 7 reversed. As written, face 6 runs against face 3 at 0-4 and the angular order
// pairs them; as oriented, they run the same way.
Soup fan_wound_against_its_strip() {
  return from_off(R"(OFF 8 8 0
    0 -1.713 -0.755
    0 -1.825 -0.334
    0 0.637 0.100
    0 -1.279 -1.507
    0 -1.528 -1.150
    -3.001 -2.015 0.526
    -3.000 -0.875 -1.948
    -25.836 -2.042 0.313
    3 0 1 2
    3 2 3 4
    3 2 4 0
    3 5 0 4
    3 5 4 6
    3 6 4 3
    3 7 4 0
    3 7 0 1
  )");
}

// Reduced from the same file, with more of the fan and of the long strip: four edges with three
// faces each (0-4, 1-3, 2-3 and 6-7) and one inconsistently oriented edge (0-1, faces 0 and 5).
// The angular order pairs two sides at each of the four edges by their written windings; one of
// those pairs contradicts the others once the faces are oriented through their own edges.
Soup fan_paired_at_four_edges() {
  return from_off(R"(OFF 13 17 0
    0 -1.713 -0.755
    0 -1.825 -0.334
    0 0.637 0.100
    0 -1.863 0.100
    0 -1.279 -1.507
    0 -1.528 -1.150
    0 -0.218 -2.249
    0 -0.613 -2.065
    -3.001 -2.015 0.526
    -3.000 -0.875 -1.948
    0 -1.825 0.534
    -25.950 -0.066 -2.365
    -25.836 -2.042 0.313
    3 0 1 2
    3 2 1 3
    3 2 4 5
    3 2 5 0
    3 8 3 1
    3 8 1 0
    3 8 0 5
    3 8 5 9
    3 9 5 4
    3 9 7 6
    3 2 7 6
    3 2 10 3
    3 11 6 7
    3 12 5 0
    3 12 0 1
    3 12 1 3
    3 12 3 10
  )");
}

}  // namespace

TEST(SingularPairsYield, a_pair_that_contradicts_the_inputs_own_edges_is_the_one_cut) {
  // Input: 7 boundary edges, one singular edge of 3 faces (one side may stay open), one
  // inconsistently oriented edge. Cutting that edge (the input's own) to keep the singular pair
  // left 10 boundary edges; the singular pair yields instead and its side is glued to the third
  // face: 8 = 7 + 1.
  for_face_orders(fan_wound_against_its_strip(), 20,
                  [](const Soup& soup, const std::vector<Index>&) {
                    const RepairResult r = repair(soup);
                    test_support::expect_repair_invariants(soup, r);
                    EXPECT_EQ(r.report.before.boundary_edges.size(), 7u);
                    EXPECT_EQ(r.report.before.singular_edges.size(), 1u);
                    EXPECT_EQ(r.report.before.inconsistent_edges.size(), 1u);
                    EXPECT_EQ(r.report.faces_out, 8u);
                    EXPECT_EQ(r.report.boundary_edges_after, 8u);
                    EXPECT_EQ(r.report.sides_cut, 1u);
                    EXPECT_EQ(r.report.sides_cut_for_orientation, 2u);
                    EXPECT_EQ(r.report.sides_stitched, 2u);
                    EXPECT_EQ(r.report.nonorientable_after_pairing, 0u);
                    EXPECT_EQ(r.report.after.num_nonorientable_components, 0u);
                    EXPECT_EQ(r.report.after.inconsistent_edges.size(), 0u);
                    EXPECT_EQ(r.report.after.singular_edges.size(), 0u);
                    EXPECT_EQ(r.report.components_after, 1u);
                  });
}

TEST(SingularPairsYield, reversing_every_face_changes_nothing_but_the_winding) {
  const Soup soup = fan_wound_against_its_strip();
  Soup reversed = soup;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    std::reverse(reversed.corner_vertices.begin() + soup.face_begin[f],
                 reversed.corner_vertices.begin() + soup.face_begin[f + 1]);
  const RepairResult a = repair(soup);
  const RepairResult b = repair(reversed);
  EXPECT_EQ(a.report.boundary_edges_after, 8u);
  EXPECT_EQ(b.report.boundary_edges_after, 8u);
  EXPECT_EQ(a.mesh.soup.num_vertices(), b.mesh.soup.num_vertices());
  EXPECT_EQ(b.report.after.inconsistent_edges.size(), 0u);
}

TEST(SingularPairsYield, without_orientation_nothing_is_cut_for_it) {
  // The rule belongs to orientation: with orientation off, every same-running pair is cut as
  // before (the inconsistent edge 0-1 and, as written, nothing at 0-4).
  RepairOptions options;
  options.orient = false;
  options.stitch = false;
  const RepairResult r = repair(fan_wound_against_its_strip(), options);
  test_support::expect_repair_invariants(fan_wound_against_its_strip(), r);
  EXPECT_EQ(r.report.sides_cut_for_orientation, 2u);
  EXPECT_EQ(r.report.boundary_edges_after, 10u);
}

TEST(SingularPairsYield, at_four_odd_edges_the_open_sides_stay_within_the_allowance) {
  // Input: 13 boundary edges and 4 singular edges of 3 faces: at most 13 + 4 = 17 after. Cutting
  // the inconsistent edge left 19; the contradicting singular pairs yield, and stitching glues
  // their sides to the third face of their edge: 17, every face oriented.
  for_face_orders(fan_paired_at_four_edges(), 20, [](const Soup& soup, const std::vector<Index>&) {
    const RepairResult r = repair(soup);
    test_support::expect_repair_invariants(soup, r);
    EXPECT_EQ(r.report.before.boundary_edges.size(), 13u);
    EXPECT_EQ(r.report.before.singular_edges.size(), 4u);
    EXPECT_EQ(r.report.before.inconsistent_edges.size(), 1u);
    EXPECT_EQ(r.report.boundary_edges_after, 17u);
    EXPECT_EQ(r.report.sides_cut, 4u);
    EXPECT_EQ(r.report.sides_cut_for_orientation, 4u);
    EXPECT_EQ(r.report.sides_stitched, 4u);
    EXPECT_EQ(r.report.nonorientable_after_pairing, 0u);
    EXPECT_EQ(r.report.after.num_nonorientable_components, 0u);
    EXPECT_EQ(r.report.after.inconsistent_edges.size(), 0u);
    EXPECT_EQ(r.report.after.singular_edges.size(), 0u);
    EXPECT_EQ(r.report.after.pinch_vertices.size(), 0u);
    EXPECT_EQ(r.report.components_after, 3u);
  });
}

TEST(SingularPairsYield, the_input_non_orientable_through_its_own_edges_is_still_reported) {
  // The rule applies only where the input's own edges orient consistently: a Moebius strip (no
  // singular edge) stays one non-orientable component, its faces as written.
  const RepairResult r = repair(models::moebius_strip());
  EXPECT_EQ(r.report.nonorientable_after_pairing, 1u);
  EXPECT_EQ(r.report.faces_flipped, 0u);
}
