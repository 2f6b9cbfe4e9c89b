// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the benchmark generators (models/benchmark_models.h): counts, contender counts per
// edge, reproducibility, and the documented defects cross-checked with detect_defects().

#include "meshbridge/models/benchmark_models.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/models/canonical_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <map>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

namespace {

using meshbridge::Index;
using meshbridge::Point;
using meshbridge::Soup;
namespace models = meshbridge::models;

using Pair = std::pair<Index, Index>;

//! Number of contenders (polygon sides) per undirected vertex pair.
std::map<Pair, int> contenders(const Soup& soup) {
  std::map<Pair, int> count;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto poly = soup.polygon(f);
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Index a = poly[i], b = poly[(i + 1) % poly.size()];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  }
  return count;
}

//! How many vertex pairs have k contenders, for each k.
std::map<int, long> contender_histogram(const Soup& soup) {
  std::map<int, long> histogram;
  for (const auto& [edge, k] : contenders(soup))
    ++histogram[k];
  return histogram;
}

bool same_soup(const Soup& a, const Soup& b) {
  return a.positions == b.positions && a.corner_vertices == b.corner_vertices &&
         a.face_begin == b.face_begin;
}

//! Indices in range, >= 3 distinct corners per polygon, no two vertices at one position, every
//! vertex used.
void expect_well_formed(const Soup& soup) {
  ASSERT_EQ(soup.face_begin.back(), soup.num_corners());
  std::vector<bool> used(soup.num_vertices(), false);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    ASSERT_GE(soup.arity(f), 3u) << "face " << f;
    std::set<Index> distinct;
    for (Index v : soup.polygon(f)) {
      ASSERT_LT(v, soup.num_vertices()) << "face " << f;
      distinct.insert(v);
      used[v] = true;
    }
    EXPECT_EQ(distinct.size(), soup.arity(f)) << "face " << f << " repeats a vertex";
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << "unused vertices";
  std::set<std::array<double, 3>> seen;
  for (const Point& p : soup.positions)
    EXPECT_TRUE(seen.insert({p[0], p[1], p[2]}).second) << p[0] << " " << p[1] << " " << p[2];
}

//! Faces [first, last) are a closed solid: every directed side once, with its reverse, and a
//! positive signed volume.
void expect_closed_outward(const Soup& soup, std::size_t first, std::size_t last) {
  std::map<Pair, int> directed;
  double volume = 0;
  for (std::size_t f = first; f < last; ++f) {
    const auto poly = soup.polygon(f);
    for (std::size_t i = 0; i < poly.size(); ++i)
      ++directed[{poly[i], poly[(i + 1) % poly.size()]}];
    const Point& p0 = soup.positions[poly[0]];
    for (std::size_t i = 1; i + 1 < poly.size(); ++i)
      volume += dot(p0, cross(soup.positions[poly[i]], soup.positions[poly[i + 1]])) / 6;
  }
  for (const auto& [side, k] : directed) {
    EXPECT_EQ(k, 1) << "faces [" << first << ", " << last << ")";
    EXPECT_EQ(directed.count({side.second, side.first}), 1u)
        << "faces [" << first << ", " << last << ")";
  }
  EXPECT_GT(volume, 0) << "faces [" << first << ", " << last << ")";
}

// --- random_singular_soup ----------------------------------------------------------------------

