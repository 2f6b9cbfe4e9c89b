// SPDX-License-Identifier: GPL-3.0-or-later
// Rules of "no new defects" (DESIGN 8a): orientation intent of nested shells, a global flip
// changing nothing, gap closing that keeps features far from the origin, and per-face-vertex
// soups welded by position.

#include "rule_support.h"
#include "scratch_folder.h"

#include "meshbridge/close_gaps.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/models/canonical_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

using namespace meshbridge;
using namespace meshbridge::rule_test;

namespace {

Soup reversed_faces(const Soup& soup) {
  Soup out = soup;
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    std::reverse(out.corner_vertices.begin() + soup.face_begin[f],
                 out.corner_vertices.begin() + soup.face_begin[f + 1]);
  return out;
}

// The signed volume of each input face's output component, as repair leaves it.
std::vector<double> volumes(const Soup& soup, const RepairOptions& options = {}) {
  return repair_and_label(soup, options).volume;
}

// A 10 x 10 square plate with a 1 x 1 window in its middle (8 triangles), at `offset`.
Soup plate_with_window(double x, double y, double z) {
  Soup soup;
  const double outer[4][2] = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const double inner[4][2] = {{4.5, 4.5}, {5.5, 4.5}, {5.5, 5.5}, {4.5, 5.5}};
  for (const auto& p : outer)
    soup.add_vertex({x + p[0], y + p[1], z});
  for (const auto& p : inner)
    soup.add_vertex({x + p[0], y + p[1], z});
  for (Index i = 0; i < 4; ++i) {
    const Index j = (i + 1) % 4;
    soup.add_polygon({i, j, Index(4 + j)});
    soup.add_polygon({i, Index(4 + j), Index(4 + i)});
  }
  return soup;
}

}  // namespace

TEST(NestedShells, outward_insert_in_outward_shell_is_kept_as_material) {
  // A 10 mm cube with a 4 mm cube inside, both closed and wound outward (an insert).
  Soup soup;
  add_cube(soup, 0, 10, true);
  add_cube(soup, 3, 4, true);
  for_face_orders(soup, 50, [&](const Soup& s, const std::vector<Index>& to_original) {
    const Outcome o = repair_and_label(s);
    test_support::expect_repair_invariants(s, o.result);
    EXPECT_EQ(o.result.report.faces_flipped, 0u);
    EXPECT_EQ(o.result.report.ambiguous_nested_shells, 1u);
    for (std::size_t f = 0; f < s.num_faces(); ++f)
      EXPECT_NEAR(o.volume[f], to_original[f] < 6 ? 1000.0 : 64.0, 1e-9);
  });
}

TEST(NestedShells, ambiguous_insert_becomes_a_cavity_on_request) {
  Soup soup;
  add_cube(soup, 0, 10, true);
  add_cube(soup, 3, 4, true);
  RepairOptions options;
  options.nested_shells = AmbiguousNesting::cavity;
  const Outcome o = repair_and_label(soup, options);
  EXPECT_EQ(o.result.report.faces_flipped, 6u);
  EXPECT_EQ(o.result.report.ambiguous_nested_shells, 1u);
  EXPECT_NEAR(o.volume[6], -64.0, 1e-9);
}

TEST(NestedShells, cavity_wound_toward_the_void_is_not_ambiguous) {
  Soup soup;
  add_cube(soup, 0, 10, true);
  add_cube(soup, 3, 4, false);
  const RepairResult r = repair(soup);
  EXPECT_EQ(r.report.faces_flipped, 0u);
  EXPECT_EQ(r.report.ambiguous_nested_shells, 0u);
}

