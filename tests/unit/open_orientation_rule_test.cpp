// SPDX-License-Identifier: GPL-3.0-or-later
// Rule: open components are oriented by the best volume/winding evidence, not by a majority of
// their faces.

#include "rule_support.h"

#include <gtest/gtest.h>

using namespace meshbridge;
using namespace meshbridge::rule_test;

namespace {

// A 2x1x1 box whose top is two quads while the sides see one long edge (a T-junction crack);
// the faces' windings are mixed, most of them inward.
const char* const kCrackedBox = R"(OFF
10 7 0
0 0 0  2 0 0  2 1 0  0 1 0  0 0 1  2 0 1  2 1 1  0 1 1  1 0 1  1 1 1
4 1 2 3 0  4 7 9 8 4  4 9 6 5 8  4 4 5 1 0  4 3 7 6 2  4 0 4 7 3  4 1 2 6 5)";

}  // namespace

TEST(Orientation, open_box_with_crack_is_oriented_by_its_volume) {
  for_face_orders(from_off(kCrackedBox), 200, [&](const Soup& s, const std::vector<Index>&) {
    const Outcome o = repair_and_label(s);
    test_support::expect_repair_invariants(s, o.result);
    for (std::size_t f = 0; f < s.num_faces(); ++f)
      EXPECT_NEAR(o.volume[f], 2.0, 1e-9) << "face " << f;
  });
}

TEST(Orientation, flat_sheet_keeps_the_winding_of_most_of_its_area) {
  // One big quad and two small ones in a plane, the big one the other way: no volume, so the
  // area decides (a majority of faces would reverse the big one).
  Soup soup;
  for (double x : {0.0, 4.0, 5.0, 6.0})
    for (double y : {0.0, 1.0})
      soup.add_vertex({x, y, 0});
  // vertices: (x index i, y index j) = 2i + j
  soup.add_polygon({0, 1, 3, 2});  // big quad [0,4]x[0,1], normal -z
  soup.add_polygon({2, 4, 5, 3});  // [4,5], normal +z
  soup.add_polygon({4, 6, 7, 5});  // [5,6], normal +z
  for_face_orders(soup, 24, [&](const Soup& s, const std::vector<Index>& to_original) {
    const RepairResult r = repair(s);
    test_support::expect_repair_invariants(s, r);
    EXPECT_EQ(r.report.faces_flipped, 2u);
    for (std::size_t f = 0; f < s.num_faces(); ++f) {
      const bool was_flipped = to_original[f] != 0;
      const PolygonView in = s.polygon(f);
      const PolygonView out = r.mesh.soup.polygon(f);
      EXPECT_EQ(was_flipped, !std::equal(in.begin(), in.end(), out.begin())) << "face " << f;
    }
  });
}
