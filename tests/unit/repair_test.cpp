// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/repair.h"
#include "meshbridge/counted.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <set>

using namespace meshbridge;
using meshbridge::test_support::expect_repair_invariants;
using meshbridge::test_support::face_components;

namespace {

std::size_t count_labels(const std::vector<Index>& label) {
  return std::set<Index>(label.begin(), label.end()).size();
}

// Every component closed, with positive volume.
void expect_closed_outward(const RepairResult& result) {
  const auto label = face_components(result.mesh.soup);
  for (Index c : std::set<Index>(label.begin(), label.end())) {
    EXPECT_GT(meshbridge::test_support::signed_volume(result.mesh.soup, label, c), 0)
        << "component " << c;
  }
  EXPECT_TRUE(result.report.after.boundary_edges.empty());
  EXPECT_TRUE(result.report.after.watertight);
}

}  // namespace

TEST(Repair, twocubes_become_two_closed_cubes) {
  const Soup soup = models::two_cubes_sharing_edge();
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.mesh.soup.num_vertices(), 16u);
  EXPECT_EQ(r.mesh.soup.num_faces(), 24u);
  EXPECT_EQ(r.report.components_after, 2u);
  EXPECT_EQ(r.report.boundary_edges_after, 0u);
  EXPECT_EQ(r.report.vertices_split, 2u);
  EXPECT_EQ(r.report.faces_flipped, 0u);
  expect_closed_outward(r);
  // The cubes are faces 0-11 and 12-23.
  const auto label = face_components(r.mesh.soup);
  for (Index f = 0; f < 24; ++f)
    EXPECT_EQ(label[f], f < 12 ? 0u : 12u);
}

TEST(Repair, hourglass_splits_the_pinch_vertex) {
  const Soup soup = models::hourglass();
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.mesh.soup.num_vertices(), 8u);
  EXPECT_EQ(r.mesh.soup.num_faces(), 8u);
  EXPECT_EQ(r.report.components_after, 2u);
  expect_closed_outward(r);
}

TEST(Repair, report_text_gives_each_count_its_noun_in_the_right_number) {
  EXPECT_EQ(counted(1, "copy"), "1 copy");
  EXPECT_EQ(counted(2, "copy"), "2 copies");
  EXPECT_EQ(counted(2, "key"), "2 keys");
  EXPECT_EQ(counted(0, "singular vertex"), "0 singular vertices");
  EXPECT_EQ(counted(1, "new triangle"), "1 new triangle");
  const RepairResult r = repair(models::hourglass());
  ASSERT_EQ(r.report.vertices_split, 1u);
  EXPECT_NE(to_text(r.report).find("(1 copy from split fans, 0 isolated removed)"),
            std::string::npos)
      << to_text(r.report);
}

TEST(Repair, bowtie_becomes_two_triangles) {
  const Soup soup = models::bowtie();
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.mesh.soup.num_vertices(), 6u);
  EXPECT_EQ(r.mesh.soup.num_faces(), 2u);
  EXPECT_EQ(r.report.components_after, 2u);
}

TEST(Repair, book_of_three_keeps_one_pair_and_separates_one_face) {
  const Soup soup = models::book_of_three();
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.mesh.soup.num_faces(), 3u);
  EXPECT_EQ(r.report.components_after, 2u);
  EXPECT_EQ(r.report.sides_cut, 3u);       // no two pages run the edge opposite ways
  EXPECT_EQ(r.report.sides_stitched, 2u);  // two pages glued back, one page flipped
  EXPECT_EQ(r.report.faces_flipped, 1u);
  EXPECT_EQ(r.mesh.soup.num_vertices(), 7u);
}

TEST(Repair, t_junction_keeps_the_plate_whole_and_separates_the_rib) {
  const Soup soup = models::t_junction_plate_rib();
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.mesh.soup.num_faces(), soup.num_faces());
  const auto label = face_components(r.mesh.soup);
  std::set<Index> plate, rib;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    bool flat = true;
    for (Index v : soup.polygon(f))
      flat = flat && soup.positions[v][2] == 0;
    (flat ? plate : rib).insert(label[f]);
  }
  EXPECT_EQ(plate.size(), 1u);
  EXPECT_EQ(rib.size(), 1u);
  EXPECT_NE(*plate.begin(), *rib.begin());
  EXPECT_EQ(r.report.sides_cut, 4u);  // the rib's bottom sides
  EXPECT_EQ(r.report.faces_flipped, 0u);
}

TEST(Repair, plate_with_box_rib_becomes_two_closed_solids) {
  const Soup soup = models::plate_with_box_rib();
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.report.components_after, 2u);
  expect_closed_outward(r);
  // Plate: faces 0-59, rib: 60-71.
  const auto label = face_components(r.mesh.soup);
  for (Index f = 0; f < 72; ++f)
    EXPECT_EQ(label[f], f < 60 ? 0u : 60u);
}

TEST(Repair, prisms24_become_24_closed_prisms) {
  const Soup soup = models::prisms24_hexagon();
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.mesh.soup.num_faces(), 120u);
  EXPECT_EQ(r.report.components_after, 24u);
  expect_closed_outward(r);
  const auto label = face_components(r.mesh.soup);
  for (Index f = 0; f < 120; ++f)
    EXPECT_EQ(label[f], 5 * (f / 5));  // prism p: faces 5p..5p+4
}

