// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"
#include "meshbridge/report_json.h"

#include "test_support.h"

#include <gtest/gtest.h>

using namespace meshbridge;

namespace {

struct ExpectedReport {
  const char* name;
  Soup (*make)();
  std::size_t vertices, faces, edges;
  std::size_t singular_edges, singular_edge_vertices, pinch_vertices;
  std::size_t boundary_edges, boundary_loops, inconsistent_edges, nonorientable;
  std::size_t duplicate_faces, components;
  long long euler;
  bool watertight;
};

Soup moebius() {
  return models::moebius_strip();
}
Soup icosphere() {
  return models::icosphere();
}

const ExpectedReport kExpected[] = {
    // name, make, V, F, E, sing. edges, their vertices, pinch, boundary, loops, inconsistent,
    // non-orientable, duplicates, components, Euler, watertight
    {"twocubes", models::two_cubes_sharing_edge, 14, 24, 35, 1, 2, 0, 0, 0, 0, 0, 0, 1, 3, false},
    {"hourglass", models::hourglass, 7, 8, 12, 0, 0, 1, 0, 0, 0, 0, 0, 2, 3, false},
    {"bowtie", models::bowtie, 5, 2, 6, 0, 0, 1, 6, 1, 0, 0, 0, 2, 1, false},
    {"book_of_three", models::book_of_three, 5, 3, 7, 1, 2, 0, 6, 1, 0, 0, 0, 1, 1, false},
    {"t_junction_rib", models::t_junction_plate_rib, 20, 24, 43, 4, 5, 0, 18, 1, 0, 0, 0, 1, 1,
     false},
    {"plate_box_rib", models::plate_with_box_rib, 36, 72, 103, 5, 4, 0, 0, 0, 0, 0, 2, 1, 5, false},
    {"prisms24", models::prisms24_hexagon, 38, 120, 103, 79, 38, 0, 0, 0, 0, 0, 30, 1, 55, false},
    {"moebius", moebius, 24, 12, 36, 0, 0, 0, 24, 1, 1, 1, 0, 1, 0, false},
    {"icosphere", icosphere, 42, 80, 120, 0, 0, 0, 0, 0, 0, 0, 0, 1, 2, true},
    {"cube_with_hole", models::cube_with_hole, 8, 10, 17, 0, 0, 0, 4, 1, 0, 0, 0, 1, 1, false},
};

void expect_report(const ExpectedReport& x, const DefectReport& r) {
  SCOPED_TRACE(x.name);
  EXPECT_EQ(r.num_vertices, x.vertices);
  EXPECT_EQ(r.num_faces, x.faces);
  EXPECT_EQ(r.num_edges, x.edges);
  EXPECT_EQ(r.singular_edges.size(), x.singular_edges);
  EXPECT_EQ(r.singular_edge_vertices.size(), x.singular_edge_vertices);
  EXPECT_EQ(r.pinch_vertices.size(), x.pinch_vertices);
  EXPECT_EQ(r.boundary_edges.size(), x.boundary_edges);
  EXPECT_EQ(r.num_boundary_loops, x.boundary_loops);
  EXPECT_EQ(r.inconsistent_edges.size(), x.inconsistent_edges);
  EXPECT_EQ(r.num_nonorientable_components, x.nonorientable);
  EXPECT_EQ(r.duplicate_faces.size(), x.duplicate_faces);
  EXPECT_EQ(r.num_components, x.components);
  EXPECT_EQ(r.euler_characteristic, x.euler);
  EXPECT_EQ(r.watertight, x.watertight);
  EXPECT_TRUE(r.isolated_vertices.empty());
  EXPECT_TRUE(r.degenerate_faces.empty());
  EXPECT_TRUE(r.zero_area_faces.empty());
  EXPECT_EQ(r.has_defects(), !x.watertight);
}

}  // namespace

TEST(DetectDefects, canonical_cases_have_exact_counts) {
  for (const ExpectedReport& x : kExpected)
    expect_report(x, detect_defects(x.make()));
}

TEST(DetectDefects, report_does_not_depend_on_face_order_or_polygon_start) {
  for (const ExpectedReport& x : kExpected) {
    for (std::uint32_t seed : {1u, 2u, 3u})
      expect_report(x, detect_defects(test_support::shuffled(x.make(), seed)));
  }
}

