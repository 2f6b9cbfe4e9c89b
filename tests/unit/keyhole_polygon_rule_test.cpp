// SPDX-License-Identifier: GPL-3.0-or-later
// Every piece of every polygon is accounted for (issue 27 item 6): a keyhole polygon, one loop of
// corners that runs a -> b and later b -> a (a slit), is an outline and holes joined by slits, as
// Blender, assimp and slicers read it. Repair cuts it into triangles as one polygon with holes:
// they cover the ring between the outline and the holes once, the holes stay open (each is a
// boundary loop), every triangle's corners are the polygon's own, and the slits are edges
// between two of its triangles. A polygon whose slit leads to a loop that is no hole keeps the
// old rule: split into its loops, the slit set aside.

#include "scratch_folder.h"
#include "test_support.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/polygon_triangles.h"
#include "meshbridge/repair.h"
#include "meshbridge/self_intersections.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using namespace meshbridge;

namespace {

// A square 0-3 (4 x 4, counter-clockwise seen from +z) with a square hole 4-7 (2 x 2, clockwise),
// and a second hole 8-11 for the two-hole polygons (then the outline is 8 x 4: 0-3 moved).
Soup keyhole_points(bool two_holes) {
  Soup soup;
  const double w = two_holes ? 8 : 4;
  const double pts[12][2] = {{0, 0}, {w, 0}, {w, 4}, {0, 4}, {1, 1}, {1, 3},
                             {3, 3}, {3, 1}, {5, 1}, {5, 3}, {7, 3}, {7, 1}};
  for (std::size_t i = 0; i < (two_holes ? 12u : 8u); ++i)
    soup.add_vertex({pts[i][0], pts[i][1], 0});
  return soup;
}

Soup with_polygon(Soup soup, std::vector<Index> polygon, std::size_t rotation, bool reversed) {
  if (reversed)
    std::reverse(polygon.begin(), polygon.end());
  std::rotate(polygon.begin(), polygon.begin() + rotation % polygon.size(), polygon.end());
  soup.add_polygon(polygon);
  return soup;
}

// The outline 0 1 2 3, the slit 0 -> 4, the hole 4 5 6 7 (turning the other way), back 4 -> 0.
const std::vector<Index> kOneHole{0, 4, 5, 6, 7, 4, 0, 1, 2, 3};
// The same hole reached from the outline's corner 2 to the hole's corner 6 (the other diagonal).
const std::vector<Index> kOtherSlit{0, 1, 2, 6, 7, 4, 5, 6, 2, 3};
// Two holes, each joined to the outline by a slit of its own (0 -> 4, 1 -> 11).
const std::vector<Index> kTwoHoles{0, 4, 5, 6, 7, 4, 0, 1, 11, 8, 9, 10, 11, 1, 2, 3};

//! Twice the signed area of triangle (a, b, c) seen from +z.
double twice_area(const Soup& soup, Index a, Index b, Index c) {
  const Point& p = soup.positions[a];
  const Point& q = soup.positions[b];
  const Point& r = soup.positions[c];
  return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
}

//! Sum of |area| and |sum of signed areas| of the soup's triangles, seen from +z: equal (and
//! equal to the ring's area) when no triangle overlaps another and all turn one way.
std::pair<double, double> areas(const Soup& soup) {
  double unsigned_sum = 0, signed_sum = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    EXPECT_EQ(p.size(), 3u);
    const double a = twice_area(soup, p[0], p[1], p[2]) / 2;
    unsigned_sum += std::abs(a);
    signed_sum += a;
  }
  return {unsigned_sum, std::abs(signed_sum)};
}

