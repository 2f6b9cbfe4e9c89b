// SPDX-License-Identifier: GPL-3.0-or-later
// What a repaired mesh becomes through STL, and the smallest separation that survives float32.

#include "meshbridge/stl_round_trip.h"
#include "meshbridge/close_gaps.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/polygon_triangles.h"
#include "meshbridge/repair.h"
#include "meshbridge/separate_copies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

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

TEST(StlRoundTrip, separate_copies_for_stl_moves_each_copy_once_and_survives_the_reread) {
  // Variants: the shared edge of two cubes, a pinch, three tetrahedra on one edge at 150 mm,
  // and the same far from the origin (UTM-like) and tiny (micrometres).
  std::vector<Soup> inputs = {models::two_cubes_sharing_edge(), models::bowtie(),
                              three_tetrahedra_on_one_edge()};
  for (const double scale : {1e-6, 1e3}) {
    Soup moved = three_tetrahedra_on_one_edge();
    for (Point& p : moved.positions)
      p = p * scale + Point(scale > 1 ? 5e5 : 0, scale > 1 ? 5e6 : 0, 0);
    inputs.push_back(moved);
  }
  for (const Soup& input : inputs) {
    RepairResult r = repair(input);
    ASSERT_GT(r.report.vertices_split, 0u);
    const double expected = stl_separation_surviving_weld(r.mesh);
    const std::vector<Point> before = r.mesh.soup.positions;
    const StlSeparation done = separate_copies_for_stl(r.mesh);
    EXPECT_TRUE(done.kept_reason.empty()) << done.kept_reason;
    EXPECT_EQ(done.distance, expected);
    std::size_t copies = 0;  // output vertices whose input vertex has two or more copies
    for (std::size_t v = 0; v < r.mesh.vertex_origin.size(); ++v)
      copies += std::count(r.mesh.vertex_origin.begin(), r.mesh.vertex_origin.end(),
                           r.mesh.vertex_origin[v]) > 1;
    EXPECT_EQ(done.vertices_moved, copies);
    for (std::size_t v = 0; v < before.size(); ++v) {  // moved copies on float32 positions
      const Point& p = r.mesh.soup.positions[v];
      if (p[0] != before[v][0] || p[1] != before[v][1] || p[2] != before[v][2]) {
        for (int a = 0; a < 3; ++a)
          EXPECT_EQ(static_cast<double>(static_cast<float>(p[a])), p[a]);
      }
    }
    const Soup reread = stl_round_trip(r.mesh.soup);
    const DefectReport again = detect_defects(reread);
    EXPECT_EQ(again.singular_edges.size() + again.num_singular_vertices(), 0u);
    EXPECT_EQ(close_gaps(reread).report.vertices_welded, 0u);
  }
  // Nothing split: nothing moves.
  RepairResult clean = repair(models::icosphere(1));
  const Soup before = clean.mesh.soup;
  const StlSeparation none = separate_copies_for_stl(clean.mesh);
  EXPECT_EQ(none.vertices_moved, 0u);
  EXPECT_EQ(none.distance, 0.0);
  EXPECT_EQ(clean.mesh.soup.positions, before.positions);
}

TEST(StlRoundTrip, written_triangles_never_reuse_an_edge_as_a_diagonal) {
  // A square quad 0-1-2-3 with a closed fin standing on its diagonal 1-3 (two triangles, one on
  // each side): the ear at corner 0 would cut along 1-3 and give that edge four triangles.
  for (const bool reversed : {false, true}) {
    Soup soup;
    for (const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                           Point(0.5, 0.5, 1), Point(0.5, 0.5, 2)})
      soup.add_vertex(p);
    if (reversed)
      soup.add_polygon({3, 2, 1, 0});
    else
      soup.add_polygon({0, 1, 2, 3});
    soup.add_polygon({1, 3, 4});
    soup.add_polygon({3, 1, 5});
    ASSERT_EQ(detect_defects(soup).singular_edges.size(), 0u);
    const Soup triangles = stl_round_trip(soup);
    EXPECT_EQ(triangles.num_faces(), 4u);
    // The public triangulation (the MeshLab plugin's) cuts the quad along 0-2, as the writers do.
    const PolygonTriangles cut = triangles_as_written(soup);
    ASSERT_EQ(cut.first, (std::vector<Index>{0, 2, 3, 4}));
    for (Index i = 0; i < 2; ++i) {
      const auto& t = cut.corners[i];
      const PolygonView quad = soup.polygon(0);
      std::vector<Index> vertices{quad[t[0]], quad[t[1]], quad[t[2]]};
      std::sort(vertices.begin(), vertices.end());
      EXPECT_TRUE(vertices == (std::vector<Index>{0, 1, 2}) ||
                  vertices == (std::vector<Index>{0, 2, 3}))
          << vertices[0] << vertices[1] << vertices[2];
    }
    EXPECT_EQ(cut.corners[2], (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(detect_defects(triangles).singular_edges.size(), 0u) << "reversed " << reversed;
  }
}

TEST(StlRoundTrip, a_sheet_written_twice_and_split_at_a_midpoint_keeps_two_faces_an_edge) {
  // Triangle 0 1 2 written on both sides (a closed hull written twice, as the DART RWP hull of
  // tests/data/realworld2), each side split at the midpoint 3 of edge 0-1, as repair splits
  // crowded pairs: quads 0 3 1 2 and 0 2 1 3. Corner 3 is flat, so each quad has one ear, whose
  // diagonal is 3-2; taken by the first quad, the second takes 0-1 (a triangle of no area)
  // rather than a fourth triangle on 3-2 (PrusaSlicer read that as 1 open edge).
  Soup soup;
  soup.positions = {{0, 0, 0}, {2, 0, 0}, {1, 2, 0}, {1, 0, 0}};
  soup.add_polygon({0, 3, 1, 2});
  soup.add_polygon({0, 2, 1, 3});
  const Soup triangles = as_triangles(soup);
  ASSERT_EQ(triangles.num_faces(), 4u);
  const DefectReport report = detect_defects(triangles);
  EXPECT_EQ(report.singular_edges.size(), 0u);
  EXPECT_EQ(report.boundary_edges.size(), 0u);
  // The first quad as before: 3-2 its diagonal; the second: 0-1.
  const auto has = [&](std::size_t f, Index a, Index b, Index c) {
    std::vector<Index> face(triangles.polygon(f).begin(), triangles.polygon(f).end());
    std::vector<Index> want{a, b, c};
    std::sort(face.begin(), face.end());
    std::sort(want.begin(), want.end());
    return face == want;
  };
  EXPECT_TRUE((has(0, 0, 3, 2) && has(1, 3, 1, 2)) || (has(0, 3, 1, 2) && has(1, 0, 3, 2)));
  EXPECT_TRUE((has(2, 0, 2, 1) && has(3, 0, 1, 3)) || (has(2, 0, 1, 3) && has(3, 0, 2, 1)));
}

}  // namespace
}  // namespace meshbridge