TEST(RandomSingularSoup, has_exactly_the_requested_singular_edges) {
  models::RandomSoupOptions options;
  options.n = 24;
  options.m = 12;
  options.singular_fraction = 0.1;
  options.max_fins = 3;
  options.seed = 7;
  const Soup soup = models::random_singular_soup(options);
  expect_well_formed(soup);
  const long torus_edges = 3 * 24 * 12;                  // 864
  const long singular = std::lround(0.1 * torus_edges);  // 86
  const long fins = static_cast<long>(soup.num_faces()) - 2 * 24 * 12;
  EXPECT_EQ(static_cast<long>(soup.num_vertices()), 24 * 12 + fins);
  EXPECT_GE(fins, singular);
  EXPECT_LE(fins, 3 * singular);
  const auto histogram = contender_histogram(soup);
  long singular_found = 0, singular_contenders = 0;
  for (const auto& [k, count] : histogram) {
    if (k > 2) {
      EXPECT_LE(k, 2 + 3);
      singular_found += count;
      singular_contenders += k * count;
    }
  }
  EXPECT_EQ(singular_found, singular);
  EXPECT_EQ(singular_contenders, 2 * singular + fins);
  EXPECT_EQ(histogram.at(1), 2 * fins);  // each fin's two free sides
  EXPECT_EQ(histogram.at(2), torus_edges - singular);

  const meshbridge::DefectReport report = meshbridge::detect_defects(soup);
  EXPECT_EQ(static_cast<long>(report.singular_edges.size()), singular);
  EXPECT_EQ(static_cast<long>(report.boundary_edges.size()), 2 * fins);
  EXPECT_EQ(report.num_components, 1u);
}

TEST(RandomSingularSoup, fins_stand_on_torus_edges_in_edge_order) {
  models::RandomSoupOptions options;
  options.n = 8;
  options.m = 5;
  options.singular_fraction = 0.5;
  const Soup soup = models::random_singular_soup(options);
  const Soup torus = models::torus_grid(8, 5);
  // The torus comes first, unchanged.
  ASSERT_GE(soup.num_vertices(), torus.num_vertices());
  EXPECT_TRUE(std::equal(torus.positions.begin(), torus.positions.end(), soup.positions.begin()));
  EXPECT_TRUE(std::equal(torus.corner_vertices.begin(), torus.corner_vertices.end(),
                         soup.corner_vertices.begin()));
  const auto torus_edges = contenders(torus);
  for (std::size_t f = torus.num_faces(); f < soup.num_faces(); ++f) {
    const auto poly = soup.polygon(f);
    ASSERT_EQ(poly.size(), 3u);
    EXPECT_EQ(torus_edges.count({std::min(poly[0], poly[1]), std::max(poly[0], poly[1])}), 1u);
    EXPECT_GE(poly[2], torus.num_vertices());  // own apex
    // The apex stands off the surface: farther from the core circle than the edge midpoint.
    const Point mid = (soup.positions[poly[0]] + soup.positions[poly[1]]) * 0.5;
    const Point apex = soup.positions[poly[2]];
    auto tube_distance = [](const Point& p) {
      return (p - Point(p[0], p[1], 0).normalized()).norm();
    };
    EXPECT_GT(tube_distance(apex), tube_distance(mid));
  }
}

TEST(RandomSingularSoup, is_reproducible_and_seeded) {
  models::RandomSoupOptions options;
  options.n = 16;
  options.m = 9;
  options.singular_fraction = 0.25;
  const Soup a = models::random_singular_soup(options);
  const Soup b = models::random_singular_soup(options);
  EXPECT_TRUE(same_soup(a, b));
  options.seed = 2;
  const Soup c = models::random_singular_soup(options);
  EXPECT_FALSE(same_soup(a, c));
}

TEST(RandomSingularSoup, zero_fraction_is_the_clean_torus_and_one_makes_every_edge_singular) {
  models::RandomSoupOptions options;
  options.n = 6;
  options.m = 4;
  options.singular_fraction = 0;
  EXPECT_TRUE(same_soup(models::random_singular_soup(options), models::torus_grid(6, 4)));
  options.singular_fraction = 1;
  options.max_fins = 1;
  const Soup all = models::random_singular_soup(options);
  EXPECT_EQ(all.num_faces(), 2u * 6 * 4 + 3 * 6 * 4);
  const auto histogram = contender_histogram(all);
  EXPECT_EQ(histogram, (std::map<int, long>{{1, 2 * 3 * 6 * 4}, {3, 3 * 6 * 4}}));
}

