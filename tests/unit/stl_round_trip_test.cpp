// SPDX-License-Identifier: GPL-3.0-or-later
// What a repaired mesh becomes through STL, and the smallest separation that survives float32.

#include "meshbridge/stl_round_trip.h"
#include "meshbridge/close_gaps.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"
#include "meshbridge/separate_copies.h"

#include <gtest/gtest.h>

#include <cmath>

namespace meshbridge {
namespace {

// Three tetrahedra sharing the edge 0-1, on a printer bed (coordinates 140..160 mm).
Soup three_tetrahedra_on_one_edge() {
  Soup soup;
  soup.add_vertex({150, 150, 150});
  soup.add_vertex({150, 150, 160});
  for (int k = 0; k < 3; ++k) {
    const double a = 2 * M_PI * k / 3, b = a + 0.6;
    const Index p = soup.add_vertex({150 + 10 * std::cos(a), 150 + 10 * std::sin(a), 155});
    const Index q = soup.add_vertex({150 + 10 * std::cos(b), 150 + 10 * std::sin(b), 155});
    soup.add_polygon({0, 1, p});
    soup.add_polygon({0, q, 1});
    soup.add_polygon({0, p, q});
    soup.add_polygon({1, q, p});
  }
  return soup;
}

TEST(StlRoundTrip, repaired_split_vertices_weld_again_without_separation) {
  const RepairResult r = repair(three_tetrahedra_on_one_edge());
  EXPECT_EQ(r.report.vertices_split, 4u);
  EXPECT_EQ(r.report.after.singular_edges.size(), 0u);
  const Soup back = stl_round_trip(r.mesh.soup);
  EXPECT_EQ(back.num_vertices(), 8u);  // the 4 copies merged again
  EXPECT_EQ(back.num_faces(), 12u);
  // 1 singular edge (6 sides) and its 2 vertices come back.
  EXPECT_EQ(singular_elements_after_stl_round_trip(r.mesh.soup), 3u);
}

TEST(StlRoundTrip, smallest_separation_at_160_mm_is_one_float_ulp) {
  const RepairResult r = repair(three_tetrahedra_on_one_edge());
  const double smallest = smallest_stl_separation(r.mesh);
  EXPECT_EQ(smallest, std::ldexp(1.0, -16));  // float32 spacing at 128..256
  IndexedMesh separated = r.mesh;
  EXPECT_EQ(separate_split_vertices(separated, smallest), 6u);  // 3 copies each of 0 and 1
  EXPECT_EQ(singular_elements_after_stl_round_trip(separated.soup), 0u);
  // Half of it, or the 1e-6 a user might type, does not survive float32 at 160 mm.
  for (double too_small : {smallest / 2, 1e-6}) {
    IndexedMesh trial = r.mesh;
    separate_split_vertices(trial, too_small);
    EXPECT_EQ(singular_elements_after_stl_round_trip(trial.soup), 3u) << too_small;
  }
}

TEST(StlRoundTrip, copies_at_the_origin_move_by_the_models_float_spacing_not_a_denormal) {
  // The hourglass's pinch vertex is the origin; the model spans [-1, 1].
  const RepairResult r = repair(models::hourglass());
  ASSERT_GT(r.report.vertices_split, 0u);
  const double smallest = smallest_stl_separation(r.mesh);
  EXPECT_GE(smallest, std::ldexp(1.0, -23));  // float32 spacing at 1
  IndexedMesh separated = r.mesh;
  separate_split_vertices(separated, smallest);
  EXPECT_EQ(singular_elements_after_stl_round_trip(separated.soup), 0u);
}

TEST(StlRoundTrip, the_separation_for_a_reread_keeps_copies_beyond_the_default_weld) {
  // The bowtie's copies of its pinch vertex are boundary vertices: one float spacing apart, the
  // default gap closing of a repair that reads the STL back would weld them into the pinch again.
  const RepairResult r = repair(models::bowtie());
  ASSERT_GT(r.report.vertices_split, 0u);
  const double smallest = smallest_stl_separation(r.mesh);
  const double for_reread = stl_separation_surviving_weld(r.mesh);
  EXPECT_GT(for_reread, smallest);
  for (const auto& [distance, welds] : {std::pair{smallest, true}, std::pair{for_reread, false}}) {
    IndexedMesh separated = r.mesh;
    separate_split_vertices(separated, distance);
    const ClosedGaps reread = close_gaps(stl_round_trip(separated.soup));
    EXPECT_EQ(reread.report.vertices_welded > 0, welds) << distance;
    EXPECT_EQ(detect_defects(reread.soup).num_singular_vertices() > 0, welds) << distance;
  }
  // An explicit tolerance is honoured: 0 (gap closing off) needs no more than STL itself.
  CloseGapsOptions off;
  off.tolerance = 0;
  EXPECT_EQ(stl_separation_surviving_weld(r.mesh, off), smallest);
}

TEST(StlRoundTrip, nothing_split_needs_no_separation) {
  Soup soup;
  soup.add_vertex({0, 0, 0});
  soup.add_vertex({1, 0, 0});
  soup.add_vertex({0, 1, 0});
  soup.add_polygon({0, 1, 2});
  EXPECT_EQ(smallest_stl_separation(repair(soup).mesh), 0.0);
}

}  // namespace
}  // namespace meshbridge
