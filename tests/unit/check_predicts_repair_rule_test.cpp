// SPDX-License-Identifier: GPL-3.0-or-later
// Rule (DESIGN 8a, issue "no new defects" item 5): check predicts repair. preview_repair() says
// that repair would change nothing exactly when repair returns the input as it was, and its
// counts are repair's, in every face order, winding and offset.

#include "rule_support.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/preview_repair.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

using namespace meshbridge;
using namespace meshbridge::rule_test;

namespace {

// An n x n grid of unit quads in the plane z = 0: an open sheet, nothing to repair.
Soup grid(int n, double offset) {
  Soup soup;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      soup.add_vertex({offset + i, offset + j, offset});
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const Index a = static_cast<Index>(j * (n + 1) + i);
      soup.add_polygon(
          {a, a + 1, a + 1 + static_cast<Index>(n + 1), a + static_cast<Index>(n + 1)});
    }
  }
  return soup;
}

Soup reversed(const Soup& soup) {
  Soup out = soup;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    out = with_face_reversed(out, f);
  return out;
}

// The preview of `soup` against the repair itself: the same verdict, the same counts, and when
// nothing would change the output is the input, polygon for polygon.
void expect_prediction(const Soup& soup, bool changes) {
  OrientationPreview orientation;
  const DefectReport before = detect_defects(soup, &orientation);
  const RepairPreview preview = preview_repair(soup, before, orientation, RepairOptions());
  const RepairResult repaired = repair(soup);
  const RepairReport& r = repaired.report;
  EXPECT_EQ(preview.changes, changes);
  EXPECT_EQ(preview.changes, repair_changes_input(r));
  EXPECT_EQ(preview.report.faces_flipped, r.faces_flipped);
  EXPECT_EQ(preview.report.vertices_split, r.vertices_split);
  EXPECT_EQ(preview.report.edges_split_to_stay_manifold, r.edges_split_to_stay_manifold);
  EXPECT_EQ(preview.report.sides_cut, r.sides_cut);
  EXPECT_EQ(preview.report.gaps.vertices_welded, r.gaps.vertices_welded);
  EXPECT_EQ(preview.report.gaps.t_junctions_closed, r.gaps.t_junctions_closed);
  EXPECT_EQ(preview.report.ambiguous_nested_shells, r.ambiguous_nested_shells);
  const std::string text = to_text(preview);
  // check_soup(), what `meshbridge check` runs, says the same in one pass.
  const SoupCheck checked = check_soup(soup);
  EXPECT_EQ(to_text(checked.report), to_text(before));
  EXPECT_EQ(checked.orientation.computed, orientation.computed);
  EXPECT_EQ(checked.orientation.faces_flipped, orientation.faces_flipped);
  EXPECT_EQ(checked.preview.ran_repair, preview.ran_repair);
  EXPECT_EQ(to_text(checked.preview), text);
  EXPECT_EQ(text.rfind(changes ? "repair would: " : "repair would change nothing", 0), 0u) << text;
  if (changes)
    return;
  const Soup& out = repaired.mesh.soup;
  EXPECT_EQ(out.positions, soup.positions);
  EXPECT_EQ(out.corner_vertices, soup.corner_vertices);
  EXPECT_EQ(out.face_begin, soup.face_begin);
}

template <class Make>
void over_orders_and_offsets(Make make, bool changes) {
  for (double offset : {0.0, 1e3, 1e6}) {
    SCOPED_TRACE("offset " + std::to_string(offset));
    for_face_orders(make(offset), 5, [&](const Soup& s, const std::vector<Index>&) {
      expect_prediction(s, changes);
    });
  }
}

}  // namespace

TEST(CheckPredictsRepair, open_sheet_is_left_as_it_is_in_either_winding) {
  over_orders_and_offsets([](double o) { return grid(4, o); }, false);
  over_orders_and_offsets([](double o) { return reversed(grid(4, o)); }, false);
  expect_prediction(grid(1, 0), false);  // one quad
}

TEST(CheckPredictsRepair, closed_cube_outward_is_left_and_inward_is_turned) {
  over_orders_and_offsets(
      [](double o) {
        Soup s;
        add_cube(s, o, 2, true);
        return s;
      },
      false);
  over_orders_and_offsets(
      [](double o) {
        Soup s;
        add_cube(s, o, 2, false);
        return s;
      },
      true);
}

TEST(CheckPredictsRepair, insert_in_a_closed_shell_is_ambiguous_and_left) {
  // An outward cube inside an outward cube: reported, kept as written.
  over_orders_and_offsets(
      [](double o) {
        Soup s;
        add_cube(s, o, 10, true);
        add_cube(s, o + 3, 4, true);
        return s;
      },
      false);
}

TEST(CheckPredictsRepair, cubes_sharing_an_edge_are_split) {
  // Two cubes on one edge (a singular edge of 4 faces): repair makes vertex copies.
  const auto make = [](double o) {
    Soup s;
    add_cube(s, o, 1, true);
    Soup other;
    add_cube(other, o + 1, 1, true);
    std::vector<Index> index_of(other.num_vertices());
    for (std::size_t v = 0; v < other.num_vertices(); ++v) {
      Point p = other.positions[v];
      p[2] -= 1;  // [o+1, o+2]^2 x [o, o+1]: touches the first cube along x = y = o + 1
      index_of[v] = static_cast<Index>(s.num_vertices());
      for (std::size_t w = 0; w < 8; ++w)
        if (s.positions[w] == p)
          index_of[v] = static_cast<Index>(w);  // the shared edge's two vertices
      if (index_of[v] == s.num_vertices())
        s.add_vertex(p);
    }
    for (std::size_t f = 0; f < other.num_faces(); ++f) {
      std::vector<Index> polygon;
      for (Index v : other.polygon(f))
        polygon.push_back(index_of[v]);
      s.add_polygon(polygon);
    }
    EXPECT_EQ(s.num_vertices(), 14u);
    return s;
  };
  over_orders_and_offsets(make, true);
}

TEST(CheckPredictsRepair, open_box_wound_inconsistently_or_inward_is_turned) {
  // A cube without its top, one side wound against the others: an orientation conflict.
  Soup box;
  add_cube(box, 0, 1, true);
  Soup open;
  open.positions = box.positions;
  for (std::size_t f = 0; f + 1 < box.num_faces(); ++f) {
    const PolygonView p = box.polygon(f);
    open.add_polygon(std::vector<Index>(p.begin(), p.end()));
  }
  expect_prediction(with_face_reversed(open, 2), true);
  expect_prediction(open, false);
  expect_prediction(reversed(open), true);  // an opened shell faces outward: 5 faces reversed
}
