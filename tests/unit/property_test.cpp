// SPDX-License-Identifier: GPL-3.0-or-later
// Property tests over thousands of seeded random soups: every invariant of repair, idempotence,
// order independence, provenance.

#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"
#include "meshbridge/repair.h"
#include "meshbridge/report_json.h"

#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <sstream>

using namespace meshbridge;
using meshbridge::test_support::expect_repair_invariants;

namespace {

// A soup of `faces` polygons (arity 3 to 5) over a small pool of vertices in general position,
// so that edges are shared by 1 to many polygons in every orientation; some polygons repeat a
// vertex and some are exact or reversed duplicates.
Soup random_soup(std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  const int vertices = 6 + static_cast<int>(random() % 20);
  const int faces = 4 + static_cast<int>(random() % 40);
  Soup soup;
  for (int v = 0; v < vertices; ++v)
    soup.add_vertex({coordinate(random), coordinate(random), coordinate(random)});
  std::vector<Index> polygon;
  for (int f = 0; f < faces; ++f) {
    const unsigned kind = random() % 20;
    if (kind == 0 && soup.num_faces() > 0) {  // duplicate, maybe reversed
      const PolygonView p = soup.polygon(random() % soup.num_faces());
      polygon.assign(p.begin(), p.end());
      if (random() % 2)
        std::reverse(polygon.begin(), polygon.end());
    } else {
      polygon.clear();
      const int arity = 3 + static_cast<int>(random() % 3);
      for (int i = 0; i < arity; ++i)
        polygon.push_back(random() % vertices);
      if (kind > 2) {  // mostly simple polygons: redraw repeats
        for (std::size_t i = 0; i < polygon.size(); ++i) {
          while (std::count(polygon.begin(), polygon.end(), polygon[i]) > 1)
            polygon[i] = random() % vertices;
        }
      }
    }
    soup.add_polygon(polygon);
  }
  return soup;
}

constexpr std::uint32_t kSoups = 2000;

}  // namespace

TEST(RepairProperties, invariants_hold_on_random_soups_with_every_policy) {
  for (std::uint32_t seed = 1; seed <= kSoups; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Soup soup = random_soup(seed);
    RepairOptions options;
    options.pairing = seed % 3 == 0 ? PairingPolicy::combinatorial : PairingPolicy::geometric;
    options.stitch = seed % 5 != 0;
    options.cut_nonorientable = seed % 7 == 0;
    expect_repair_invariants(soup, repair(soup, options));
    if (::testing::Test::HasFailure())
      return;
  }
}

TEST(RepairProperties, repair_is_idempotent_on_random_soups) {
  for (std::uint32_t seed = 1; seed <= kSoups; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const RepairResult once = repair(random_soup(seed));
    const RepairResult twice = repair(once.mesh.soup);
    EXPECT_EQ(twice.mesh.soup.corner_vertices, once.mesh.soup.corner_vertices);
    EXPECT_EQ(twice.mesh.soup.positions, once.mesh.soup.positions);
    EXPECT_EQ(twice.report.vertices_split, 0u);
    EXPECT_EQ(twice.report.faces_flipped, 0u);
    if (::testing::Test::HasFailure())
      return;
  }
}

// The same soup with every polygon fanned into triangles (all of one arity, so the corners'
// faces are c / 3 rather than a table).
Soup fanned(const Soup& soup) {
  Soup triangles;
  triangles.positions = soup.positions;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    for (std::size_t i = 1; i + 1 < p.size(); ++i)
      triangles.add_polygon(std::vector<Index>{p[0], p[i], p[i + 1]});
  }
  return triangles;
}

// `soup` without the faces a coin toss removes (one in four): open fans, pinched vertices and
// boundary loops cut into canonical solids.
Soup with_faces_removed(const Soup& soup, std::uint32_t seed) {
  std::mt19937 random(seed);
  Soup kept;
  kept.positions = soup.positions;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (random() % 4 != 0)
      kept.add_polygon(soup.polygon(f));
  }
  return kept;
}

// detect_defects() visits the sides vertex pair by vertex pair without keeping them; repair()'s
// `before` reads the same soup through the grouping it keeps (EdgeBridges). Both must give every
// element list and count alike: on random soups (mostly singular edges), on the canonical models
// and on them with faces removed (open and pinched fans), each also fanned into triangles (one
// arity: the corners' faces are c / 3, not a table).
TEST(RepairProperties, detection_without_a_grouping_equals_detection_through_edge_bridges) {
  ReportJsonOptions everything;
  everything.elements = true;
  RepairOptions options;
  options.close_gaps.tolerance = 0;
  const auto expect_same = [&](const Soup& soup) {
    for (const Soup& s : {soup, fanned(soup)}) {
      const std::string lean = check_report_json("soup", detect_defects(s), nullptr, everything);
      const std::string grouped =
          check_report_json("soup", repair(s, options).report.before, nullptr, everything);
      ASSERT_EQ(lean, grouped);
    }
  };
  for (std::uint32_t seed = 1; seed <= kSoups; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same(random_soup(seed));
  }
  for (const models::NamedModel& model : models::canonical_models()) {
    SCOPED_TRACE(model.name);
    expect_same(model.soup);
    for (std::uint32_t seed = 1; seed <= 20; ++seed)
      expect_same(with_faces_removed(model.soup, seed));
  }
}

