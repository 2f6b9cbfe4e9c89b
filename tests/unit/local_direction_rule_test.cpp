// SPDX-License-Identifier: GPL-3.0-or-later
// Rules: the angular order at an edge uses each face's own direction where it leaves that edge
// (a bent polygon sorts like its triangulation), and faces of (near) zero area there take no
// part in ordering the others.

#include "rule_support.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace meshbridge;
using namespace meshbridge::rule_test;

namespace {

// A plate of two quads (faces 0, 1) and a rib (face 2): a hexagon that leaves the joint edge
// 10 degrees above the plate and then bends down below it.
const char* const kPlateWithBentRib = R"(OFF
10 3 0
0 0 0  0 1 0  1 0 0  1 1 0  -1 0 0  -1 1 0  1 0 0.176327  1 1 0.176327  3 0 -0.5  3 1 -0.5
4 0 2 3 1  4 4 0 1 5  6 0 6 8 9 7 1)";

// A plate of two quads (faces 0, 2), a rib (face 1) and a sliver along the joint (face 3).
const char* const kPlateWithSliver = R"(OFF
9 4 0
0 0 0  0 1 0  1 0 0  1 1 0  -1 0 0  -1 1 0  0 0 1  0 1 1  0 0.5 0
4 0 2 3 1  4 0 1 7 6  4 4 0 1 5  3 0 8 1)";

// Expects the plate faces (original a, b) in one piece and the rib (original r) apart.
void expect_plate_whole(const Soup& s, const std::vector<Index>& to_original, Index a, Index b,
                        Index rib) {
  const Outcome o = repair_and_label(s);
  test_support::expect_repair_invariants(s, o.result);
  std::vector<Index> component(s.num_faces());
  for (std::size_t f = 0; f < s.num_faces(); ++f)
    component[to_original[f]] = o.component[f];
  EXPECT_EQ(component[a], component[b]);
  if (rib != kNoIndex)
    EXPECT_NE(component[a], component[rib]);
}

}  // namespace

TEST(PairContenders, bent_polygon_sorts_by_its_direction_at_the_edge) {
  for_face_orders(from_off(kPlateWithBentRib), 200,
                  [&](const Soup& s, const std::vector<Index>& to_original) {
                    expect_plate_whole(s, to_original, 0, 1, 2);
                  });
}

TEST(PairContenders, bent_polygon_sorts_like_its_planar_version) {
  // The same rib made planar (10 degrees up all the way) gives the same pieces.
  Soup planar = from_off(kPlateWithBentRib);
  planar.positions[8] = {3, 0, 0.528981};
  planar.positions[9] = {3, 1, 0.528981};
  for_face_orders(planar, 50, [&](const Soup& s, const std::vector<Index>& to_original) {
    expect_plate_whole(s, to_original, 0, 1, 2);
  });
}

TEST(PairContenders, quad_rib_bent_by_one_degree_sorts_like_its_triangulations) {
  // A quad rib whose far edge is twisted: it leaves the joint 1 degree below the plate at one
  // end and 3 degrees below at the other. Both triangulations put the triangle at the joint
  // between 1 and 3 degrees below; the quad sorts there too, so all three give the same pieces,
  // in every face order. Then the same with the rib 1 and 3 degrees above.
  for (double sign : {-1.0, 1.0}) {
    SCOPED_TRACE(sign < 0 ? "below" : "above");
    Soup points;
    points.positions = from_off(kPlateWithBentRib).positions;
    points.positions[6] = {1, 0, sign * std::tan(1.0 * 3.14159265358979 / 180)};
    points.positions[7] = {1, 1, sign * std::tan(3.0 * 3.14159265358979 / 180)};
    const auto model = [&](std::vector<std::vector<Index>> rib) {
      Soup soup;
      soup.positions = points.positions;
      soup.add_polygon({0, 2, 3, 1});
      soup.add_polygon({4, 0, 1, 5});
      for (const auto& polygon : rib)
        soup.add_polygon(polygon);
      return soup;
    };
    const Soup quad = model({{0, 6, 7, 1}});
    const Soup split_61 = model({{0, 6, 1}, {6, 7, 1}});
    const Soup split_07 = model({{0, 6, 7}, {0, 7, 1}});
    const Outcome reference = repair_and_label(quad);
    const bool plate_whole = reference.component[0] == reference.component[1];
    const bool rib_on_0 = reference.component[0] == reference.component[2];
    for (const Soup* triangulated : {&split_61, &split_07}) {
      const Outcome o = repair_and_label(*triangulated);
      // the rib's triangle at the joint is face 2 in split_61 and face 3 in split_07
      const Index at_joint = triangulated == &split_61 ? 2 : 3;
      EXPECT_EQ(o.component[0] == o.component[1], plate_whole);
      EXPECT_EQ(o.component[0] == o.component[at_joint], rib_on_0);
    }
    for_face_orders(quad, 50, [&](const Soup& s, const std::vector<Index>& to_original) {
      const Outcome o = repair_and_label(s);
      test_support::expect_repair_invariants(s, o.result);
      std::vector<Index> component(3);
      for (std::size_t f = 0; f < 3; ++f)
        component[to_original[f]] = o.component[f];
      EXPECT_EQ(component[0] == component[1], plate_whole);
      EXPECT_EQ(component[0] == component[2], rib_on_0);
    });
  }
}

TEST(PairContenders, zero_area_face_takes_no_part_in_ordering) {
  for_face_orders(from_off(kPlateWithSliver), 200,
                  [&](const Soup& s, const std::vector<Index>& to_original) {
                    expect_plate_whole(s, to_original, 0, 2, kNoIndex);
                  });
}

TEST(PairContenders, near_zero_area_face_takes_no_part_in_ordering) {
  Soup soup = from_off(kPlateWithSliver);
  soup.positions[8] = {1e-10, 0.5, 0};  // a sliver 1e-10 wide
  for_face_orders(soup, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
    expect_plate_whole(s, to_original, 0, 2, kNoIndex);
  });
}
