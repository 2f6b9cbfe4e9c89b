// SPDX-License-Identifier: GPL-3.0-or-later
// Rule: copies of one polygon (a face given twice or more, either way round) glue back to back
// where two pairs would otherwise share an output edge, instead of being cut open. Such copies
// are what a sheet written once per orientation is made of (a slicer pairs every facet with its
// reversed twin and sees no open edge); a repair must not leave more boundary edges than a
// slicer finds in the input. A copy that its solid does not need stays a loose sheet, and the
// solids close.

#include "meshbridge/models/canonical_models.h"

#include "rule_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace meshbridge;
using namespace meshbridge::rule_test;

namespace {

// Three triangles of chair_model.obj (tests/data/realworld; its vertices 1687, 1729, 1765, 1764,
// 1814, renumbered), each written once per orientation: a strip A-C-B whose two inner edges
// (0-3, 0-4) join rim vertices, so the strip's two layers would share them.
const char* const kChairStrip = R"(OFF
5 6 0
-0.0331816 0.00364709 -0.0846183
-0.0243312 0.0153399 -0.103028
-0.0539718 0.00594292 -0.0623719
-0.0423743 0.0354951 -0.0979262
-0.0483549 0.0205974 -0.0803269
3 3 0 1  3 1 0 3  3 2 0 4  3 4 0 2  3 0 3 4  3 4 3 0)";

constexpr double kPi = 3.14159265358979323846;
constexpr double kOpen = NAN;  // an open component: its volume is not checked

// Five vertices of chair_model.obj (1458, 1528, 1552, 1584, 1615, renumbered in that order) and
// the ten faces on them: two triangles given twice each way, one once each way.
const char* const kChairQuadrupledStrip = R"(OFF
5 10 0
0.121695 0.102068 -0.244211
0.117947 0.0368206 -0.181638
-0.0291217 -0.0214046 -0.0641529
-0.0170035 -0.0341462 -0.0574451
-0.00643832 -0.0452549 -0.0515976
3 1 0 2  3 2 0 1  3 0 1 2  3 2 1 0  3 1 2 3  3 3 2 1  3 2 1 3  3 3 1 2  3 3 1 4  3 4 1 3)";

// Each polygon followed by its reversed copy.
Soup doubled(const Soup& soup) {
  Soup out;
  out.positions = soup.positions;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    std::vector<Index> polygon(p.begin(), p.end());
    out.add_polygon(polygon);
    std::reverse(polygon.begin(), polygon.end());
    out.add_polygon(polygon);
  }
  return out;
}

// The soup with copies of polygon f appended, as given (reversed = false) or reversed.
Soup with_copies(const Soup& soup, Index f, const std::vector<bool>& reversed) {
  Soup out = soup;
  for (bool r : reversed) {
    const PolygonView p = soup.polygon(f);
    std::vector<Index> polygon(p.begin(), p.end());
    if (r)
      std::reverse(polygon.begin(), polygon.end());
    out.add_polygon(polygon);
  }
  return out;
}

// A unit square strip of n unit squares along x, two triangles each, in the plane z = 0.
Soup strip(int n) {
  Soup soup;
  for (int i = 0; i <= n; ++i) {
    soup.add_vertex({double(i), 0, 0});
    soup.add_vertex({double(i), 1, 0});
  }
  for (int i = 0; i < n; ++i) {
    const Index a = 2 * i, b = 2 * i + 2, c = 2 * i + 3, d = 2 * i + 1;
    soup.add_polygon({a, b, c});
    soup.add_polygon({a, c, d});
  }
  return soup;
}

// A regular hexagon of six triangles around its centre (vertex 0), in the plane z = 0.
Soup hexagon() {
  Soup soup;
  soup.add_vertex({0, 0, 0});
  for (int k = 0; k < 6; ++k)
    soup.add_vertex({std::cos(k * kPi / 3), std::sin(k * kPi / 3), 0});
  for (Index k = 0; k < 6; ++k)
    soup.add_polygon({0, 1 + k, 1 + (k + 1) % 6});
  return soup;
}

// Cube A of two_cubes_sharing_edge() alone: 8 vertices, 12 outward triangles.
Soup unit_cube() {
  const Soup two = models::two_cubes_sharing_edge();
  Soup cube;
  for (Index v = 0; v < 8; ++v)
    cube.add_vertex(two.positions[v]);
  for (std::size_t f = 0; f < 12; ++f) {
    const PolygonView p = two.polygon(f);
    cube.add_polygon(std::vector<Index>(p.begin(), p.end()));
  }
  return cube;
}

// The first face of cube A on the edge the two cubes share (vertices 3 and 7).
Index face_on_shared_edge(const Soup& soup) {
  for (std::size_t f = 0; f < 12; ++f) {
    const PolygonView p = soup.polygon(f);
    if (std::count(p.begin(), p.end(), 3u) && std::count(p.begin(), p.end(), 7u))
      return static_cast<Index>(f);
  }
  return kNoIndex;
}