//! Checks a repaired keyhole polygon of `corners` corners (slits counted twice) with `holes`
//! holes and ring area `area`: its triangles, their corners and the output's counts. `inside`:
//! vertices on a bridge only (on no loop), which no boundary edge reaches.
void expect_polygon_with_holes(const Soup& input, const RepairResult& r, std::size_t holes,
                               double area, std::size_t inside = 0) {
  const std::size_t n = input.num_corners();
  const Soup& out = r.mesh.soup;
  test_support::expect_repair_invariants(input, r);
  EXPECT_EQ(r.report.keyhole_polygons_triangulated, 1u);
  EXPECT_EQ(r.report.slits_set_aside, 0u);
  EXPECT_EQ(r.report.faces_split, 1u);
  EXPECT_EQ(r.report.faces_added_by_split, n - 3);
  EXPECT_EQ(r.report.faces_set_aside, 0u);
  EXPECT_EQ(out.num_faces(), n - 2);
  const auto [unsigned_area, signed_area] = areas(out);
  EXPECT_DOUBLE_EQ(unsigned_area, area);
  EXPECT_DOUBLE_EQ(signed_area, area);
  // Every triangle's corners are corners of the polygon, at the same vertex.
  ASSERT_EQ(r.mesh.corner_origin.size(), out.num_corners());
  for (std::size_t c = 0; c < out.num_corners(); ++c) {
    const Index from = r.mesh.corner_origin[c];
    ASSERT_LT(from, n);
    EXPECT_EQ(r.mesh.vertex_origin[out.corner_vertices[c]], input.corner_vertices[from]);
  }
  for (Index f : r.mesh.face_origin)
    EXPECT_EQ(f, 0u);
  // V - E + F = 1 - holes on one piece: E = V + F - 1 + holes; the outline and the holes open.
  const DefectReport after = detect_defects(out);
  const std::size_t v = input.num_vertices();
  EXPECT_EQ(out.num_vertices(), v);
  EXPECT_EQ(after.num_edges, v + (n - 2) - 1 + holes);
  EXPECT_EQ(after.num_components, 1u);
  EXPECT_EQ(after.num_boundary_loops, 1 + holes);
  // The file's polygon and its triangles are the same surface: a disk with `holes` holes.
  const long long euler = 1 - static_cast<long long>(holes);
  EXPECT_EQ(after.euler_characteristic, euler);
  EXPECT_EQ(detect_defects(input).euler_characteristic, euler);
  EXPECT_EQ(after.boundary_edges.size(), v - inside);
  EXPECT_EQ(after.num_singular_vertices(), 0u);
  EXPECT_TRUE(after.singular_edges.empty());
  EXPECT_TRUE(after.duplicate_faces.empty());
  EXPECT_TRUE(after.zero_area_faces.empty());
  EXPECT_TRUE(after.degenerate_faces.empty());
  if (self_intersections_available())
    EXPECT_FALSE(find_self_intersections(out).has_self_intersections());
}

}  // namespace

TEST(KeyholePolygon, a_square_with_a_square_hole_leaves_the_hole_open_from_every_start_corner) {
  for (const bool reversed : {false, true}) {
    for (const auto* polygon : {&kOneHole, &kOtherSlit}) {
      for (std::size_t rotation = 0; rotation < polygon->size(); ++rotation) {
        SCOPED_TRACE(std::string(reversed ? "reversed" : "as written") +
                     (polygon == &kOneHole ? ", slit 0-4" : ", slit 2-6") + ", rotation " +
                     std::to_string(rotation));
        const Soup s = with_polygon(keyhole_points(false), *polygon, rotation, reversed);
        // The file: 8 edges of the loops and the slit, one piece, two loops of boundary.
        const DefectReport d = detect_defects(s);
        EXPECT_EQ(d.num_edges, 9u);
        EXPECT_EQ(d.num_components, 1u);
        EXPECT_EQ(d.keyhole_polygons_triangulated, 1u);
        EXPECT_EQ(d.slits_set_aside, 0u);
        const RepairResult r = repair(s);
        expect_polygon_with_holes(s, r, 1, 16 - 4);
        EXPECT_NE(to_text(r.report).find("1 keyhole polygon triangulated"), std::string::npos);
        EXPECT_EQ(to_text(r.report).find("keyhole slit"), std::string::npos);
      }
    }
  }
}

TEST(KeyholePolygon, two_holes_joined_by_two_slits_both_stay_open) {
  for (const bool reversed : {false, true}) {
    for (std::size_t rotation = 0; rotation < kTwoHoles.size(); ++rotation) {
      SCOPED_TRACE(std::string(reversed ? "reversed" : "as written") + ", rotation " +
                   std::to_string(rotation));
      const Soup s = with_polygon(keyhole_points(true), kTwoHoles, rotation, reversed);
      const DefectReport d = detect_defects(s);
      EXPECT_EQ(d.num_edges, 12u + 2u);
      EXPECT_EQ(d.num_components, 1u);
      EXPECT_EQ(d.keyhole_polygons_triangulated, 1u);
      const RepairResult r = repair(s);
      expect_polygon_with_holes(s, r, 2, 32 - 4 - 4);
    }
  }
}