TEST(NestedShells, reversing_every_face_gives_the_same_repaired_mesh) {
  // Insert, cavity, island in a cavity, mixed windings: the repaired volumes of every shell are
  // the same for the input and for the input with every face reversed.
  std::vector<Soup> models;
  {
    Soup insert;
    add_cube(insert, 0, 10, true);
    add_cube(insert, 3, 4, true);
    models.push_back(insert);
    Soup cavity;
    add_cube(cavity, 0, 10, false);
    add_cube(cavity, 3, 4, true);
    models.push_back(cavity);
    Soup island;
    add_cube(island, 0, 6, true);
    add_cube(island, 1, 4, false);
    add_cube(island, 2, 2, true);
    models.push_back(island);
    Soup mixed = cavity;
    for (std::size_t f : {1u, 7u})
      mixed = with_face_reversed(mixed, f);
    models.push_back(mixed);
  }
  for (std::size_t m = 0; m < models.size(); ++m) {
    SCOPED_TRACE("model " + std::to_string(m));
    const std::vector<double> given = volumes(models[m]);
    const std::vector<double> flipped = volumes(reversed_faces(models[m]));
    ASSERT_EQ(given.size(), flipped.size());
    for (std::size_t f = 0; f < given.size(); ++f)
      EXPECT_NEAR(given[f], flipped[f], 1e-9) << "face " << f;
  }
}

TEST(NestedShells, inside_out_checkerboard_comes_out_like_the_outward_one) {
  const Soup outward = models::checkerboard_cubes(3);
  const std::vector<double> expected = volumes(outward);
  const std::vector<double> got = volumes(reversed_faces(outward));
  ASSERT_EQ(expected.size(), got.size());
  for (std::size_t f = 0; f < got.size(); ++f) {
    EXPECT_GT(got[f], 0) << "face " << f;
    EXPECT_NEAR(got[f], expected[f], 1e-9) << "face " << f;
  }
}

TEST(GapClosing, far_from_the_origin_a_window_stays_open) {
  // The same plate at the origin and at UTM-like offsets, in doubles and as if read from floats:
  // the window's corners are 1 apart, far over any rounding: nothing welds, 8 boundary edges.
  const double offsets[5][3] = {
      {0, 0, 0}, {1e3, 1e3, 0}, {1e6, 1e6, 1e6}, {5e5, 5e6, 0}, {1e7, 1e7, 1e7}};
  for (const auto& o : offsets) {
    for (bool float_coordinates : {false, true}) {
      SCOPED_TRACE("offset " + std::to_string(o[0]) + (float_coordinates ? " float" : " double"));
      const Soup soup = plate_with_window(o[0], o[1], o[2]);
      RepairOptions options;
      options.close_gaps.float_coordinates = float_coordinates;
      const RepairResult r = repair(soup, options);
      EXPECT_EQ(r.report.gaps.vertices_welded, 0u);
      EXPECT_EQ(r.report.gaps.t_junctions_closed, 0u);
      EXPECT_EQ(r.report.boundary_edges_after, 8u);
      EXPECT_EQ(r.mesh.soup.num_vertices(), 8u);
      if (!float_coordinates)  // doubles: only the plate's own extent counts
        EXPECT_NEAR(r.report.gaps.tolerance, std::ldexp(10.0, -21), 1e-12);
    }
  }
}

TEST(GapClosing, a_crack_closes_the_same_at_every_offset_and_scale) {
  // Two halves of a plate meeting along x = 5 with their corners 1e-6 apart (a CAD export's
  // rounding): welded at the origin, and the same far away or scaled (doubles).
  for (double offset : {0.0, 1e3, 1e6, 1e7}) {
    for (double scale : {1e-6, 1.0, 1e6}) {
      if (scale * 1e-6 < offset * 1e-12)
        continue;  // a crack that doubles cannot hold there
      SCOPED_TRACE("offset " + std::to_string(offset) + " scale " + std::to_string(scale));
      Soup soup;
      const double pts[8][2] = {{0, 0},           {5, 0},  {5, 10},  {0, 10},
                                {5 + 1e-6, 1e-6}, {10, 0}, {10, 10}, {5 - 1e-6, 10 + 1e-6}};
      for (const auto& p : pts)
        soup.add_vertex({offset + scale * p[0], offset + scale * p[1], offset});
      soup.add_polygon({0, 1, 2, 3});
      soup.add_polygon({4, 5, 6, 7});
      const RepairResult r = repair(soup);
      EXPECT_EQ(r.report.gaps.vertices_welded, 2u);
      EXPECT_EQ(r.report.boundary_edges_after, 6u);
    }
  }
}

