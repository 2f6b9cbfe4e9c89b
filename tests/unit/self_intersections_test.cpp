// SPDX-License-Identifier: GPL-3.0-or-later
// find_self_intersections(): one test per kind of contact, meshes built in code, each checked
// over face orders (shuffled faces, rotated start corners) and as quads and triangles.
#include "meshbridge/self_intersections.h"
#include "meshbridge/errors.h"
#include "meshbridge/models/benchmark_models.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"

#include "meshbridge/io.h"

#include "scratch_folder.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>

namespace meshbridge {
namespace {

using test_support::shuffled;

//! Appends an axis-aligned box [lo, hi] on vertices of its own, faces outward (inward if
//! `inward`), as 6 quads or 12 triangles.
void add_box(Soup& soup, const Point& lo, const Point& hi, bool triangles, bool inward = false) {
  const Index base = static_cast<Index>(soup.num_vertices());
  for (int c = 0; c < 8; ++c)
    soup.add_vertex({c & 1 ? hi[0] : lo[0], c & 2 ? hi[1] : lo[1], c & 4 ? hi[2] : lo[2]});
  // Outward quads of the corners c = x + 2y + 4z.
  const std::array<std::array<Index, 4>, 6> quads = {
      {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
  for (auto q : quads) {
    for (Index& v : q)
      v += base;
    if (inward)
      std::swap(q[1], q[3]);
    if (triangles) {
      soup.add_polygon({q[0], q[1], q[2]});
      soup.add_polygon({q[0], q[2], q[3]});
    } else {
      soup.add_polygon(q);
    }
  }
}

//! The report of `soup` under 4 face orders: the counts must not depend on the order.
struct Counts {
  std::size_t pairs, faces, component_pairs, components;
};
Counts counts_over_orders(const Soup& soup) {
  const SelfIntersectionReport first = find_self_intersections(soup);
  const Counts counts{first.face_pairs.size(), first.faces.size(), first.component_pairs.size(),
                      first.num_components};
  for (std::uint32_t seed = 1; seed <= 3; ++seed) {
    const SelfIntersectionReport other = find_self_intersections(shuffled(soup, seed));
    EXPECT_EQ(other.face_pairs.size(), counts.pairs) << "seed " << seed;
    EXPECT_EQ(other.faces.size(), counts.faces) << "seed " << seed;
    EXPECT_EQ(other.component_pairs.size(), counts.component_pairs) << "seed " << seed;
    EXPECT_EQ(other.num_components, counts.components) << "seed " << seed;
  }
  return counts;
}

TEST(SelfIntersections, crossing_cubes) {
  // B's three low faces cross A's three high faces, each two of them: 6 pairs of quads.
  Soup quads;
  add_box(quads, {0, 0, 0}, {1, 1, 1}, false);
  add_box(quads, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, false);
  const Counts q = counts_over_orders(quads);
  EXPECT_EQ(q.pairs, 6u);
  EXPECT_EQ(q.faces, 6u);
  EXPECT_EQ(q.component_pairs, 1u);
  EXPECT_EQ(q.components, 2u);
  const SelfIntersectionReport r = find_self_intersections(quads);
  // A's faces x = 1 (5), y = 1 (3), z = 1 (1); B's x = 0.5 (10), y = 0.5 (8), z = 0.5 (6).
  const std::vector<Index> faces = {1, 3, 5, 6, 8, 10};
  EXPECT_EQ(r.faces, faces);
  EXPECT_EQ(r.component_pairs, (std::vector<FacePair>{{0, 1}}));

  Soup triangles;
  add_box(triangles, {0, 0, 0}, {1, 1, 1}, true);
  add_box(triangles, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, true);
  const Counts t = counts_over_orders(triangles);
  EXPECT_EQ(t.component_pairs, 1u);
  EXPECT_EQ(t.faces, 12u);  // both triangles of each of the 6 quads
}

TEST(SelfIntersections, piercing_triangle) {
  // A lone triangle in the plane y = 0.3 through the cube's bottom (z = 0), its tip inside;
  // it meets neither diagonal of the bottom square (x = y, x + y = 1): one face crossed.
  for (bool triangles : {false, true}) {
    Soup soup;
    add_box(soup, {0, 0, 0}, {1, 1, 1}, triangles);
    const Index a = soup.add_vertex({0.4, 0.3, -0.5});
    const Index b = soup.add_vertex({0.6, 0.3, -0.5});
    const Index c = soup.add_vertex({0.5, 0.3, 0.5});
    soup.add_polygon({a, b, c});
    const Counts counts = counts_over_orders(soup);
    EXPECT_EQ(counts.pairs, 1u) << "triangles " << triangles;
    EXPECT_EQ(counts.faces, 2u);
    EXPECT_EQ(counts.component_pairs, 1u);
    EXPECT_EQ(counts.components, 2u);
  }
}

TEST(SelfIntersections, fold) {
  // Across a shared edge: the second triangle folded flat onto the first.
  Soup edge_fold;
  edge_fold.add_vertex({0, 0, 0});
  edge_fold.add_vertex({1, 0, 0});
  edge_fold.add_vertex({0, 1, 0});
  edge_fold.add_vertex({0.5, 0.5, 0});
  edge_fold.add_polygon({0, 1, 2});
  edge_fold.add_polygon({1, 0, 3});
  const Counts e = counts_over_orders(edge_fold);
  EXPECT_EQ(e.pairs, 1u);
  EXPECT_EQ(e.faces, 2u);
  EXPECT_EQ(e.component_pairs, 0u);  // one shell crossing itself
  EXPECT_EQ(e.components, 1u);

  // Through a shared vertex: a triangle in the plane x = y whose far side pierces the first.
  Soup vertex_fold;
  vertex_fold.add_vertex({0, 0, 0});
  vertex_fold.add_vertex({1, 0, 0});
  vertex_fold.add_vertex({0, 1, 0});
  vertex_fold.add_vertex({0.4, 0.4, 1});
  vertex_fold.add_vertex({0.4, 0.4, -1});
  vertex_fold.add_polygon({0, 1, 2});
  vertex_fold.add_polygon({0, 3, 4});
  EXPECT_EQ(counts_over_orders(vertex_fold).pairs, 1u);

  // A cube with one top corner pushed down through its bottom face: folds within one shell.
  Soup pushed;
  add_box(pushed, {0, 0, 0}, {1, 1, 1}, true);
  pushed.positions[7] = {0.9, 0.9, -0.5};
  const Counts p = counts_over_orders(pushed);
  EXPECT_EQ(p.pairs, 6u);
  EXPECT_EQ(p.component_pairs, 0u);
}

TEST(SelfIntersections, coplanar_overlap) {
  Soup soup;  // two triangles in z = 0, no shared vertex, overlapping
  soup.add_vertex({0, 0, 0});
  soup.add_vertex({2, 0, 0});
  soup.add_vertex({0, 2, 0});
  soup.add_vertex({0.5, 0.5, 0});
  soup.add_vertex({3, 0.5, 0});
  soup.add_vertex({0.5, 3, 0});
  soup.add_polygon({0, 1, 2});
  soup.add_polygon({3, 4, 5});
  const Counts counts = counts_over_orders(soup);
  EXPECT_EQ(counts.pairs, 1u);
  EXPECT_EQ(counts.component_pairs, 1u);

  // The same triangle twice (a duplicate face) overlaps itself entirely.
  Soup twice;
  twice.add_vertex({0, 0, 0});
  twice.add_vertex({1, 0, 0});
  twice.add_vertex({0, 1, 0});
  twice.add_polygon({0, 1, 2});
  twice.add_polygon({2, 1, 0});
  EXPECT_EQ(counts_over_orders(twice).pairs, 1u);
}

// Solids that share a wall (prisms24: neighbouring prisms; plate_box_rib: the rib's foot on
// the plate) give that wall twice, with opposite winding: the two copies overlap over their
// whole area, a coplanar overlap, so they count (face contact; edge and vertex contact do not).
// Exactly those pairs and no other, before and after repair (which keeps every wall).
// Where repair splits one pair's edge p-q at its midpoint m, the faces of that pair have m as a
// corner and those of the other pair do not: a triangle (p, m, x) meets (p, q, r) along p-m, a
// side from their one shared corner. Touching, not crossing: in space, or in one plane across
// p-q; in one plane on the same side of p-q they overlap, and count. (Two planes through p-q
// meet nowhere else, so no fold passes there.)
TEST(SelfIntersections, touching_along_a_side_from_the_shared_corner) {
  const auto contact = [](const Point& x, const Point& r) {
    Soup soup;
    for (const Point& v : {Point(0, 0, 0), Point(2, 0, 0), Point(1, 0, 0), x, r})
      soup.add_vertex(v);
    soup.add_polygon({0, 2, 3});  // (p, m, x) and (m, q, x): one pair's face, cut at m
    soup.add_polygon({2, 1, 3});
    soup.add_polygon({1, 0, 4});  // (q, p, r): the other pair's face, without m
    return counts_over_orders(soup).pairs;
  };
  EXPECT_EQ(contact({1, 1, 0}, {1, 0, 1}), 0u);    // at right angles
  EXPECT_EQ(contact({1, 1, 0}, {1, -1, 0}), 0u);   // in one plane, across p-q
  EXPECT_EQ(contact({1, 1, 1}, {1, 1, -1}), 0u);   // at an acute angle
  EXPECT_EQ(contact({1, 1, 0}, {1, 2, 0}), 2u);    // in one plane, on one side: they overlap
  EXPECT_EQ(contact({1, 1, 0}, {0.5, 3, 0}), 2u);  // the same, the other wider
  // Faces that share no corner still count at any contact (as CGAL counts them).
  Soup apart;
  for (const Point& v : {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0.5, 0, 0),
                         Point(3, 0, 0), Point(1, 0, 1)})
    apart.add_vertex(v);
  apart.add_polygon({0, 1, 2});
  apart.add_polygon({3, 4, 5});
  EXPECT_EQ(counts_over_orders(apart).pairs, 1u);
}

//! The self-intersecting face pairs of a file, read as it is.
std::size_t pairs_in(const std::string& path) {
  return find_self_intersections(read_soup(path)).face_pairs.size();
}

// A real part whose repair splits 4 edges at their midpoint: the output holds the input's pairs
// and no more (the midpoints touch the other pair's edges, touching is not crossing).
TEST(SelfIntersections, repair_adds_none_where_it_splits_edges) {
  const std::string in = std::string(MESHBRIDGE_REALWORLD_DIR) + "2/ur_ur20_forearm_collision.stl";
  const RepairResult repaired = repair(read_soup(in));
  ASSERT_EQ(repaired.report.edges_split_to_stay_manifold, 4u);
  EXPECT_EQ(pairs_in(in), 790u);
  EXPECT_EQ(find_self_intersections(repaired.mesh.soup).face_pairs.size(), 790u);
}

TEST(SelfIntersections, solids_sharing_a_wall_overlap_on_it) {
  struct Case {
    Soup soup;
    std::size_t walls, component_pairs_after;
  };
  for (const Case& c :
       {Case{models::prisms24_hexagon(), 30, 30}, Case{models::plate_with_box_rib(), 2, 1}}) {
    const SelfIntersectionReport report = find_self_intersections(c.soup);
    ASSERT_EQ(report.face_pairs.size(), c.walls);
    EXPECT_EQ(counts_over_orders(c.soup).pairs, c.walls);
    EXPECT_EQ(report.component_pairs.size(), 0u);  // one connected soup before repair
    for (const FacePair& p : report.face_pairs) {
      const PolygonView a = c.soup.polygon(p.f0), b = c.soup.polygon(p.f1);
      std::vector<Index> ca(a.begin(), a.end()), cb(b.begin(), b.end());
      ASSERT_EQ(ca.size(), cb.size());
      // Opposite winding: b read backwards from a's first corner is a.
      const auto start = std::find(cb.begin(), cb.end(), ca[0]);
      ASSERT_NE(start, cb.end()) << p.f0 << "-" << p.f1 << " share no first corner";
      std::rotate(cb.begin(), start, cb.end());
      std::reverse(cb.begin() + 1, cb.end());
      EXPECT_EQ(ca, cb) << p.f0 << "-" << p.f1 << " is not one wall given twice";
    }
    const RepairResult repaired = repair(c.soup);
    const SelfIntersectionReport after = find_self_intersections(repaired.mesh.soup);
    EXPECT_EQ(after.face_pairs.size(), c.walls);
    EXPECT_EQ(after.component_pairs.size(), c.component_pairs_after);
  }
}

TEST(SelfIntersections, touching_not_crossing) {
  for (bool triangles : {false, true}) {
    // A alone: its faces meet along shared edges and at shared corners only.
    Soup soup;
    add_box(soup, {0, 0, 0}, {1, 1, 1}, triangles);
    EXPECT_EQ(counts_over_orders(soup).pairs, 0u);
    // B on an edge of A and C on a corner of A, each on vertices of its own at equal positions
    // (as repair leaves split copies).
    add_box(soup, {1, 1, 0}, {2, 2, 1}, triangles);
    add_box(soup, {1, -1, 1}, {2, 0, 2}, triangles);
    const Counts counts = counts_over_orders(soup);
    EXPECT_EQ(counts.pairs, 0u) << "triangles " << triangles;
    EXPECT_EQ(counts.components, 3u);
  }
  // Two triangles on one edge at an angle, and two on one vertex: touching only.
  Soup hinge;
  hinge.add_vertex({0, 0, 0});
  hinge.add_vertex({1, 0, 0});
  hinge.add_vertex({0, 1, 0});
  hinge.add_vertex({0.5, 0.5, 1e-300});  // nearly flat, still on the far side: exact predicates
  hinge.add_vertex({-1, -1, 0});
  hinge.add_vertex({-1, 0, 0});
  hinge.add_polygon({0, 1, 2});
  hinge.add_polygon({1, 0, 3});
  hinge.add_polygon({0, 4, 5});
  EXPECT_EQ(counts_over_orders(hinge).pairs, 0u);
}

TEST(SelfIntersections, nested_shells_not_crossing) {
  for (bool triangles : {false, true}) {
    Soup soup;
    add_box(soup, {0, 0, 0}, {3, 3, 3}, triangles);
    add_box(soup, {1, 1, 1}, {2, 2, 2}, triangles, true);  // a cavity
    const Counts counts = counts_over_orders(soup);
    EXPECT_EQ(counts.pairs, 0u);
    EXPECT_EQ(counts.components, 2u);
  }
}

TEST(SelfIntersections, repaired_outputs_are_clean) {
  for (const Soup& input : {models::two_cubes_sharing_edge(), models::hourglass(), models::bowtie(),
                            models::checkerboard_cubes(3)}) {
    EXPECT_EQ(find_self_intersections(input).face_pairs.size(), 0u);
    const RepairResult repaired = repair(input);
    const Counts counts = counts_over_orders(repaired.mesh.soup);
    EXPECT_EQ(counts.pairs, 0u);
    EXPECT_EQ(counts.component_pairs, 0u);
  }
  const RepairResult cubes = repair(models::two_cubes_sharing_edge());
  EXPECT_EQ(find_self_intersections(cubes.mesh.soup).num_components, 2u);
}

TEST(SelfIntersections, same_result_on_any_number_of_threads) {
  Soup soup = models::torus_grid(96, 32);
  EXPECT_EQ(find_self_intersections(soup).face_pairs.size(), 0u);
  // A second torus moved a little: the two cross along two loops.
  const Soup copy = models::torus_grid(96, 32);
  const Index base = static_cast<Index>(soup.num_vertices());
  for (const Point& p : copy.positions)
    soup.add_vertex(p + Point(0.13, 0.07, 0.05));
  for (std::size_t f = 0; f < copy.num_faces(); ++f) {
    std::vector<Index> polygon;
    for (Index v : copy.polygon(f))
      polygon.push_back(v + base);
    soup.add_polygon(polygon);
  }
  SelfIntersectionOptions one;
  one.threads = 1;
  const SelfIntersectionReport a = find_self_intersections(soup, one);
  EXPECT_EQ(a.face_pairs.size(), 868u);
  EXPECT_EQ(a.component_pairs, (std::vector<FacePair>{{0, 1}}));
  // An explicit count runs that many threads at any size (the default keeps a mesh this small on
  // one): the cells are shared out differently, the lists come out the same, in the same order.
  for (unsigned threads : {2u, 3u, 5u, 8u}) {
    SelfIntersectionOptions many;
    many.threads = threads;
    const SelfIntersectionReport b = find_self_intersections(soup, many);
    EXPECT_EQ(a.face_pairs, b.face_pairs) << threads << " threads";
    EXPECT_EQ(a.faces, b.faces) << threads << " threads";
    EXPECT_EQ(a.component_pairs, b.component_pairs) << threads << " threads";
    EXPECT_EQ(a.num_components, b.num_components);
    EXPECT_EQ(a.degenerate_triangles, b.degenerate_triangles);
  }
}

//! The same counts after a round trip through every format MeshBridge writes.
class SelfIntersectionFormats : public test_support::ScratchFolderTest {
 protected:
  SelfIntersectionFormats() : ScratchFolderTest("selfx") {}
  //! `soup` written as `name` and read back.
  Soup round_trip(const Soup& soup, const std::string& name) const {
    IndexedMesh mesh;
    mesh.soup = soup;
    for (Index v = 0; v < soup.num_vertices(); ++v)
      mesh.vertex_origin.push_back(v);
    for (Index f = 0; f < soup.num_faces(); ++f)
      mesh.face_origin.push_back(f);
    for (Index c = 0; c < soup.num_corners(); ++c)
      mesh.corner_origin.push_back(c);
    write_mesh(path(name), mesh);
    return read_soup(path(name));
  }
};

TEST_F(SelfIntersectionFormats, crossing_cubes_in_every_format) {
  Soup quads;
  add_box(quads, {0, 0, 0}, {1, 1, 1}, false);
  add_box(quads, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, false);
  const std::vector<Index> faces = {1, 3, 5, 6, 8, 10};
  for (const char* name : {"cubes.obj", "cubes.off", "cubes.ply"}) {
    const SelfIntersectionReport r = find_self_intersections(round_trip(quads, name));
    EXPECT_EQ(r.face_pairs.size(), 6u) << name;
    EXPECT_EQ(r.faces, faces) << name;
    EXPECT_EQ(r.component_pairs.size(), 1u) << name;
  }
  // STL holds triangles: each square becomes two, and every one of the 12 is crossed (either
  // diagonal of a crossed square runs through the corner of the L the crossing draws): 18 pairs.
  Soup triangles;
  add_box(triangles, {0, 0, 0}, {1, 1, 1}, true);
  add_box(triangles, {0.5, 0.5, 0.5}, {1.5, 1.5, 1.5}, true);
  EXPECT_EQ(find_self_intersections(triangles).face_pairs.size(), 18u);
  const SelfIntersectionReport stl = find_self_intersections(round_trip(quads, "cubes.stl"));
  EXPECT_EQ(stl.face_pairs.size(), 18u);
  EXPECT_EQ(stl.faces.size(), 12u);
  EXPECT_EQ(stl.component_pairs.size(), 1u);
}

TEST_F(SelfIntersectionFormats, repaired_two_cubes_stay_clean_in_every_format) {
  const RepairResult repaired = repair(models::two_cubes_sharing_edge());
  for (const char* name : {"fixed.obj", "fixed.off", "fixed.ply", "fixed.stl"}) {
    IndexedMesh mesh = repaired.mesh;
    write_mesh(path(name), mesh);
    const SelfIntersectionReport r = find_self_intersections(read_soup(path(name)));
    EXPECT_EQ(r.face_pairs.size(), 0u) << name;
  }
}

TEST(SelfIntersections, bad_input_is_named) {
  Soup soup;
  soup.add_vertex({0, 0, 0});
  soup.add_polygon({0, 1, 2});
  EXPECT_THROW(find_self_intersections(soup), InvalidSoupError);
}

}  // namespace
}  // namespace meshbridge