TEST(KeyholePolygon, a_bridge_of_two_slits_through_a_vertex_of_its_own_is_cut_too) {
  // The outline reaches the hole through vertex 8 at (1, 0.5), on no loop: 0 -> 8 -> 4 and back.
  Soup points = keyhole_points(false);
  points.add_vertex({1, 0.5, 0});
  const Soup s = with_polygon(points, {0, 8, 4, 5, 6, 7, 4, 8, 0, 1, 2, 3}, 0, false);
  const DefectReport d = detect_defects(s);
  EXPECT_EQ(d.num_edges, 10u);
  EXPECT_TRUE(d.isolated_vertices.empty());  // vertex 8 is the bridge's, used by the polygon
  EXPECT_EQ(d.euler_characteristic, 0);
  const RepairResult r = repair(s);
  expect_polygon_with_holes(s, r, 1, 12, 1);
}

// A keyhole polygon is counted once, as a keyhole: not among the degenerate faces (so
// remove_degenerate_faces keeps it, triangulated), no pinch vertex, and the reading says so.
TEST(KeyholePolygon, is_no_degenerate_face_and_is_triangulated_with_the_degenerate_removed) {
  const Soup s = with_polygon(keyhole_points(false), kOneHole, 0, false);
  const DefectReport d = detect_defects(s);
  EXPECT_EQ(d.keyhole_polygons_triangulated, 1u);
  EXPECT_TRUE(d.degenerate_faces.empty());
  EXPECT_EQ(d.num_singular_vertices(), 0u);
  EXPECT_TRUE(d.has_defects());  // repair changes it: check says so
  RepairOptions options;
  options.remove_degenerate_faces = true;
  const RepairResult r = repair(s, options);
  expect_polygon_with_holes(s, r, 1, 12);
  EXPECT_EQ(r.report.degenerate_faces_removed, 0u);
  // A pinched polygon that is no keyhole (two triangles through one vertex) is degenerate.
  Soup bow = keyhole_points(false);
  bow.add_polygon({0, 1, 4, 0, 2, 3});
  EXPECT_EQ(detect_defects(bow).degenerate_faces, std::vector<Index>{0});
  EXPECT_EQ(detect_defects(bow).keyhole_polygons_triangulated, 0u);
}

TEST(KeyholePolygon, a_hole_wound_like_its_outline_is_split_and_its_slit_set_aside) {
  // The inner loop turns the same way as the outline: the polygon winds twice round the middle,
  // so no triangulation covers it once; the old rule holds (two loops, the slit set aside).
  const Soup s = with_polygon(keyhole_points(false), {0, 4, 7, 6, 5, 4, 0, 1, 2, 3}, 0, false);
  EXPECT_EQ(detect_defects(s).slits_set_aside, 1u);
  const RepairResult r = repair(s);
  EXPECT_EQ(r.report.keyhole_polygons_triangulated, 0u);
  EXPECT_EQ(r.report.slits_set_aside, 1u);
  EXPECT_EQ(r.report.faces_added_by_split, 1u);
  EXPECT_EQ(r.mesh.soup.num_faces(), 2u);
}

TEST(KeyholePolygon, a_slit_to_a_loop_outside_the_outline_is_set_aside) {
  // A flag: the square 0-3 and, through the slit 2 -> 4, a square 4-7 beside it (not a hole).
  Soup s;
  const double pts[8][2] = {{0, 0}, {2, 0}, {2, 2}, {0, 2}, {3, 3}, {5, 3}, {5, 5}, {3, 5}};
  for (const auto& p : pts)
    s.add_vertex({p[0], p[1], 0});
  s.add_polygon({0, 1, 2, 4, 5, 6, 7, 4, 2, 3});
  const DefectReport d = detect_defects(s);
  EXPECT_EQ(d.keyhole_polygons_triangulated, 0u);
  EXPECT_EQ(d.slits_set_aside, 1u);
  EXPECT_EQ(d.num_edges, 9u);
  const RepairResult r = repair(s);
  EXPECT_EQ(r.report.keyhole_polygons_triangulated, 0u);
  EXPECT_EQ(r.report.slits_set_aside, 1u);
  EXPECT_EQ(r.report.faces_split, 1u);
  EXPECT_EQ(r.report.faces_added_by_split, 1u);
  EXPECT_EQ(r.mesh.soup.num_faces(), 2u);
  EXPECT_NE(to_text(r.report).find("1 keyhole slit set aside"), std::string::npos);
}