TEST(RepairProperties, detection_does_not_depend_on_face_order_or_polygon_start) {
  for (std::uint32_t seed = 1; seed <= kSoups; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const Soup soup = random_soup(seed);
    const DefectReport a = detect_defects(soup);
    const DefectReport b = detect_defects(test_support::shuffled(soup, seed));
    EXPECT_EQ(a.singular_edges.size(), b.singular_edges.size());
    EXPECT_EQ(a.singular_edge_vertices, b.singular_edge_vertices);
    EXPECT_EQ(a.pinch_vertices, b.pinch_vertices);
    EXPECT_EQ(a.boundary_edges.size(), b.boundary_edges.size());
    EXPECT_EQ(a.num_boundary_loops, b.num_boundary_loops);
    EXPECT_EQ(a.inconsistent_edges.size(), b.inconsistent_edges.size());
    EXPECT_EQ(a.num_nonorientable_components, b.num_nonorientable_components);
    EXPECT_EQ(a.num_components, b.num_components);
    EXPECT_EQ(a.euler_characteristic, b.euler_characteristic);
    EXPECT_EQ(a.duplicate_faces.size(), b.duplicate_faces.size());
    EXPECT_EQ(a.degenerate_faces.size(), b.degenerate_faces.size());
    if (::testing::Test::HasFailure())
      return;
  }
}

TEST(RepairProperties, repair_counts_do_not_depend_on_face_order_or_polygon_start) {
  std::size_t differing = 0;
  for (std::uint32_t seed = 1; seed <= kSoups; ++seed) {
    const Soup soup = random_soup(seed);
    const RepairResult a = repair(soup);
    const RepairResult b = repair(test_support::shuffled(soup, seed));
    if (a.mesh.soup.num_vertices() != b.mesh.soup.num_vertices() ||
        a.report.components_after != b.report.components_after ||
        a.report.boundary_edges_after != b.report.boundary_edges_after) {
      ++differing;
      if (differing < 5)
        ADD_FAILURE() << "seed " << seed << ": " << a.mesh.soup.num_vertices() << "/"
                      << b.mesh.soup.num_vertices() << " v, " << a.report.components_after << "/"
                      << b.report.components_after << " components, "
                      << a.report.boundary_edges_after << "/" << b.report.boundary_edges_after
                      << " boundary";
    }
  }
  EXPECT_EQ(differing, 0u);
}

namespace {

// `soup` with every polygon's corner order reversed (every component turned inside out).
Soup reversed(const Soup& soup) {
  Soup out = soup;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    std::reverse(out.corner_vertices.begin() + soup.face_begin[f],
                 out.corner_vertices.begin() + soup.face_begin[f + 1]);
  }
  return out;
}

// `outer` and, inside it, `inner` shrunk to half about `outer`'s vertex centroid: a solid with
// a cavity when `inner` is wound the other way, two outward shells otherwise.
Soup nested(const Soup& outer, const Soup& inner) {
  Point centre(0, 0, 0);
  for (const Point& p : outer.positions)
    centre += p / static_cast<double>(outer.positions.size());
  Soup out = outer;
  const Index offset = static_cast<Index>(out.num_vertices());
  for (const Point& p : inner.positions)
    out.add_vertex(centre + (p - centre) * 0.5);
  for (std::size_t f = 0; f < inner.num_faces(); ++f) {
    std::vector<Index> polygon;
    for (Index v : inner.polygon(f))
      polygon.push_back(v + offset);
    out.add_polygon(polygon);
  }
  return out;
}

std::string mesh_digest(const IndexedMesh& mesh) {
  std::ostringstream out;
  out.precision(17);
  for (const Point& p : mesh.soup.positions)
    out << p[0] << ' ' << p[1] << ' ' << p[2] << ';';
  for (const auto* list : {&mesh.soup.corner_vertices, &mesh.soup.face_begin, &mesh.vertex_origin,
                           &mesh.face_origin, &mesh.corner_origin}) {
    out << '|';
    for (Index i : *list)
      out << i << ',';
  }
  return out.str();
}

}  // namespace