TEST(DetectDefects, twocubes_lists_the_shared_edge_with_four_contenders) {
  const Soup soup = models::two_cubes_sharing_edge();
  const DefectReport r = detect_defects(soup);
  ASSERT_EQ(r.singular_edges.size(), 1u);
  const SingularEdge& edge = r.singular_edges[0];
  EXPECT_EQ(edge.contenders, 4u);
  const Point& a = soup.positions[edge.vertices.v0];
  const Point& b = soup.positions[edge.vertices.v1];
  EXPECT_EQ(a[0], 1.0);
  EXPECT_EQ(a[1], 1.0);
  EXPECT_EQ(b[0], 1.0);
  EXPECT_EQ(b[1], 1.0);
  EXPECT_EQ(r.singular_edge_vertices, (std::vector<Index>{edge.vertices.v0, edge.vertices.v1}));
}

TEST(DetectDefects, degenerate_zero_area_duplicate_and_isolated_elements) {
  Soup soup;
  for (int i = 0; i < 6; ++i)
    soup.add_vertex({double(i % 3), double(i / 3), 0});
  soup.add_vertex({5, 5, 5});      // 6: isolated
  soup.add_polygon({0, 1, 4});     // 0
  soup.add_polygon({4, 1, 0});     // 1: duplicate of 0 (other orientation)
  soup.add_polygon({0, 1, 2});     // 2: collinear, zero area
  soup.add_polygon({0, 0, 4});     // 3: degenerate, set aside
  soup.add_polygon({1, 2, 5, 5});  // 4: degenerate, kept as triangle 1 2 5
  const DefectReport r = detect_defects(soup);
  EXPECT_EQ(r.duplicate_faces, std::vector<Index>{1});
  EXPECT_EQ(r.zero_area_faces, (std::vector<Index>{2, 3}));
  EXPECT_EQ(r.degenerate_faces, (std::vector<Index>{3, 4}));
  EXPECT_EQ(r.faces_set_aside, std::vector<Index>{3});
  EXPECT_EQ(r.isolated_vertices, (std::vector<Index>{3, 6}));
  EXPECT_TRUE(r.has_defects());
}

TEST(DetectDefects, isolated_vertices_are_listed_but_are_no_defect) {
  Soup soup = models::icosphere(1);
  const Index lone = soup.add_vertex({5, 5, 5});
  const DefectReport r = detect_defects(soup);
  EXPECT_EQ(r.isolated_vertices, std::vector<Index>{lone});
  EXPECT_TRUE(r.watertight);
  EXPECT_FALSE(r.has_defects());
}

TEST(DetectDefects, text_carries_the_counts) {
  const DefectReport r = detect_defects(models::two_cubes_sharing_edge());
  const std::string text = to_text(r);
  EXPECT_NE(text.find("singular edges: 1  [3-7 (4 faces)]"), std::string::npos);
  EXPECT_NE(text.find("watertight no"), std::string::npos);
}

// detect_defects() consumes its grouping of the sides as it goes (its side-to-edge array becomes
// the manifold pairing, the bridges are freed early); repair() detects the input on a grouping it
// keeps for the pipeline. Both must report the same elements.
TEST(DetectDefects, consuming_the_grouping_reports_what_repair_detects) {
  ReportJsonOptions elements;
  elements.elements = true;
  Soup degenerate;
  for (int i = 0; i < 6; ++i)
    degenerate.add_vertex({double(i % 3), double(i / 3), 0});
  degenerate.add_polygon({0, 1, 4});
  degenerate.add_polygon({4, 1, 0});
  degenerate.add_polygon({0, 0, 4});
  degenerate.add_polygon({1, 2, 5, 5});
  std::vector<Soup> soups = {degenerate};
  for (const ExpectedReport& x : kExpected) {
    soups.push_back(x.make());
    soups.push_back(test_support::shuffled(x.make(), 7));
  }
  for (const Soup& soup : soups) {
    const DefectReport consumed = detect_defects(soup);
    const DefectReport kept = repair(soup).report.before;
    EXPECT_EQ(check_report_json("x", consumed, nullptr, elements),
              check_report_json("x", kept, nullptr, elements));
  }
}