TEST(RandomSingularSoup, rejects_bad_options) {
  models::RandomSoupOptions options;
  options.singular_fraction = 1.5;
  EXPECT_THROW(models::random_singular_soup(options), std::invalid_argument);
  options = {};
  options.max_fins = 0;
  EXPECT_THROW(models::random_singular_soup(options), std::invalid_argument);
  options = {};
  options.n = 2;
  EXPECT_THROW(models::random_singular_soup(options), std::invalid_argument);
}

// --- prisms_hexagon ----------------------------------------------------------------------------

//! The contender histogram documented for prisms_hexagon(k), s = 2k.
std::map<int, long> prisms_histogram(long s) {
  const long points = 3 * s * s + 3 * s + 1;
  const long interior_edges = 9 * s * s - 3 * s;
  return {{2, 12 * s},                  // rim edges at both heights
          {4, 2 * interior_edges + 6},  // interior horizontal edges; verticals at the corners
          {6, 6 * (s - 1)},             // verticals at rim points that are not corners
          {12, points - 6 * s}};        // verticals at interior points
}

TEST(PrismsHexagon, level_one_is_the_papers_24_prisms) {
  const Soup soup = models::prisms_hexagon(1);
  const Soup paper = models::prisms24_hexagon();
  EXPECT_EQ(soup.num_vertices(), 38u);
  EXPECT_EQ(soup.num_faces(), 120u);
  EXPECT_EQ(soup.num_corners(), paper.num_corners());
  expect_well_formed(soup);
  EXPECT_EQ(contender_histogram(soup), contender_histogram(paper));
  EXPECT_EQ(contender_histogram(soup), prisms_histogram(2));
  // Same points as the paper's model (other numbering).
  auto sorted_points = [](const Soup& s) {
    std::vector<std::array<double, 3>> points;
    for (const Point& p : s.positions)
      points.push_back({p[0], p[1], p[2]});
    std::sort(points.begin(), points.end());
    return points;
  };
  const auto mine = sorted_points(soup), theirs = sorted_points(paper);
  ASSERT_EQ(mine.size(), theirs.size());
  for (std::size_t i = 0; i < mine.size(); ++i) {
    for (int d = 0; d < 3; ++d)
      EXPECT_NEAR(mine[i][d], theirs[i][d], 1e-15) << i;
  }
}

TEST(PrismsHexagon, counts_and_defects_at_levels_2_and_3) {
  for (int k : {2, 3}) {
    SCOPED_TRACE("k = " + std::to_string(k));
    const long s = 2 * k;
    const long points = 3 * s * s + 3 * s + 1, prisms = 6 * s * s;
    const Soup soup = models::prisms_hexagon(k);
    EXPECT_EQ(static_cast<long>(soup.num_vertices()), 2 * points);
    EXPECT_EQ(static_cast<long>(soup.num_faces()), 5 * prisms);
    EXPECT_EQ(prisms, 24L * k * k);
    expect_well_formed(soup);
    EXPECT_EQ(contender_histogram(soup), prisms_histogram(s));
    for (long p = 0; p < prisms; ++p) {
      expect_closed_outward(soup, 5 * p, 5 * p + 5);
      EXPECT_EQ(soup.arity(5 * p), 3u);
      EXPECT_EQ(soup.arity(5 * p + 2), 4u);
    }
    const meshbridge::DefectReport report = meshbridge::detect_defects(soup);
    EXPECT_EQ(static_cast<long>(report.singular_edges.size()), 2 * (9 * s * s - 3 * s) + points);
    EXPECT_EQ(static_cast<long>(report.num_singular_vertices()), 2 * points);
    EXPECT_EQ(static_cast<long>(report.duplicate_faces.size()), 9 * s * s - 3 * s);
    EXPECT_TRUE(report.boundary_edges.empty());
  }
}

TEST(PrismsHexagon, rejects_bad_level) {
  EXPECT_THROW(models::prisms_hexagon(0), std::invalid_argument);
  EXPECT_THROW(models::prisms_hexagon(65), std::invalid_argument);
}

// --- stiffened_plate ---------------------------------------------------------------------------

struct PlateCounts {
  long vertices, faces, boundary, singular3, singular4, singular_vertices;
};