// Copies of one polygon are interchangeable: each face is named by its polygon's first copy.
std::vector<Index> polygon_names(const Soup& soup) {
  std::vector<std::vector<Index>> cycles(soup.num_faces());
  std::vector<Index> name(soup.num_faces());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    std::vector<Index> forward(p.begin(), p.end());
    std::rotate(forward.begin(), std::min_element(forward.begin(), forward.end()), forward.end());
    std::vector<Index> backward(forward.rbegin(), forward.rend());
    std::rotate(backward.begin(), std::min_element(backward.begin(), backward.end()),
                backward.end());
    cycles[f] = std::min(forward, backward);
    name[f] = static_cast<Index>(f);
    for (std::size_t g = 0; g < f; ++g) {
      if (cycles[g] == cycles[f]) {
        name[f] = name[g];
        break;
      }
    }
  }
  return name;
}

// One component of a repair: the names of its input faces (sorted) and its signed volume.
struct Part {
  std::vector<Index> faces;
  double volume;
};

// The components of a repair of a shuffled model, by original face names, in sorted order.
std::vector<Part> parts(const Outcome& o, const std::vector<Index>& to_original,
                        const std::vector<Index>& name) {
  std::map<Index, Part> by_component;
  for (std::size_t f = 0; f < to_original.size(); ++f) {
    Part& part = by_component[o.component[f]];
    part.faces.push_back(name[to_original[f]]);
    part.volume = o.volume[f];
  }
  std::vector<Part> out;
  for (auto& [component, part] : by_component) {
    std::sort(part.faces.begin(), part.faces.end());
    out.push_back(part);
  }
  std::sort(out.begin(), out.end(), [](const Part& a, const Part& b) { return a.faces < b.faces; });
  return out;
}

// Repairs `model` in its order and 200 shuffles; checks the invariants, the boundary edges
// after, and the components (faces by name; volume where `expected` gives a finite one).
void expect_parts(const Soup& model, std::size_t boundary_after, std::vector<Part> expected) {
  std::sort(expected.begin(), expected.end(),
            [](const Part& a, const Part& b) { return a.faces < b.faces; });
  const std::vector<Index> name = polygon_names(model);
  for_face_orders(model, 200, [&](const Soup& s, const std::vector<Index>& to_original) {
    const Outcome o = repair_and_label(s);
    test_support::expect_repair_invariants(s, o.result);
    EXPECT_EQ(o.result.report.faces_out, model.num_faces());
    EXPECT_EQ(o.result.report.boundary_edges_after, boundary_after);
    const std::vector<Part> got = parts(o, to_original, name);
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_EQ(got[i].faces, expected[i].faces) << "component " << i;
      if (std::isfinite(expected[i].volume))
        EXPECT_NEAR(got[i].volume, expected[i].volume, 1e-12) << "component " << i;
    }
  });
}

}  // namespace

TEST(PairContenders, copies_in_a_doubled_strip_glue_back_to_back) {
  // The chair's strip: the layers would share both inner edges, so each triangle closes on its
  // reversed copy (three pillows, as the slicer's three parts).
  const Soup chair = from_off(kChairStrip);
  expect_parts(chair, 0, {{{0, 0}, 0.0}, {{2, 2}, 0.0}, {{4, 4}, 0.0}});
  const RepairResult r = repair(chair);
  EXPECT_EQ(r.report.sides_cut_to_stay_manifold, 0u);
  EXPECT_EQ(r.report.sides_paired_with_copies, 8u);  // two exchanges, one per inner edge
  // Four triangles in a row: every inner edge joins rim vertices.
  expect_parts(doubled(strip(2)), 0, {{{0, 0}, 0.0}, {{2, 2}, 0.0}, {{4, 4}, 0.0}, {{6, 6}, 0.0}});
  // Two triangles: the diagonal joins rim vertices.
  expect_parts(doubled(strip(1)), 0, {{{0, 0}, 0.0}, {{2, 2}, 0.0}});
}

TEST(PairContenders, strip_given_twice_the_same_way_closes) {
  // Both copies wound alike: orientation reverses one layer, and the copies glue back to back as
  // above (before this rule: 6 boundary edges; the slicer finds 12 open edges in the input).
  const Soup once = strip(2);
  Soup twice = once;
  for (std::size_t f = 0; f < once.num_faces(); ++f) {
    const PolygonView p = once.polygon(f);
    twice.add_polygon(std::vector<Index>(p.begin(), p.end()));
  }
  expect_parts(twice, 0, {{{0, 0}, 0.0}, {{1, 1}, 0.0}, {{2, 2}, 0.0}, {{3, 3}, 0.0}});
  // A third layer (wound as the first) has no partner: it stays one loose sheet, its 6 rim edges
  // open, as the slicer's 6 (before this rule: 12).
  Soup thrice = doubled(once);
  for (std::size_t f = 0; f < once.num_faces(); ++f) {
    const PolygonView p = once.polygon(f);
    thrice.add_polygon(std::vector<Index>(p.begin(), p.end()));
  }
  expect_parts(thrice, 6,
               {{{0, 0}, 0.0}, {{2, 2}, 0.0}, {{4, 4}, 0.0}, {{6, 6}, 0.0}, {{0, 2, 4, 6}, kOpen}});
}

