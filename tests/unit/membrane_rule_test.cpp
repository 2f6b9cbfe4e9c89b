// SPDX-License-Identifier: GPL-3.0-or-later
// Rule: a face with material on both sides (a membrane, an interface kept by a union) is the
// leftover whatever its winding; the solid around it closes.

#include "rule_support.h"

#include <gtest/gtest.h>

using namespace meshbridge;
using namespace meshbridge::rule_test;

namespace {

// The outer surface of a 1x1x3 box (faces 0-9, rings at z = 0, 1, 3) and the square at z = 1.
const char* const kBoxWithMembrane = R"(OFF
12 11 0
0 0 0  1 0 0  1 1 0  0 1 0  0 0 1  1 0 1  1 1 1  0 1 1  0 0 3  1 0 3  1 1 3  0 1 3
4 3 2 1 0  4 0 1 5 4  4 1 2 6 5  4 2 3 7 6  4 3 0 4 7  4 4 5 9 8  4 5 6 10 9
4 6 7 11 10  4 7 4 8 11  4 8 9 10 11  4 4 5 6 7)";

}  // namespace

TEST(PairContenders, membrane_inside_solid_is_leftover) {
  const Soup given = from_off(kBoxWithMembrane);
  for (bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "membrane wound down" : "membrane wound up");
    const Soup soup = reversed ? with_face_reversed(given, 10) : given;
    for_face_orders(soup, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
      const Outcome o = repair_and_label(s);
      test_support::expect_repair_invariants(s, o.result);
      EXPECT_EQ(o.result.mesh.soup.num_vertices(), 16u);
      EXPECT_EQ(o.result.report.components_after, 2u);
      for (std::size_t f = 0; f < s.num_faces(); ++f) {
        if (to_original[f] == 10) {  // a loose sheet: a component of its own
          EXPECT_NE(o.component[f], o.component[(f + 1) % s.num_faces()]);
        } else {
          EXPECT_NEAR(o.volume[f], 3.0, 1e-9) << "face " << to_original[f];
        }
      }
    });
  }
}

TEST(PairContenders, interface_between_two_cubes_is_leftover) {
  // A 2x1x1 bar given as its outer surface (10 quads) plus the unit square at x = 1 between its
  // two halves: the interface a union kept, in a checkerboard of two cells.
  Soup soup;
  for (int i = 0; i < 12; ++i)
    soup.add_vertex({double(i % 3), double((i / 3) % 2), double(i / 6)});
  // vertex (x, y, z) = x + 3y + 6z
  const auto v = [](int x, int y, int z) { return static_cast<Index>(x + 3 * y + 6 * z); };
  for (int x = 0; x < 2; ++x) {
    soup.add_polygon({v(x, 0, 0), v(x, 1, 0), v(x + 1, 1, 0), v(x + 1, 0, 0)});  // bottom
    soup.add_polygon({v(x, 0, 1), v(x + 1, 0, 1), v(x + 1, 1, 1), v(x, 1, 1)});  // top
    soup.add_polygon({v(x, 0, 0), v(x + 1, 0, 0), v(x + 1, 0, 1), v(x, 0, 1)});  // front
    soup.add_polygon({v(x, 1, 0), v(x, 1, 1), v(x + 1, 1, 1), v(x + 1, 1, 0)});  // back
  }
  soup.add_polygon({v(0, 0, 0), v(0, 0, 1), v(0, 1, 1), v(0, 1, 0)});  // end x = 0
  soup.add_polygon({v(2, 0, 0), v(2, 1, 0), v(2, 1, 1), v(2, 0, 1)});  // end x = 2
  const Index interface_face = static_cast<Index>(soup.num_faces());
  soup.add_polygon({v(1, 0, 0), v(1, 1, 0), v(1, 1, 1), v(1, 0, 1)});
  for (bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "interface reversed" : "interface as given");
    const Soup model = reversed ? with_face_reversed(soup, interface_face) : soup;
    for_face_orders(model, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
      const Outcome o = repair_and_label(s);
      test_support::expect_repair_invariants(s, o.result);
      EXPECT_EQ(o.result.mesh.soup.num_vertices(), 16u);
      EXPECT_EQ(o.result.report.components_after, 2u);
      for (std::size_t f = 0; f < s.num_faces(); ++f) {
        if (to_original[f] == interface_face) {
          EXPECT_NE(o.component[f], o.component[(f + 1) % s.num_faces()]);
        } else {
          EXPECT_NEAR(o.volume[f], 2.0, 1e-9) << "face " << to_original[f];
        }
      }
    });
  }
}