//! The counts documented for stiffened_plate().
PlateCounts plate_counts(long r, long R, long C) {
  const long nx = 2 * (C + 1) * r, ny = (R + 1) * r;
  return {(nx + 1) * (ny + 1) + R * (nx + 1) * r + C * ((ny + 1) * r - R * r),
          2 * nx * ny + 2 * R * nx * r + 2 * C * ny * r,
          2 * (nx + ny) + R * (nx + 2 * r) + C * (ny + 2 * r),
          R * nx + C * ny,
          R * C * r,
          R * (nx + 1) + C * (ny + 1) - R * C + R * C * r};
}

TEST(StiffenedPlate, counts_and_defects) {
  const std::array<std::array<int, 3>, 5> cases = {
      {{1, 1, 0}, {2, 3, 0}, {3, 2, 1}, {1, 3, 2}, {4, 0, 0}}};
  for (const auto& [r, R, C] : cases) {
    SCOPED_TRACE("r = " + std::to_string(r) + ", ribs = " + std::to_string(R) +
                 ", cross_ribs = " + std::to_string(C));
    models::StiffenedPlateOptions options;
    options.resolution = r;
    options.ribs = R;
    options.cross_ribs = C;
    const Soup soup = models::stiffened_plate(options);
    const PlateCounts expected = plate_counts(r, R, C);
    EXPECT_EQ(static_cast<long>(soup.num_vertices()), expected.vertices);
    EXPECT_EQ(static_cast<long>(soup.num_faces()), expected.faces);
    expect_well_formed(soup);
    auto histogram = contender_histogram(soup);
    EXPECT_EQ(histogram[1], expected.boundary);
    EXPECT_EQ(histogram[3], expected.singular3);
    EXPECT_EQ(histogram[4], expected.singular4);
    histogram.erase(1);
    histogram.erase(2);
    histogram.erase(3);
    histogram.erase(4);
    for (const auto& [k, count] : histogram)
      EXPECT_EQ(count, 0) << k << " contenders";
    const meshbridge::DefectReport report = meshbridge::detect_defects(soup);
    EXPECT_EQ(static_cast<long>(report.singular_edges.size()),
              expected.singular3 + expected.singular4);
    EXPECT_EQ(static_cast<long>(report.num_singular_vertices()), expected.singular_vertices);
    EXPECT_EQ(static_cast<long>(report.boundary_edges.size()), expected.boundary);
    EXPECT_EQ(report.num_components, 1u);
    EXPECT_TRUE(report.duplicate_faces.empty());
  }
}

TEST(StiffenedPlate, plate_faces_up_and_ribs_stand_on_it) {
  models::StiffenedPlateOptions options;
  options.resolution = 2;
  options.ribs = 2;
  options.cross_ribs = 1;
  const Soup soup = models::stiffened_plate(options);
  const long nx = 2 * 2 * 2, ny = 3 * 2;
  for (long f = 0; f < 2 * nx * ny; ++f) {
    const auto poly = soup.polygon(f);
    const Point n = cross(soup.positions[poly[1]] - soup.positions[poly[0]],
                          soup.positions[poly[2]] - soup.positions[poly[0]]);
    EXPECT_GT(n[2], 0) << "plate face " << f;
    for (Index v : poly)
      EXPECT_EQ(soup.positions[v][2], 0.0);
  }
  for (std::size_t f = 2 * nx * ny; f < soup.num_faces(); ++f) {
    double top = 0;
    for (Index v : soup.polygon(f))
      top = std::max(top, soup.positions[v][2]);
    EXPECT_GT(top, 0) << "rib face " << f;
  }
}

TEST(StiffenedPlate, rejects_bad_options) {
  models::StiffenedPlateOptions options;
  options.resolution = 0;
  EXPECT_THROW(models::stiffened_plate(options), std::invalid_argument);
  options = {};
  options.ribs = -1;
  EXPECT_THROW(models::stiffened_plate(options), std::invalid_argument);
  options = {};
  options.resolution = 100000;
  EXPECT_THROW(models::stiffened_plate(options), std::invalid_argument);
}

}  // namespace
