// SPDX-License-Identifier: GPL-3.0-or-later
// Repair with several threads (MESHBRIDGE_THREADS): the input's detection beside the pipeline,
// singular edges sorted and paired in shares, shells' nesting depths in shares, face checks
// beside the rest of detection. Every thread count must give the one-thread result exactly:
// the mesh, its origins and every count of the report. The models are large enough that each
// step is cut into parts (thousands of singular edges and of closed shells).

#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <string>

using namespace meshbridge;

namespace {

using test_support::ThreadsSetting;

//! Adds an axis-aligned cube of edge `size` at `corner`, facing outward (or inward: a cavity).
void add_cube(Soup& soup, const Point& corner, double size, bool inward) {
  const Index base = static_cast<Index>(soup.num_vertices());
  for (int i = 0; i < 8; ++i)
    soup.add_vertex(corner + Point(i & 1, (i >> 1) & 1, (i >> 2) & 1) * size);
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    for (const auto& t : {std::array<int, 3>{q[0], q[1], q[2]}, {q[0], q[2], q[3]}}) {
      if (inward)
        soup.add_polygon({base + Index(t[0]), base + Index(t[2]), base + Index(t[1])});
      else
        soup.add_polygon({base + Index(t[0]), base + Index(t[1]), base + Index(t[2])});
    }
  }
}

//! 48 x 48 solids, each a cube with a cavity; every other one wound inside out (so orientation
//! turns it, with its cavity, by nesting depth): 4,608 closed shells.
Soup hollow_cubes() {
  Soup soup;
  for (int i = 0; i < 48; ++i) {
    for (int j = 0; j < 48; ++j) {
      const bool flipped = (i + j) % 2 == 1;
      add_cube(soup, Point(3 * i, 3 * j, 0), 2, flipped);
      add_cube(soup, Point(3 * i + 0.5, 3 * j + 0.5, 0.5), 1, !flipped);
    }
  }
  return soup;
}

std::string counts(const DefectReport& r) {
  return std::to_string(r.singular_edges.size()) + " singular edges, " +
         std::to_string(r.num_singular_vertices()) + " singular vertices, " +
         std::to_string(r.boundary_edges.size()) + " boundary edges, " +
         std::to_string(r.num_components) + " components, " +
         std::to_string(r.zero_area_faces.size()) + " zero-area, " +
         std::to_string(r.duplicate_faces.size()) + " duplicates, " +
         std::to_string(r.num_nonorientable_components) + " non-orientable";
}

void expect_same_for_every_thread_count(const Soup& input) {
  const auto run = [&input](unsigned threads) {
    const ThreadsSetting setting(threads);
    Soup copy = input;  // the consuming overload: the path the CLI takes
    return repair(std::move(copy));
  };
  const RepairResult one = run(1);
  for (unsigned threads : {2u, 3u, 5u}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    const RepairResult many = run(threads);
    EXPECT_EQ(to_text(many.report), to_text(one.report));
    EXPECT_EQ(counts(many.report.before), counts(one.report.before));
    EXPECT_EQ(counts(many.report.after), counts(one.report.after));
    test_support::expect_same_mesh(many.mesh, one.mesh);
  }
}

}  // namespace

TEST(ParallelRepair, singular_edges_paired_in_shares_give_the_one_thread_mesh) {
  // 24^3 / 2 cubes meeting at about 40,000 singular edges, faces shuffled, a duplicate face.
  Soup board = test_support::shuffled(models::checkerboard_cubes(24), 11);
  board.add_polygon({board.corner_vertices[0], board.corner_vertices[1], board.corner_vertices[2]});
  const RepairResult one = [&] {
    const ThreadsSetting setting(1);
    return repair(board);
  }();
  ASSERT_GT(one.report.before.singular_edges.size(), 4u * 4096);
  EXPECT_EQ(one.report.before.duplicate_faces.size(), 1u);
  expect_same_for_every_thread_count(board);
}

TEST(ParallelRepair, shells_nested_in_shares_give_the_one_thread_mesh) {
  const Soup hollow = hollow_cubes();
  const RepairResult one = [&] {
    const ThreadsSetting setting(1);
    return repair(hollow);
  }();
  // Half the solids were inside out: their 12 faces and their cavity's 12 are turned.
  EXPECT_EQ(one.report.faces_flipped, 24u * 48 * 48 / 2);
  EXPECT_EQ(one.report.after.num_components, 2u * 48 * 48);
  EXPECT_TRUE(one.report.after.watertight);
  expect_same_for_every_thread_count(hollow);
}
