// SPDX-License-Identifier: GPL-3.0-or-later
// Rule: closed shells are oriented by their nesting depth (outer boundaries outward, cavities
// toward the void, islands inside cavities outward again), in every face order.

#include "rule_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <numeric>
#include <vector>

using namespace meshbridge;
using namespace meshbridge::rule_test;

namespace {

// Outer tetrahedron (faces 0-3) with a smaller one inside (faces 4-7), wound as a cavity.
const char* const kTetrahedronWithCavity = R"(OFF
8 8 0
0 0 0  4 0 0  0 4 0  0 0 4  0.5 0.5 0.5  1.5 0.5 0.5  0.5 1.5 0.5  0.5 0.5 1.5
3 0 2 1  3 0 1 3  3 0 3 2  3 1 2 3  3 4 5 6  3 4 7 5  3 4 6 7  3 5 7 6)";

void expect_volumes(const Soup& soup, const std::vector<Index>& to_original,
                    const std::vector<double>& volume_of_original_face,
                    const RepairOptions& options = {}) {
  const Outcome o = repair_and_label(soup, options);
  test_support::expect_repair_invariants(soup, o.result);
  EXPECT_EQ(o.result.report.vertices_split, 0u);
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    EXPECT_NEAR(o.volume[f], volume_of_original_face[to_original[f]], 1e-9) << "face " << f;
}

}  // namespace

TEST(Orientation, cavity_stays_toward_void) {
  const Soup soup = from_off(kTetrahedronWithCavity);
  std::vector<double> expected(8, 64.0 / 6);
  for (int f = 4; f < 8; ++f)
    expected[f] = -1.0 / 6;
  for_face_orders(soup, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
    expect_volumes(s, to_original, expected);
    EXPECT_EQ(repair(s).report.faces_flipped, 0u);
  });
}

TEST(Orientation, cavity_wound_outward_is_ambiguous_and_turned_toward_void_on_request) {
  // Outward inside outward: an insert, or a cavity wound the wrong way. By default it stays as
  // written (material); with AmbiguousNesting::cavity it is turned toward the void.
  Soup soup = from_off(kTetrahedronWithCavity);
  for (std::size_t f = 4; f < 8; ++f)
    soup = with_face_reversed(soup, f);
  RepairOptions cavity;
  cavity.nested_shells = AmbiguousNesting::cavity;
  std::vector<double> as_written(8, 64.0 / 6), expected(8, 64.0 / 6);
  for (int f = 4; f < 8; ++f) {
    as_written[f] = 1.0 / 6;
    expected[f] = -1.0 / 6;
  }
  for_face_orders(soup, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
    expect_volumes(s, to_original, as_written);
    expect_volumes(s, to_original, expected, cavity);
    EXPECT_EQ(repair(s).report.faces_flipped, 0u);
    EXPECT_EQ(repair(s).report.ambiguous_nested_shells, 1u);
    EXPECT_EQ(repair(s, cavity).report.faces_flipped, 4u);
  });
}

TEST(Orientation, cube_with_cubic_cavity_in_either_winding) {
  for (bool cavity_outward : {false, true}) {
    SCOPED_TRACE(cavity_outward ? "cavity given outward" : "cavity given inward");
    Soup soup;
    add_cube(soup, 0, 3, true);
    add_cube(soup, 1, 1, cavity_outward);
    std::vector<double> expected(12, 27.0);
    for (int f = 6; f < 12; ++f)
      expected[f] = -1.0;
    RepairOptions options;  // outward inside outward is ambiguous: asked to be a cavity
    options.nested_shells = AmbiguousNesting::cavity;
    for_face_orders(soup, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
      expect_volumes(s, to_original, expected, options);
    });
  }
}

TEST(Orientation, island_inside_cavity_is_outward_again) {
  // Two levels of nesting, every shell given the wrong way round.
  Soup soup;
  add_cube(soup, 0, 6, false);  // outer boundary, inward
  add_cube(soup, 1, 4, true);   // cavity, outward
  add_cube(soup, 2, 2, false);  // island in the cavity, inward
  std::vector<double> expected(18, 216.0);
  for (int f = 6; f < 12; ++f)
    expected[f] = -64.0;
  for (int f = 12; f < 18; ++f)
    expected[f] = 8.0;
  for_face_orders(soup, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
    expect_volumes(s, to_original, expected);
    EXPECT_EQ(repair(s).report.faces_flipped, 18u);
  });
}