TEST(KeyholePolygon, the_writers_cut_a_keyhole_polygon_as_repair_does) {
  // STL and 3MF hold triangles only: the unrepaired polygon is cut the same way, the hole open.
  const Soup s = with_polygon(keyhole_points(false), kOneHole, 3, false);
  const Soup triangles = as_triangles(s);
  EXPECT_EQ(triangles.num_faces(), 8u);
  const auto [unsigned_area, signed_area] = areas(triangles);
  EXPECT_DOUBLE_EQ(unsigned_area, 12.0);
  EXPECT_DOUBLE_EQ(signed_area, 12.0);
  const PolygonTriangles cut = triangles_as_written(s);
  ASSERT_EQ(cut.corners.size(), 8u);
  for (std::size_t t = 0; t < 8; ++t) {  // the corners as positions in the polygon, as written
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(s.corner_vertices[cut.corners[t][k]], triangles.polygon(t)[k]);
  }
}

class KeyholeFiles : public test_support::ScratchFolderTest {
 protected:
  KeyholeFiles() : ScratchFolderTest("keyhole") {}
};

// Reading names a keyhole polygon as one (counted in faces_split, and in keyhole_polygons), not
// as pinched; a pinched polygon that is no keyhole keeps its words.
TEST_F(KeyholeFiles, reading_names_a_keyhole_polygon_as_one) {
  const std::string in = write("keyhole_and_bow.obj",
                               "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\n"
                               "v 1 1 0\nv 1 3 0\nv 3 3 0\nv 3 1 0\nv 9 9 0\n"
                               "f 1 5 6 7 8 5 1 2 3 4\nf 2 3 9 2 4 9\n");
  ReadInfo info;
  read_soup(in, &info);
  EXPECT_EQ(info.faces_kept, 0u);
  EXPECT_EQ(info.faces_split, 2u);
  EXPECT_EQ(info.keyhole_polygons, 1u);
  EXPECT_EQ(describe_reading(info),
            "2 face records: 0 kept, 1 split (pinched: a vertex revisited), 1 keyhole polygon (an "
            "outline and holes joined by slits: cut into triangles, the holes left open)");
  ReadInfo assimp;
  read_soup(std::string(MESHBRIDGE_REALWORLD_DIR) + "/../realworld2/assimp_concave_polygon.obj",
            &assimp);
  EXPECT_EQ(describe_reading(assimp),
            "1 face record: 0 kept, 1 keyhole polygon (an outline and holes joined by slits: cut "
            "into triangles, the holes left open)");
}

TEST_F(KeyholeFiles, an_obj_keyhole_polygon_repaired_and_read_back_keeps_its_hole) {
  const std::string in = write("keyhole.obj",
                               "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 0 4 0\n"
                               "v 1 1 0\nv 1 3 0\nv 3 3 0\nv 3 1 0\n"
                               "f 1 5 6 7 8 5 1 2 3 4\n");
  const Soup s = read_soup(in);
  ASSERT_EQ(s.num_faces(), 1u);
  ASSERT_EQ(s.num_corners(), 10u);
  const RepairResult r = repair(s);
  expect_polygon_with_holes(s, r, 1, 12);
  const std::string out = path("repaired.obj");
  write_mesh(out, r.mesh);
  const Soup again = read_soup(out);
  EXPECT_EQ(again.num_faces(), 8u);
  const DefectReport d = detect_defects(again);
  EXPECT_EQ(d.num_edges, 16u);
  EXPECT_EQ(d.num_boundary_loops, 2u);
  EXPECT_EQ(d.boundary_edges.size(), 8u);
  EXPECT_EQ(d.num_components, 1u);
  EXPECT_TRUE(d.duplicate_faces.empty());
  EXPECT_TRUE(d.degenerate_faces.empty());
  EXPECT_EQ(areas(again).first, 12.0);
  // A second repair finds nothing more to do.
  const RepairResult second = repair(again);
  EXPECT_EQ(second.report.keyhole_polygons_triangulated, 0u);
  EXPECT_EQ(second.report.faces_out, 8u);
}

