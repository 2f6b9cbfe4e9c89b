// SPDX-License-Identifier: GPL-3.0-or-later
// Gap closing before pairing: welding rounding-level copies and splitting T-junction cracks.

#include "meshbridge/close_gaps.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/repair.h"
#include "meshbridge/validate.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace meshbridge {
namespace {

using test_support::every_edge_manifold;
using test_support::face_components;
using test_support::openmesh_accepts;
using test_support::signed_volume;

// A 10 mm cube at 100 mm from the origin (printer-bed coordinates), 12 triangles. Corners are
// written twice: the -x, -y, -z sides use vertices 0..7, the +x, +y, +z sides use 8..15, which
// are the same corners moved by `offset` along every axis (rounding-level when offset is an ulp).
// Corner 7 is on no -side and corner 0 on no +side: 6 corners are on both, and vertices 7 and 8
// are isolated.
Soup cube_written_twice(double offset) {
  Soup soup;
  for (int copy = 0; copy < 2; ++copy) {
    for (int i = 0; i < 8; ++i) {
      const Point p(100 + 10 * (i & 1), 100 + 10 * ((i >> 1) & 1), 100 + 10 * ((i >> 2) & 1));
      soup.add_vertex(copy == 0 ? p : p + Point(offset, -offset, offset));
    }
  }
  // Quads of the cube, outward, as corner bit patterns; then each as two triangles.
  const int quads[6][4] = {{0, 4, 6, 2}, {0, 1, 5, 4}, {0, 2, 3, 1},   // -x, -y, -z
                           {1, 3, 7, 5}, {2, 6, 7, 3}, {4, 5, 7, 6}};  // +x, +y, +z
  for (int q = 0; q < 6; ++q) {
    const Index base = q < 3 ? 0 : 8;
    const Index a = base + quads[q][0], b = base + quads[q][1], c = base + quads[q][2],
                d = base + quads[q][3];
    soup.add_polygon({a, b, c});
    soup.add_polygon({a, c, d});
  }
  return soup;
}

// One float32 unit in the last place at 110: the difference two exports of one corner show.
double float_ulp_at_110() {
  return static_cast<double>(std::nextafter(110.0f, 200.0f)) - 110.0;
}

// Gap closing for coordinates that came from float32 (an STL): the automatic tolerance respects
// float rounding at the vertex's own coordinates.
CloseGapsOptions from_floats() {
  CloseGapsOptions options;
  options.float_coordinates = true;
  return options;
}
RepairOptions repair_from_floats() {
  RepairOptions options;
  options.close_gaps = from_floats();
  return options;
}

// Box [0,2]x[0,1]x[0,1] of 7 quads, outward. Its top is two quads that meet at x = 1 (vertices 8
// and 9), while the front (y = 0) and back (y = 1) are one quad each: vertices 8 and 9 lie on
// their top sides (T-junction crack). `lift` moves vertex 8 up off the front's side.
Soup box_with_t_junction(double lift = 0) {
  Soup soup;
  for (int i = 0; i < 8; ++i)
    soup.add_vertex(Point(2 * (i & 1), (i >> 1) & 1, (i >> 2) & 1));
  soup.add_vertex(Point(1, 0, 1 + lift));  // 8
  soup.add_vertex(Point(1, 1, 1));         // 9
  soup.add_polygon({0, 2, 3, 1});          // bottom
  soup.add_polygon({0, 1, 5, 4});          // front, whole
  soup.add_polygon({2, 6, 7, 3});          // back, whole
  soup.add_polygon({0, 4, 6, 2});          // left
  soup.add_polygon({1, 3, 7, 5});          // right
  soup.add_polygon({4, 8, 9, 6});          // top, left half
  soup.add_polygon({8, 5, 7, 9});          // top, right half
  return soup;
}

// The repair keeps every face, closes one outward component of `volume` (relative `precision`),
// and is manifold.
void expect_closed_solid(const Soup& input, const RepairResult& result, double volume,
                         double precision = 1e-9) {
  const IndexedMesh& mesh = result.mesh;
  EXPECT_EQ(result.report.faces_out, input.num_faces());
  EXPECT_EQ(mesh.soup.num_faces(), input.num_faces());
  EXPECT_EQ(result.report.boundary_edges_after, 0u);
  EXPECT_EQ(result.report.components_after, 1u);
  EXPECT_TRUE(result.report.after.watertight);
  EXPECT_TRUE(every_edge_manifold(mesh.soup));
  EXPECT_TRUE(openmesh_accepts(mesh));
  const std::vector<Index> label = face_components(mesh.soup);
  EXPECT_NEAR(signed_volume(mesh.soup, label, 0), volume, precision * volume);
  // Provenance: every vertex and corner maps into the input; welded corners map to a vertex
  // within the tolerance of the survivor they were welded into.
  ASSERT_EQ(mesh.vertex_origin.size(), mesh.soup.num_vertices());
  ASSERT_EQ(mesh.corner_origin.size(), mesh.soup.num_corners());
  for (std::size_t v = 0; v < mesh.soup.num_vertices(); ++v)
    EXPECT_EQ(mesh.soup.positions[v], input.positions[mesh.vertex_origin[v]]);
  for (std::size_t c = 0; c < mesh.soup.num_corners(); ++c)
    ASSERT_LT(mesh.corner_origin[c], input.num_corners());
  for (std::size_t f = 0; f < mesh.face_origin.size(); ++f)
    EXPECT_EQ(mesh.face_origin[f], f);
}

TEST(CloseGaps, default_tolerance_is_four_float_ulps_of_a_float_coordinate_else_of_the_part) {
  const Soup soup = cube_written_twice(0);
  // From floats: 2^-21 x the vertex's largest coordinate.
  EXPECT_EQ(default_weld_tolerance(soup, true), 110.0 / (1 << 21));
  EXPECT_GE(default_weld_tolerance(soup, true), 4 * float_ulp_at_110() / 2);
  // Doubles: 2^-21 x the extent of the vertex's part (each half of this cube spans 10).
  EXPECT_EQ(default_weld_tolerance(soup), 10.0 / (1 << 21));
  EXPECT_EQ(default_weld_tolerance(Soup()), 0.0);
  // A stray vertex that no face uses, far away, does not widen it (it would weld small parts).
  Soup stray = soup;
  stray.add_vertex({1e9, 0, 0});
  EXPECT_EQ(default_weld_tolerance(stray, true), 110.0 / (1 << 21));
  EXPECT_EQ(default_weld_tolerance(stray), 10.0 / (1 << 21));
}

TEST(CloseGaps, cube_with_corners_written_twice_welds_six_and_closes) {
  const Soup input = cube_written_twice(float_ulp_at_110());
  const ClosedGaps closed = close_gaps(input, from_floats());
  EXPECT_EQ(closed.report.vertices_welded, 6u);
  EXPECT_EQ(closed.report.welds_refused, 0u);
  EXPECT_DOUBLE_EQ(closed.report.largest_weld_distance, std::sqrt(3.0) * float_ulp_at_110());
  EXPECT_EQ(closed.report.t_junctions_closed, 0u);
  EXPECT_EQ(closed.soup.num_vertices(), 10u);
  EXPECT_EQ(closed.soup.num_faces(), 12u);
  for (std::size_t v = 0; v < 8; ++v)
    EXPECT_EQ(closed.vertex_origin[v], v);  // the first copies survive
  EXPECT_EQ(closed.vertex_origin[8], 8u);   // copy of corner 0: isolated
  EXPECT_EQ(closed.vertex_origin[9], 15u);  // copy of corner 7: only on +sides

  const RepairResult result = repair(input, repair_from_floats());
  EXPECT_EQ(result.report.gaps.vertices_welded, 6u);
  EXPECT_EQ(result.report.boundary_edges_before, 12u);  // the input as read
  EXPECT_EQ(result.report.vertices_in, 16u);
  EXPECT_EQ(result.report.vertices_out, 10u);
  EXPECT_EQ(result.report.after.isolated_vertices.size(), 2u);
  // Corner 7 keeps its +side position, one ulp off: the volume moves by about 3 ulp x 100 mm^2.
  expect_closed_solid(input, result, 1000, 1e-6);
}

TEST(CloseGaps, weld_zero_turns_gap_closing_off) {
  const Soup input = cube_written_twice(float_ulp_at_110());
  RepairOptions options;
  options.close_gaps.tolerance = 0;
  const RepairResult result = repair(input, options);
  EXPECT_EQ(result.report.gaps.tolerance, 0.0);
  EXPECT_EQ(result.report.gaps.vertices_welded, 0u);
  EXPECT_EQ(result.report.vertices_out, 16u);
  // The six cube edges between a -side and a +side are open on both sides.
  EXPECT_EQ(result.report.boundary_edges_after, 12u);
  EXPECT_EQ(result.report.faces_out, 12u);
}

TEST(CloseGaps, crack_wider_than_the_tolerance_stays_open_and_is_reported) {
  const Soup input = cube_written_twice(1e-3);  // 1 um, 19x the automatic tolerance at 110 mm
  const RepairResult result = repair(input);
  EXPECT_EQ(result.report.gaps.vertices_welded, 0u);
  EXPECT_EQ(result.report.gaps.t_junctions_closed, 0u);
  EXPECT_EQ(result.report.boundary_edges_after, 12u);
  EXPECT_EQ(result.report.after.boundary_edges.size(), 12u);
  EXPECT_FALSE(result.report.after.watertight);
  EXPECT_EQ(result.report.faces_out, 12u);
  // An explicit tolerance above the crack closes it.
  RepairOptions wide;
  wide.close_gaps.tolerance = 2e-3;
  const RepairResult closed = repair(input, wide);
  EXPECT_EQ(closed.report.gaps.vertices_welded, 6u);
  expect_closed_solid(input, closed, 1000, 1e-4);
}

TEST(CloseGaps, t_junction_crack_splits_the_whole_sides_and_stitches) {
  const Soup input = box_with_t_junction();
  const ClosedGaps closed = close_gaps(input);
  EXPECT_EQ(closed.report.vertices_welded, 0u);
  EXPECT_EQ(closed.report.t_junctions_closed, 2u);
  EXPECT_EQ(closed.report.sides_split, 2u);
  EXPECT_EQ(closed.soup.num_faces(), 7u);
  EXPECT_EQ(closed.soup.arity(1), 5u);  // front: 0 1 5 8 4
  EXPECT_EQ(closed.soup.arity(2), 5u);  // back: 2 6 9 7 3
  EXPECT_NO_THROW(validate_soup(closed.soup));

  const RepairResult result = repair(input);
  EXPECT_EQ(result.report.boundary_edges_before, 6u);
  EXPECT_EQ(result.report.gaps.t_junctions_closed, 2u);
  EXPECT_EQ(result.report.faces_flipped, 0u);
  expect_closed_solid(input, result, 2);
}

TEST(CloseGaps, t_junction_farther_than_the_tolerance_stays_open) {
  const Soup input = box_with_t_junction(1e-3);
  const RepairResult result = repair(input);
  EXPECT_EQ(result.report.gaps.t_junctions_closed, 1u);  // only vertex 9 is on its side
  // Vertex 8 stays off the front's top side: that side and the two top sides at 8 stay open.
  EXPECT_EQ(result.report.boundary_edges_after, 3u);
  EXPECT_EQ(result.report.faces_out, 7u);
}

TEST(CloseGaps, never_merges_two_corners_of_one_polygon) {
  Soup soup;
  soup.add_vertex({0, 0, 0});
  soup.add_vertex({1, 0, 0});
  soup.add_vertex({1, 1e-9, 0});  // within 1e-6 of vertex 1, in the same triangle
  soup.add_polygon({0, 1, 2});
  CloseGapsOptions options;
  options.tolerance = 1e-6;
  const ClosedGaps closed = close_gaps(soup, options);
  EXPECT_EQ(closed.report.vertices_welded, 0u);
  EXPECT_EQ(closed.report.welds_refused, 1u);
  EXPECT_EQ(closed.soup.num_vertices(), 3u);
  EXPECT_EQ(closed.soup.num_faces(), 1u);
}

TEST(CloseGaps, no_weld_moves_farther_than_the_tolerance_at_huge_coordinates) {
  // At 1e300 the automatic tolerance is 4.8e293 and the squares of distances overflow: two
  // boundary vertices 1e293 apart were welded with a "largest move" of inf (a fuzz finding).
  // Distances beyond 1e154 are never welded; every move stays within the tolerance.
  Soup soup;
  soup.add_vertex({1e300, 0, 0});
  soup.add_vertex({0, 1e300, 0});
  soup.add_vertex({0, 0, 1e300});
  soup.add_vertex({1.0000001e300, 0, 0});
  soup.add_vertex({0, -1e300, 0});
  soup.add_vertex({0, 0, -1e300});
  soup.add_polygon({0, 1, 2});
  soup.add_polygon({3, 4, 5});
  const ClosedGaps closed = close_gaps(soup);
  EXPECT_GT(closed.report.tolerance, 1e293);
  EXPECT_TRUE(std::isfinite(closed.report.largest_weld_distance));
  EXPECT_LE(closed.report.largest_weld_distance, closed.report.tolerance);
  EXPECT_EQ(closed.report.vertices_welded, 0u);
}

TEST(CloseGaps, refuses_a_nan_tolerance) {
  CloseGapsOptions options;
  options.tolerance = std::nan("");
  EXPECT_THROW(close_gaps(test_support::triangle(), options), std::invalid_argument);
}

TEST(CloseGaps, closing_twice_changes_nothing_more) {
  const ClosedGaps once = close_gaps(cube_written_twice(float_ulp_at_110()), from_floats());
  const ClosedGaps twice = close_gaps(once.soup, from_floats());
  EXPECT_FALSE(twice.report.changed());
  EXPECT_EQ(twice.soup.corner_vertices, once.soup.corner_vertices);
  const ClosedGaps box_once = close_gaps(box_with_t_junction());
  EXPECT_FALSE(close_gaps(box_once.soup).report.changed());
}

// preview_close_gaps() is close_gaps()'s report, field by field, whether gaps close or not.
TEST(CloseGaps, preview_reports_what_close_gaps_would_do) {
  const auto expect_same = [](const Soup& soup, const CloseGapsOptions& options) {
    const CloseGapsReport preview = preview_close_gaps(soup, options);
    const CloseGapsReport done = close_gaps(soup, options).report;
    EXPECT_EQ(preview.tolerance, done.tolerance);
    EXPECT_EQ(preview.vertices_welded, done.vertices_welded);
    EXPECT_EQ(preview.largest_weld_distance, done.largest_weld_distance);
    EXPECT_EQ(preview.welds_refused, done.welds_refused);
    EXPECT_EQ(preview.t_junctions_closed, done.t_junctions_closed);
    EXPECT_EQ(preview.sides_split, done.sides_split);
    const DefectReport detected = detect_defects(soup);
    const CloseGapsReport told = preview_close_gaps(soup, options, &detected);
    EXPECT_EQ(told.tolerance, done.tolerance);
    EXPECT_EQ(told.vertices_welded, done.vertices_welded);
    EXPECT_EQ(told.largest_weld_distance, done.largest_weld_distance);
    EXPECT_EQ(told.welds_refused, done.welds_refused);
    EXPECT_EQ(told.t_junctions_closed, done.t_junctions_closed);
    EXPECT_EQ(told.sides_split, done.sides_split);
  };
  CloseGapsOptions off;
  off.tolerance = 0;
  for (const CloseGapsOptions& options : {CloseGapsOptions(), from_floats(), off}) {
    expect_same(cube_written_twice(float_ulp_at_110()), options);  // welds
    expect_same(cube_written_twice(1e-3), options);                // crack stays open
    expect_same(box_with_t_junction(), options);                   // T-junctions
    expect_same(close_gaps(box_with_t_junction()).soup, options);  // closed: nothing to do
    expect_same(Soup(), options);
  }
  EXPECT_EQ(
      preview_close_gaps(cube_written_twice(float_ulp_at_110()), from_floats()).vertices_welded,
      6u);
  CloseGapsOptions nan;
  nan.tolerance = std::nan("");
  EXPECT_THROW(preview_close_gaps(test_support::triangle(), nan), std::invalid_argument);
}

}  // namespace
}  // namespace meshbridge