// With orientation off no face is reversed, by any stage (stitching glued inconsistent sides by
// reversing a component): every side of every output face, mapped to input vertices, is a side
// of the input polygon it came from, running the same way.
TEST(RepairProperties, without_orientation_no_face_is_reversed) {
  RepairOptions options;
  options.orient = false;
  for (const models::NamedModel& model : models::canonical_models()) {
    Soup soups[2] = {model.soup, model.soup};
    for (std::size_t f = 0; f < soups[1].num_faces(); f += 2) {  // every other face reversed
      auto first = soups[1].corner_vertices.begin() + soups[1].face_begin[f];
      std::reverse(first, soups[1].corner_vertices.begin() + soups[1].face_begin[f + 1]);
    }
    for (const Soup& input : soups) {
      SCOPED_TRACE(model.name);
      const RepairResult result = repair(input, options);
      EXPECT_EQ(result.report.faces_flipped, 0u);
      const IndexedMesh& out = result.mesh;
      for (std::size_t f = 0; f < out.soup.num_faces(); ++f) {
        const PolygonView p = out.soup.polygon(f);
        const PolygonView q = input.polygon(out.face_origin[f]);
        for (std::size_t i = 0; i < p.size(); ++i) {
          const Index a = out.vertex_origin[p[i]], b = out.vertex_origin[p[(i + 1) % p.size()]];
          bool found = false;
          for (std::size_t k = 0; k < q.size() && !found; ++k)
            found = q[k] == a && q[(k + 1) % q.size()] == b;
          EXPECT_TRUE(found) << "output face " << f << ", side " << a << "-" << b;
        }
      }
    }
  }
}

// repair(Soup&&) returns the soup itself when nothing changes (no grouping, no copy) and runs
// the full repair otherwise; either way its mesh and report equal repair(const Soup&)'s. Closed
// repaired canonical models must take the shortcut (the output owns the input's buffer); turned
// inside out, with a cavity wound either way, fanned, with an isolated vertex, and under each
// option that can change a closed soup, the results must still be the same.
TEST(RepairProperties, consuming_repair_equals_repair_and_keeps_unchanged_soups_as_they_are) {
  ReportJsonOptions everything;
  everything.elements = true;
  std::vector<std::pair<std::string, RepairOptions>> option_sets(6);
  option_sets[0].first = "defaults";
  option_sets[1].first = "no orientation";
  option_sets[1].second.orient = false;
  option_sets[2].first = "remove isolated vertices";
  option_sets[2].second.remove_isolated_vertices = true;
  option_sets[3].first = "remove duplicates and degenerate faces";
  option_sets[3].second.remove_duplicate_faces = true;
  option_sets[3].second.remove_degenerate_faces = true;
  option_sets[4].first = "no reports";
  option_sets[4].second.detect_before_after = false;
  option_sets[5].first = "no gap closing";
  option_sets[5].second.close_gaps.tolerance = 0;
  std::size_t kept = 0;
  for (const models::NamedModel& model : models::canonical_models()) {
    const Soup closed = repair(model.soup).mesh.soup;
    Soup with_isolated = closed;
    with_isolated.add_vertex({1e3, 1e3, 1e3});
    const std::vector<std::pair<std::string, Soup>> soups = {
        {"input", model.soup},
        {"repaired", closed},
        {"repaired, inside out", reversed(closed)},
        {"repaired, fanned", fanned(closed)},
        {"repaired, isolated vertex", with_isolated},
        {"repaired, with a cavity", nested(closed, reversed(closed))},
        {"repaired, with an outward shell inside", nested(closed, closed)},
    };
    for (const auto& [soup_name, soup] : soups) {
      for (const auto& [options_name, options] : option_sets) {
        SCOPED_TRACE(model.name + ", " + soup_name + ", " + options_name);
        const RepairResult copied = repair(soup, options);
        Soup consumed = soup;
        const Point* buffer = consumed.positions.data();
        const RepairResult moved = repair(std::move(consumed), options);
        ASSERT_EQ(mesh_digest(moved.mesh), mesh_digest(copied.mesh));
        ASSERT_EQ(repair_report_json("in", "out", moved.report, nullptr, everything),
                  repair_report_json("in", "out", copied.report, nullptr, everything));
        const bool shortcut = moved.mesh.soup.positions.data() == buffer;
        kept += shortcut ? 1 : 0;
        if (copied.report.after.watertight && soup_name == "repaired" &&
            !closed.positions.empty() && options.detect_before_after) {
          EXPECT_TRUE(shortcut) << "a closed repaired soup went through the full repair";
        }
      }
    }
  }
  EXPECT_GT(kept, 0u);
}

// repair(Soup&&) hands the grouping its detection made to the pipeline when the soup has a
// boundary or singular edge; repair(const Soup&) groups afresh. Random soups (singular edges,
// boundaries, degenerate polygons) and the canonical models with faces removed must give the
// same mesh and report both ways.
TEST(RepairProperties, consuming_repair_reuses_the_grouping_of_its_detection_faithfully) {
  ReportJsonOptions everything;
  everything.elements = true;
  const auto expect_same = [&](const Soup& soup) {
    const RepairResult copied = repair(soup);
    const RepairResult moved = repair(Soup(soup));
    ASSERT_EQ(mesh_digest(moved.mesh), mesh_digest(copied.mesh));
    ASSERT_EQ(repair_report_json("in", "out", moved.report, nullptr, everything),
              repair_report_json("in", "out", copied.report, nullptr, everything));
  };
  for (std::uint32_t seed = 1; seed <= kSoups; seed += 4) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    expect_same(random_soup(seed));
  }
  for (const models::NamedModel& model : models::canonical_models()) {
    SCOPED_TRACE(model.name);
    for (std::uint32_t seed = 1; seed <= 5; ++seed)
      expect_same(with_faces_removed(model.soup, seed));
  }
}