// assimp's test model (Debian assimp-testmodels, tests/data/realworld2): one face of 66 corners,
// an outline of 32 corners and a hole of 32 joined by the slit 31 -> 32 ... 32 -> 31, all in the
// plane x = -1.146.
TEST(KeyholePolygon, assimps_concave_polygon_is_a_ring_with_an_open_hole) {
  const Soup s = read_soup(std::string(MESHBRIDGE_REALWORLD_DIR) +
                           "/../realworld2/assimp_concave_polygon.obj");
  ASSERT_EQ(s.num_faces(), 1u);
  ASSERT_EQ(s.num_corners(), 66u);
  const DefectReport d = detect_defects(s);
  EXPECT_EQ(d.num_edges, 65u);
  EXPECT_EQ(d.num_components, 1u);
  EXPECT_EQ(d.num_boundary_loops, 2u);
  EXPECT_EQ(d.boundary_edges.size(), 64u);
  EXPECT_EQ(d.keyhole_polygons_triangulated, 1u);
  EXPECT_TRUE(d.degenerate_faces.empty());  // counted once, as a keyhole
  EXPECT_EQ(d.num_singular_vertices(), 0u);
  EXPECT_EQ(d.slits_set_aside, 0u);
  const RepairResult r = repair(s);
  EXPECT_EQ(r.report.keyhole_polygons_triangulated, 1u);
  EXPECT_EQ(r.report.slits_set_aside, 0u);
  EXPECT_EQ(r.report.faces_out, 64u);
  EXPECT_EQ(r.report.faces_added_by_split, 63u);
  const Soup& out = r.mesh.soup;
  // The ring's area from the file's two loops (y, z: the plane's coordinates): corners 0-30
  // and 65 (vertex 31) are the outline, 32-63 (vertex 32 at 32 and at 64) the hole.
  const auto loop_area = [&](const std::vector<Index>& loop) {
    double twice = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point& a = s.positions[loop[i]];
      const Point& b = s.positions[loop[(i + 1) % loop.size()]];
      twice += a[1] * b[2] - b[1] * a[2];
    }
    return twice / 2;
  };
  std::vector<Index> outline(s.corner_vertices.begin(), s.corner_vertices.begin() + 31);
  outline.push_back(s.corner_vertices[65]);
  const std::vector<Index> hole(s.corner_vertices.begin() + 32, s.corner_vertices.begin() + 64);
  const double outline_area = loop_area(outline), hole_area = loop_area(hole);
  EXPECT_LT(outline_area * hole_area, 0);  // they turn opposite ways
  const double ring = std::abs(outline_area + hole_area);
  EXPECT_LT(ring, std::abs(outline_area) - 0.5);  // the hole is more than half a unit square
  double unsigned_sum = 0, signed_sum = 0;
  for (std::size_t f = 0; f < out.num_faces(); ++f) {
    const PolygonView p = out.polygon(f);
    ASSERT_EQ(p.size(), 3u);
    const Point& a = out.positions[p[0]];
    const Point& b = out.positions[p[1]];
    const Point& c = out.positions[p[2]];
    const double area = ((b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1])) / 2;
    unsigned_sum += std::abs(area);
    signed_sum += area;
  }
  EXPECT_NEAR(unsigned_sum, ring, 1e-12);
  EXPECT_NEAR(std::abs(signed_sum), ring, 1e-12);
  const DefectReport after = detect_defects(out);
  EXPECT_EQ(after.num_edges, 128u);
  EXPECT_EQ(after.num_components, 1u);
  EXPECT_EQ(after.num_boundary_loops, 2u);
  EXPECT_EQ(after.boundary_edges.size(), 64u);
  EXPECT_TRUE(after.duplicate_faces.empty());
  EXPECT_TRUE(after.singular_edges.empty());
  if (self_intersections_available())
    EXPECT_FALSE(find_self_intersections(out).has_self_intersections());
}