TEST(GapClosing, a_stray_facet_far_away_widens_nothing) {
  // A 100 mm part at the origin with a 1e-3 crack, and one stray facet at x = 1e7: the part's
  // tolerance is its own (2^-21 x 100), so the 1e-3 crack stays open, as without the facet.
  Soup soup;
  const double pts[8][2] = {{0, 0},         {50, 0},  {50, 100},  {0, 100},
                            {50 + 1e-3, 0}, {100, 0}, {100, 100}, {50 + 1e-3, 100}};
  for (const auto& p : pts)
    soup.add_vertex({p[0], p[1], 0});
  soup.add_polygon({0, 1, 2, 3});
  soup.add_polygon({4, 5, 6, 7});
  const RepairResult alone = repair(soup);
  const Index s = static_cast<Index>(soup.num_vertices());
  soup.add_vertex({1e7, 0, 0});
  soup.add_vertex({1e7 + 1, 0, 0});
  soup.add_vertex({1e7, 1, 0});
  soup.add_polygon({s, Index(s + 1), Index(s + 2)});
  for (bool float_coordinates : {false, true}) {
    RepairOptions options;
    options.close_gaps.float_coordinates = float_coordinates;
    const RepairResult r = repair(soup, options);
    EXPECT_EQ(r.report.gaps.vertices_welded, alone.report.gaps.vertices_welded);
    EXPECT_EQ(r.report.gaps.vertices_welded, 0u);
    EXPECT_EQ(r.report.boundary_edges_after, alone.report.boundary_edges_after + 3);
  }
}

TEST(GapClosing, no_weld_is_longer_than_a_quarter_of_an_edge) {
  // An explicit tolerance wider than the window: the window's corners are still not welded.
  const Soup soup = plate_with_window(0, 0, 0);
  RepairOptions options;
  options.close_gaps.tolerance = 3;
  const RepairResult r = repair(soup, options);
  EXPECT_EQ(r.report.gaps.vertices_welded, 0u);
  EXPECT_GT(r.report.gaps.welds_too_long + r.report.gaps.welds_undone, 0u);
  EXPECT_EQ(r.report.boundary_edges_after, 8u);
}

class SoupWelding : public test_support::ScratchFolderTest {
 public:
  SoupWelding() : ScratchFolderTest("soup_weld") {}
};

// `soup` written as OBJ, each face with its own vertices (per-face-vertex), faces in order.
std::string per_face_vertex_obj(const Soup& soup) {
  std::ostringstream obj;
  obj.precision(17);
  std::size_t next = 1;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    for (Index v : soup.polygon(f)) {
      const Point& p = soup.positions[v];
      obj << "v " << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
    obj << "f";
    for (std::size_t i = 0; i < soup.polygon(f).size(); ++i)
      obj << " " << next++;
    obj << "\n";
  }
  return obj.str();
}