TEST(Orientation, side_by_side_shells_are_not_nested) {
  // Two cubes next to each other and a third touching the first along a face: no nesting.
  Soup soup;
  add_cube(soup, 0, 1, false);
  add_cube(soup, 2, 1, true);
  add_cube(soup, 1, 1, false);  // touches the first cube at one corner point (1,1,1)
  std::vector<double> expected(18, 1.0);
  for_face_orders(soup, 50, [&](const Soup& s, const std::vector<Index>& to_original) {
    const Outcome o = repair_and_label(s);
    test_support::expect_repair_invariants(s, o.result);
    for (std::size_t f = 0; f < s.num_faces(); ++f)
      EXPECT_NEAR(o.volume[f], expected[to_original[f]], 1e-9) << "face " << f;
  });
}

TEST(Orientation, shells_with_faces_wound_either_way_still_nest) {
  // Some faces of both shells given reversed: the nesting test must see each shell as the
  // faces will run once made consistent, not as stored (a winding number over mixed windings
  // is no integer, and the cavity would come out outward).
  Soup soup;
  add_cube(soup, 0, 3, true);
  add_cube(soup, 1, 1, false);
  for (std::size_t f : {1u, 4u, 6u, 9u, 11u})
    soup = with_face_reversed(soup, f);
  std::vector<double> expected(12, 27.0);
  for (int f = 6; f < 12; ++f)
    expected[f] = -1.0;
  for_face_orders(soup, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
    expect_volumes(s, to_original, expected);
  });
}

TEST(Orientation, repairing_the_output_again_reverses_nothing) {
  // Decisions that rounding could tip (a zero-area pillow, a shell touching its container, a
  // model far from the origin) must come out the same on the output, which is stored reversed
  // and renumbered: repair is idempotent.
  std::vector<Soup> cases;
  {
    Soup pillow;  // two triangles back to back on three collinear points: no area, no volume
    const double t = -6.3e-05;
    for (const Point& p : {Point(0, 0, 0), Point(-1, -1, -1), Point(t, t, t)})
      pillow.add_vertex(p);
    pillow.add_polygon({0, 1, 2});
    pillow.add_polygon({0, 0, 1, 2});
    cases.push_back(pillow);
  }
  {
    Soup touching;  // a cavity sharing a face's plane with its container, half the faces wrong
    add_cube(touching, 0, 3, true);
    add_cube(touching, 0, 1, false);
    for (std::size_t f : {0u, 3u, 7u, 8u})
      touching = with_face_reversed(touching, f);
    cases.push_back(touching);
  }
  {
    Soup far;  // nested cubes 1e7 from the origin, both given the wrong way round
    add_cube(far, 1e7, 3, false);
    add_cube(far, 1e7 + 1, 1, true);
    cases.push_back(far);
  }
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE("case " + std::to_string(i));
    const RepairResult once = repair(cases[i]);
    const RepairResult twice = repair(once.mesh.soup);
    EXPECT_EQ(twice.mesh.soup.corner_vertices, once.mesh.soup.corner_vertices);
    EXPECT_EQ(twice.report.faces_flipped, 0u);
  }
  const RepairResult far = repair(cases[2]);
  EXPECT_EQ(far.report.faces_flipped, 12u);  // outer turned outward, cavity toward the void
}