TEST(Repair, checkerboard_cubes_all_close_and_separate) {
  const Soup soup = models::checkerboard_cubes(5);
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  const std::size_t cubes = soup.num_faces() / 12;
  EXPECT_EQ(r.report.components_after, cubes);
  EXPECT_EQ(r.mesh.soup.num_vertices(), 8 * cubes);
  expect_closed_outward(r);
}

TEST(Repair, moebius_is_reported_non_orientable_and_cut_open) {
  const Soup soup = models::moebius_strip();
  const RepairResult plain = repair(soup);
  expect_repair_invariants(soup, plain);
  EXPECT_EQ(plain.report.nonorientable_after_pairing, 1u);
  EXPECT_EQ(plain.report.before.num_nonorientable_components, 1u);
  EXPECT_EQ(plain.report.after.num_nonorientable_components, 0u);
  EXPECT_EQ(plain.report.faces_flipped, 0u);

  RepairOptions options;
  options.cut_nonorientable = true;
  const RepairResult cut = repair(soup, options);
  expect_repair_invariants(soup, cut);
  EXPECT_EQ(cut.report.nonorientable_after_pairing, 1u);
  EXPECT_EQ(cut.report.sides_cut_for_orientation, 2u);
  EXPECT_EQ(cut.report.after.num_nonorientable_components, 0u);
  EXPECT_EQ(cut.report.components_after, 1u);
}

TEST(Repair, inconsistent_input_is_oriented_outward) {
  Soup soup = models::icosphere(1);
  // Reverse every third triangle.
  for (std::size_t f = 0; f < soup.num_faces(); f += 3) {
    std::swap(soup.corner_vertices[soup.face_begin[f] + 1],
              soup.corner_vertices[soup.face_begin[f] + 2]);
  }
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.report.faces_flipped, (soup.num_faces() + 2) / 3);
  EXPECT_EQ(r.mesh.soup.num_vertices(), 42u);
  expect_closed_outward(r);
}

TEST(Repair, every_canonical_case_keeps_its_invariants_with_every_policy) {
  for (const auto& model : models::canonical_models()) {
    SCOPED_TRACE(model.name);
    for (PairingPolicy pairing : {PairingPolicy::geometric, PairingPolicy::combinatorial}) {
      for (int flags = 0; flags < 8; ++flags) {
        RepairOptions options;
        options.pairing = pairing;
        options.orient = flags & 1;
        options.stitch = flags & 2;
        options.cut_nonorientable = flags & 4;
        expect_repair_invariants(model.soup, repair(model.soup, options));
      }
    }
  }
}

TEST(Repair, repairing_a_repaired_mesh_changes_nothing) {
  for (const auto& model : models::canonical_models()) {
    SCOPED_TRACE(model.name);
    const RepairResult once = repair(model.soup);
    const RepairResult twice = repair(once.mesh.soup);
    EXPECT_EQ(twice.mesh.soup.positions, once.mesh.soup.positions);
    EXPECT_EQ(twice.mesh.soup.corner_vertices, once.mesh.soup.corner_vertices);
    EXPECT_EQ(twice.report.vertices_split, 0u);
    EXPECT_EQ(twice.report.faces_flipped, 0u);
    EXPECT_EQ(twice.report.sides_cut, 0u);
  }
}

TEST(Repair, counts_do_not_depend_on_face_order_or_polygon_start) {
  for (const auto& model : models::canonical_models()) {
    SCOPED_TRACE(model.name);
    const RepairResult reference = repair(model.soup);
    for (std::uint32_t seed : {7u, 8u, 9u}) {
      const Soup soup = meshbridge::test_support::shuffled(model.soup, seed);
      const RepairResult r = repair(soup);
      expect_repair_invariants(soup, r);
      EXPECT_EQ(r.mesh.soup.num_vertices(), reference.mesh.soup.num_vertices());
      EXPECT_EQ(r.report.components_after, reference.report.components_after);
      EXPECT_EQ(r.report.boundary_edges_after, reference.report.boundary_edges_after);
      EXPECT_EQ(r.report.sides_cut, reference.report.sides_cut);
    }
  }
}

TEST(Repair, degenerate_polygons_are_collapsed_split_or_set_aside_and_counted) {
  Soup soup;
  for (int i = 0; i < 6; ++i)
    soup.add_vertex({double(i % 3), double(i / 3), double(i % 2)});
  soup.add_polygon({0, 1, 4});           // fine
  soup.add_polygon({1, 1, 2, 5});        // collapses to 1 2 5
  soup.add_polygon({0, 3, 4, 0, 1, 2});  // pinched at 0: splits into 0 3 4 and 0 1 2
  soup.add_polygon({3, 3, 4});           // set aside
  const RepairResult r = repair(soup);
  expect_repair_invariants(soup, r);
  EXPECT_EQ(r.report.faces_set_aside, 1u);
  EXPECT_EQ(r.report.faces_split, 1u);
  EXPECT_EQ(r.report.faces_added_by_split, 1u);
  EXPECT_EQ(r.report.faces_out, 4u);
  EXPECT_EQ(r.mesh.face_origin, (std::vector<Index>{0, 1, 2, 2}));
  EXPECT_EQ(r.report.before.faces_set_aside, std::vector<Index>{3});
}