TEST(PairContenders, doubled_sheet_with_inner_vertex_stays_one_pillow) {
  // Every inner edge of a doubled hexagon has the centre at one end, whose layers are two fans:
  // nothing would share an output edge, so nothing is exchanged and the sheet is one pillow.
  const Soup model = doubled(hexagon());
  expect_parts(model, 0, {{{0, 0, 2, 2, 4, 4, 6, 6, 8, 8, 10, 10}, 0.0}});
  EXPECT_EQ(repair(model).report.sides_paired_with_copies, 0u);
}

TEST(PairContenders, quadrupled_triangle_in_doubled_sheet_closes) {
  // chair_model.obj's doubled patch: a triangle of a doubled sheet given twice more (once each
  // way), so its edges carry 6 sides and the extra layer must close on itself.
  const Soup model = with_copies(doubled(hexagon()), 0, {false, true});
  expect_parts(model, 0, {{{0, 0}, 0.0}, {{0, 0, 2, 2, 4, 4, 6, 6, 8, 8, 10, 10}, 0.0}});
}

TEST(PairContenders, quadrupled_strip_from_chair_closes) {
  // chair_model.obj's doubled patch where it failed (vertices 1458, 1528, 1552, 1584, 1615):
  // triangles T (faces 0-3) and U (4-7) given twice each way, V (8-9) once each way, in a strip
  // T-U-V whose inner edges join rim vertices. Before this rule: 4 boundary edges.
  const Soup model = from_off(kChairQuadrupledStrip);
  expect_parts(model, 0,
               {{{0, 0}, 0.0}, {{0, 0}, 0.0}, {{4, 4}, 0.0}, {{4, 4}, 0.0}, {{8, 8}, 0.0}});
}

TEST(PairContenders, duplicate_triangle_on_singular_edge_stays_loose) {
  // Two cubes sharing an edge, one triangle on that edge given once more: both cubes close, the
  // extra copy is a loose sheet (3 boundary edges, as a slicer finds in the input).
  const Soup two = models::two_cubes_sharing_edge();
  const Index f = face_on_shared_edge(two);
  std::vector<Index> cube_a, cube_b;
  for (Index g = 0; g < 12; ++g)
    cube_a.push_back(g);
  for (Index g = 12; g < 24; ++g)
    cube_b.push_back(g);
  for (bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "copy reversed" : "copy as given");
    expect_parts(with_copies(two, f, {reversed}), 3, {{{f}, kOpen}, {cube_a, 1.0}, {cube_b, 1.0}});
  }
  // Given twice more, the same way: the two extra copies close on each other.
  expect_parts(with_copies(two, f, {false, false}), 0,
               {{{f, f}, 0.0}, {cube_a, 1.0}, {cube_b, 1.0}});
  // Two more opposite ones: the same.
  expect_parts(with_copies(two, f, {false, true}), 0,
               {{{f, f}, 0.0}, {cube_a, 1.0}, {cube_b, 1.0}});
}

TEST(PairContenders, duplicate_triangle_on_manifold_edges_stays_loose) {
  // A closed cube, one triangle given once more: its edges carry 3 sides each; the cube closes
  // and the copy is a loose sheet. Given once more each way, the two copies close on each other.
  const Soup cube = unit_cube();
  std::vector<Index> all(12);
  for (Index g = 0; g < 12; ++g)
    all[g] = g;
  for (bool reversed : {false, true}) {
    SCOPED_TRACE(reversed ? "copy reversed" : "copy as given");
    expect_parts(with_copies(cube, 5, {reversed}), 3, {{{5}, kOpen}, {all, 1.0}});
  }
  expect_parts(with_copies(cube, 5, {false, true}), 0, {{{5, 5}, 0.0}, {all, 1.0}});
}

TEST(PairContenders, doubled_book_pages_close_as_pillows) {
  // Three doubled pages on one spine (6 sides there); each page a square of two triangles whose
  // diagonal joins rim vertices: every triangle closes on its reversed copy.
  Soup book;
  book.add_vertex({0, 0, 0});
  book.add_vertex({0, 0, 1});
  for (int k = 0; k < 3; ++k) {
    const double angle = 2 * kPi * k / 3;
    const Index a = book.add_vertex({std::cos(angle), std::sin(angle), 0});
    const Index b = book.add_vertex({std::cos(angle), std::sin(angle), 1});
    book.add_polygon({0, a, b});
    book.add_polygon({0, b, 1});
  }
  std::vector<Part> pillows;
  for (Index f = 0; f < 12; f += 2)
    pillows.push_back({{f, f}, 0.0});
  expect_parts(doubled(book), 0, pillows);
}