namespace {

// The cube [lo, lo + size]^3 with each side cut into n x n quads (6 n^2 faces, shared corners).
void add_divided_cube(Soup& soup, double lo, double size, int n, bool outward) {
  std::map<std::array<int, 3>, Index> lattice;
  const auto vertex = [&](std::array<int, 3> k) {
    const auto [it, added] = lattice.try_emplace(k, static_cast<Index>(soup.num_vertices()));
    if (added)
      soup.add_vertex({lo + size * k[0] / n, lo + size * k[1] / n, lo + size * k[2] / n});
    return it->second;
  };
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  const auto corner = [n](int c) {
    return std::array<int, 3>{n * (c & 1), n * ((c >> 1) & 1), n * ((c >> 2) & 1)};
  };
  for (const auto& q : quads) {
    const auto p0 = corner(q[0]), p1 = corner(q[1]), p3 = corner(q[3]);
    const auto at = [&](int i, int j) {
      std::array<int, 3> k;
      for (int a = 0; a < 3; ++a)
        k[a] = p0[a] + (p1[a] - p0[a]) * i / n + (p3[a] - p0[a]) * j / n;
      return vertex(k);
    };
    for (int i = 0; i < n; ++i) {
      for (int j = 0; j < n; ++j) {
        std::vector<Index> polygon{at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
        if (!outward)
          std::reverse(polygon.begin(), polygon.end());
        soup.add_polygon(polygon);
      }
    }
  }
}

}  // namespace

TEST(Orientation, many_cavities_in_a_finely_divided_block_face_the_void) {
  // A block of 8 x 8 quads a side (384 faces: its inside test counts ray crossings), given
  // inward, with 4 x 4 x 4 cubic cavities given outward and an island in every other cavity
  // given inward: every shell wrong. Cavities sit on the block's grid lines, so rays from their
  // faces' centroids also meet the block's edges (undecided there, decided elsewhere).
  Soup soup;
  add_divided_cube(soup, 0, 16, 8, false);
  std::vector<double> expected(384, 16.0 * 16 * 16);
  std::size_t islands = 0;
  for (int x = 0; x < 4; ++x) {
    for (int y = 0; y < 4; ++y) {
      for (int z = 0; z < 4; ++z) {
        Soup cube;
        add_cube(cube, 0, 3, true);
        for (Point& p : cube.positions)
          p += Point(1 + 4 * x, 1 + 4 * y, 1 + 4 * z) - Point(0, 0, 0);
        const Index base = static_cast<Index>(soup.num_vertices());
        for (const Point& p : cube.positions)
          soup.add_vertex(p);
        for (std::size_t f = 0; f < cube.num_faces(); ++f) {
          std::vector<Index> polygon;
          for (Index v : cube.polygon(f))
            polygon.push_back(base + v);
          soup.add_polygon(polygon);
          expected.push_back(-27.0);
        }
        if ((x + y + z) % 2 == 0) {
          Soup island;
          add_cube(island, 0, 1, false);
          const Index first = static_cast<Index>(soup.num_vertices());
          for (const Point& p : island.positions)
            soup.add_vertex(p + Point(2 + 4 * x, 2 + 4 * y, 2 + 4 * z));
          for (std::size_t f = 0; f < island.num_faces(); ++f) {
            std::vector<Index> polygon;
            for (Index v : island.polygon(f))
              polygon.push_back(first + v);
            soup.add_polygon(polygon);
            expected.push_back(1.0);
          }
          ++islands;
        }
      }
    }
  }
  std::vector<Index> identity(soup.num_faces());
  std::iota(identity.begin(), identity.end(), Index(0));
  expect_volumes(soup, identity, expected);
  EXPECT_EQ(repair(soup).report.faces_flipped, soup.num_faces());
  EXPECT_EQ(islands, 32u);
  for_face_orders(soup, 3, [&](const Soup& s, const std::vector<Index>& to_original) {
    expect_volumes(s, to_original, expected);
  });
}

TEST(Orientation, cavity_on_the_grid_lines_of_a_finely_divided_block_faces_the_void) {
  // A block of 10 x 10 quads a side (600 faces: inside tests by rays) and a cavity whose faces'
  // centres lie on the block's grid lines and on its quads' diagonals: a ray along an axis would
  // meet an edge from every sample point and leave the cavity undecided (it stayed a solid).
  for (bool cavity_outward : {true, false}) {
    SCOPED_TRACE(cavity_outward ? "cavity given outward" : "cavity given inward");
    Soup soup;
    add_divided_cube(soup, 0, 100, 10, true);
    add_cube(soup, 30, 10, cavity_outward);
    std::vector<double> expected(600, 1e6);
    expected.insert(expected.end(), 6, -1000.0);
    std::vector<Index> identity(soup.num_faces());
    std::iota(identity.begin(), identity.end(), Index(0));
    RepairOptions cavity;  // outward inside outward is ambiguous: asked to be a cavity
    cavity.nested_shells = AmbiguousNesting::cavity;
    expect_volumes(soup, identity, expected, cavity);
    EXPECT_EQ(repair(soup, cavity).report.faces_flipped, cavity_outward ? 6u : 0u);
    EXPECT_EQ(repair(soup).report.ambiguous_nested_shells, cavity_outward ? 1u : 0u);
  }
}