TEST(Repair, cleanup_options_remove_and_count) {
  Soup soup = models::icosphere(1);
  soup.add_polygon(soup.polygon(5));  // duplicate, face 80
  soup.add_polygon({1, 1, 2});        // degenerate, face 81
  soup.add_vertex({9, 9, 9});         // isolated
  RepairOptions options;
  options.remove_duplicate_faces = true;
  options.remove_degenerate_faces = true;
  options.remove_isolated_vertices = true;
  const RepairResult r = repair(soup, options);
  EXPECT_EQ(r.report.duplicate_faces_removed, 1u);
  EXPECT_EQ(r.report.degenerate_faces_removed, 1u);
  EXPECT_EQ(r.report.isolated_vertices_removed, 1u);
  EXPECT_EQ(r.report.faces_out, 80u);
  EXPECT_EQ(r.mesh.soup.num_vertices(), 42u);
  EXPECT_TRUE(r.report.after.watertight);
  EXPECT_TRUE(meshbridge::test_support::openmesh_accepts(r.mesh));

  const RepairResult kept = repair(soup);  // cleanup off: nothing leaves but what must
  EXPECT_EQ(kept.report.faces_out, 81u);
  EXPECT_EQ(kept.report.faces_set_aside, 1u);
  EXPECT_EQ(kept.mesh.soup.num_vertices(), 43u + kept.report.vertices_split);
}

TEST(Repair, without_detection_the_mesh_and_the_repair_counts_are_the_same) {
  const Soup soup = models::prisms24_hexagon();
  RepairOptions options;
  options.detect_before_after = false;
  const RepairResult fast = repair(soup, options);
  const RepairResult full = repair(soup);
  EXPECT_EQ(fast.mesh.soup.corner_vertices, full.mesh.soup.corner_vertices);
  EXPECT_EQ(fast.mesh.soup.positions, full.mesh.soup.positions);
  EXPECT_EQ(fast.report.vertices_split, full.report.vertices_split);
  EXPECT_EQ(fast.report.faces_out, full.report.faces_out);
  EXPECT_EQ(fast.report.before.num_faces, 0u);  // not detected
  EXPECT_EQ(fast.report.components_after, 0u);
  EXPECT_EQ(full.report.components_after, 24u);
}

TEST(Repair, a_collapsed_polygon_that_duplicates_another_is_removed_once) {
  // Found by fuzz_repair: 0 1 2 3 2 0 collapses to the triangle 0 1 2, which face 1 repeats.
  Soup soup;
  for (const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)})
    soup.add_vertex(p);
  soup.add_polygon({0, 1, 2, 3, 2, 0});
  soup.add_polygon({1, 2, 0});
  RepairOptions options;
  options.stitch = false;
  options.remove_duplicate_faces = true;
  options.remove_isolated_vertices = true;
  const RepairResult once = repair(soup, options);
  EXPECT_EQ(once.report.before.duplicate_faces, std::vector<Index>{1});
  EXPECT_EQ(once.report.duplicate_faces_removed, 1u);
  EXPECT_EQ(once.report.faces_out, 1u);
  const RepairResult twice = repair(once.mesh.soup, options);
  EXPECT_EQ(twice.mesh.soup.corner_vertices, once.mesh.soup.corner_vertices);
  EXPECT_EQ(twice.report.duplicate_faces_removed, 0u);
}

TEST(Repair, zero_area_faces_are_removed_on_request_and_counted) {
  // A unit square of two triangles plus slivers of distinct corners on one line (one lying on
  // the square's diagonal, one on its own), in either winding.
  for (const bool reversed : {false, true}) {
    Soup soup;
    for (const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                           Point(0.5, 0.5, 0), Point(5, 5, 5), Point(6, 6, 6), Point(7, 7, 7)})
      soup.add_vertex(p);
    const auto add = [&](std::vector<Index> corners) {
      if (reversed)
        std::reverse(corners.begin(), corners.end());
      soup.add_polygon(corners);
    };
    add({0, 1, 2});
    add({0, 2, 3});
    add({0, 4, 2});  // zero area: 4 lies on the diagonal 0-2
    add({5, 6, 7});  // zero area: on one line
    ASSERT_EQ(detect_defects(soup).zero_area_faces, (std::vector<Index>{2, 3}));
    RepairOptions options;
    options.remove_zero_area_faces = true;
    const RepairResult r = repair(soup, options);
    EXPECT_EQ(r.report.zero_area_faces_removed, 2u);
    EXPECT_EQ(r.report.faces_out, 2u);
    EXPECT_EQ(r.mesh.face_origin, (std::vector<Index>{0, 1}));
    EXPECT_EQ(repair(soup).report.faces_out, 4u);  // off by default
    EXPECT_EQ(repair(soup).report.zero_area_faces_removed, 0u);
  }
}