TEST_F(SoupWelding, a_per_face_vertex_file_repairs_like_the_indexed_one) {
  const Soup indexed = models::checkerboard_cubes(3);
  for (std::uint32_t seed : {0u, 7u}) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Soup order = seed == 0 ? indexed : test_support::shuffled(indexed, seed);
    ReadInfo info;
    const Soup read = read_soup(write("soup.obj", per_face_vertex_obj(order)), &info);
    EXPECT_EQ(info.vertices_welded_by_position, order.num_corners() - indexed.num_vertices());
    EXPECT_NE(describe_reading(info).find("the file repeats each vertex per face"),
              std::string::npos);
    const DefectReport a = detect_defects(read), b = detect_defects(indexed);
    EXPECT_EQ(a.num_vertices, b.num_vertices);
    EXPECT_EQ(a.singular_edges.size(), b.singular_edges.size());
    EXPECT_EQ(a.num_singular_vertices(), b.num_singular_vertices());
    EXPECT_EQ(a.boundary_edges.size(), 0u);
    const RepairResult ra = repair(read), rb = repair(indexed);
    EXPECT_EQ(ra.report.components_after, rb.report.components_after);
    EXPECT_EQ(ra.report.boundary_edges_after, 0u);
    EXPECT_EQ(ra.report.gaps.vertices_welded, 0u);
    EXPECT_EQ(ra.report.gaps.t_junctions_closed, 0u);
    EXPECT_EQ(ra.mesh.soup.num_vertices(), rb.mesh.soup.num_vertices());
  }
}

TEST_F(SoupWelding, a_repaired_file_read_back_is_not_welded_again) {
  const RepairResult r = repair(models::checkerboard_cubes(3));
  ASSERT_GT(r.report.vertices_split, 0u);
  const std::string file = path("repaired.obj");
  write_mesh(file, r.mesh);
  ReadInfo info;
  const Soup again = read_soup(file, &info);
  EXPECT_EQ(info.vertices_welded_by_position, 0u);
  EXPECT_EQ(again.num_vertices(), r.mesh.soup.num_vertices());
  EXPECT_TRUE(detect_defects(again).watertight);
}

TEST(Keyhole, the_slit_is_counted_and_the_polygon_stays_one_component) {
  // A square with a square hole written as one polygon: outer 0-3, slit 0 -> 4, inner 4-7
  // (reversed), slit 4 -> 0, back to the outer loop. The file has 8 + 1 = 9 edges (outer 4,
  // inner 4, the slit) and 1 component.
  Soup soup;
  const double pts[8][2] = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 1}, {1, 3}, {3, 3}, {3, 1}};
  for (const auto& p : pts)
    soup.add_vertex({p[0], p[1], 0});
  for (std::size_t rotation = 0; rotation < 10; ++rotation) {
    std::vector<Index> polygon{0, 4, 5, 6, 7, 4, 0, 1, 2, 3};
    std::rotate(polygon.begin(), polygon.begin() + rotation, polygon.end());
    Soup s;
    s.positions = soup.positions;
    s.add_polygon(polygon);
    SCOPED_TRACE("rotation " + std::to_string(rotation));
    const DefectReport d = detect_defects(s);
    EXPECT_EQ(d.num_edges, 9u);
    EXPECT_EQ(d.num_components, 1u);
    EXPECT_EQ(d.keyhole_polygons_triangulated, 1u);
    EXPECT_EQ(d.slits_set_aside, 0u);
    // Repair cuts it into 8 triangles, the hole left open (keyhole_polygon_rule_test.cpp).
    const RepairResult r = repair(s);
    EXPECT_EQ(r.report.keyhole_polygons_triangulated, 1u);
    EXPECT_EQ(r.report.slits_set_aside, 0u);
    EXPECT_EQ(r.report.faces_split, 1u);
    EXPECT_EQ(r.report.faces_added_by_split, 7u);
    EXPECT_EQ(r.report.components_after, 1u);
    EXPECT_NE(to_text(r.report).find("1 keyhole polygon triangulated"), std::string::npos);
  }
}

TEST_F(SoupWelding, a_repaired_bowtie_of_two_lone_triangles_is_not_welded_again) {
  // Two triangles that met at one vertex, repaired: each has vertices of its own, and only one
  // position of five is repeated: a file's own choice, not a per-face-vertex export.
  const RepairResult r = repair(models::bowtie());
  const std::string file = path("bowtie.obj");
  write_mesh(file, r.mesh);
  ReadInfo info;
  const Soup again = read_soup(file, &info);
  EXPECT_EQ(info.vertices_welded_by_position, 0u);
  EXPECT_EQ(detect_defects(again).num_singular_vertices(), 0u);
}
