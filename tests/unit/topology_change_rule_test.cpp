// SPDX-License-Identifier: GPL-3.0-or-later
// A midpoint split says what it adds (issue 27, a new user's review): a vertex per edge, a corner
// to each of the pair's polygons.

#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"
#include "meshbridge/report_json.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <string>

using namespace meshbridge;
using meshbridge::test_support::expect_repair_invariants;

// The UR20 forearm (tests/data/realworld2): its repair splits 4 edges at their midpoint: 4 vertices
// added, and each of the 8 triangles of those pairs becomes a quad (the input is all triangles).
TEST(MidpointSplits, the_ur20_forearm_says_its_4_midpoints_make_8_quads) {
  const Soup s =
      read_soup(std::string(MESHBRIDGE_REALWORLD_DIR) + "2/ur_ur20_forearm_collision.stl");
  const RepairResult r = repair(s);
  expect_repair_invariants(s, r);
  const std::string text = to_text(r.report);
  const std::string json = repair_report_json("ur20.stl", "", r.report);
  ASSERT_EQ(r.report.edges_split_to_stay_manifold, 4u);
  EXPECT_EQ(r.report.faces_given_midpoints, 8u);
  EXPECT_EQ(r.report.triangles_given_midpoints, 8u);
  std::size_t quads = 0, midpoints = 0;
  for (std::size_t f = 0; f < r.mesh.soup.num_faces(); ++f)
    quads += r.mesh.soup.arity(f) == 4 ? 1 : 0;
  for (Index o : r.mesh.vertex_origin)
    midpoints += o == kNoIndex ? 1 : 0;
  EXPECT_EQ(quads, 8u);
  EXPECT_EQ(midpoints, 4u);
  EXPECT_NE(text.find("4 edges split at the midpoint instead: 4 vertices added, 8 triangles became "
                      "quads), "),
            std::string::npos)
      << text;
  EXPECT_NE(json.find("\"faces_given_midpoints\":8,\"triangles_given_midpoints\":8"),
            std::string::npos);
}

TEST(MidpointSplits, none_leaves_the_sides_line_as_it_was) {
  const RepairResult r = repair(models::two_cubes_sharing_edge());
  EXPECT_EQ(r.report.faces_given_midpoints, 0u);
  EXPECT_EQ(r.report.triangles_given_midpoints, 0u);
  EXPECT_NE(to_text(r.report).find("0 edges split at the midpoint instead), "), std::string::npos)
      << to_text(r.report);
}
