// SPDX-License-Identifier: GPL-3.0-or-later
// Tests of the canonical models (models/): counts, index ranges, contender counts per edge,
// and outward consistent orientation of every closed solid.

#include "meshbridge/models/canonical_models.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using meshbridge::Index;
using meshbridge::Point;
using meshbridge::Soup;
namespace models = meshbridge::models;

using Pair = std::pair<Index, Index>;

constexpr double kPi = 3.14159265358979323846;

Pair undirected(Index a, Index b) {
  return {std::min(a, b), std::max(a, b)};
}

//! Every polygon side (a, b) of the soup, in face order.
std::vector<Pair> directed_sides(const Soup& soup, std::size_t first = 0,
                                 std::size_t last = static_cast<std::size_t>(-1)) {
  std::vector<Pair> sides;
  last = std::min(last, soup.num_faces());
  for (std::size_t f = first; f < last; ++f) {
    const auto poly = soup.polygon(f);
    for (std::size_t i = 0; i < poly.size(); ++i) {
      sides.emplace_back(poly[i], poly[(i + 1) % poly.size()]);
    }
  }
  return sides;
}

//! Number of contenders (polygon sides) per undirected vertex pair.
std::map<Pair, int> contenders(const Soup& soup) {
  std::map<Pair, int> count;
  for (const auto& [a, b] : directed_sides(soup))
    ++count[undirected(a, b)];
  return count;
}

//! How many vertex pairs have k contenders, for each k.
std::map<int, int> contender_histogram(const Soup& soup) {
  std::map<int, int> histogram;
  for (const auto& [edge, k] : contenders(soup))
    ++histogram[k];
  return histogram;
}

//! Signed volume enclosed by faces [first, last) (fan triangulation of each polygon).
double signed_volume(const Soup& soup, std::size_t first, std::size_t last) {
  double volume = 0;
  for (std::size_t f = first; f < last; ++f) {
    const auto poly = soup.polygon(f);
    const Point& p0 = soup.positions[poly[0]];
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      volume += dot(p0, cross(soup.positions[poly[i]], soup.positions[poly[i + 1]])) / 6;
    }
  }
  return volume;
}

double signed_volume(const Soup& soup) {
  return signed_volume(soup, 0, soup.num_faces());
}

//! Unnormalized normal of polygon f (Newell's method).
Point face_normal(const Soup& soup, std::size_t f) {
  const auto poly = soup.polygon(f);
  Point n(0, 0, 0);
  for (std::size_t i = 0; i < poly.size(); ++i) {
    n += cross(soup.positions[poly[i]], soup.positions[poly[(i + 1) % poly.size()]]);
  }
  return n;
}

void expect_indices_in_range(const Soup& soup) {
  ASSERT_EQ(soup.face_begin.size(), soup.num_faces() + 1);
  EXPECT_EQ(soup.face_begin.front(), 0u);
  EXPECT_EQ(soup.face_begin.back(), soup.num_corners());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    EXPECT_GE(soup.arity(f), 3u) << "face " << f;
    std::set<Index> distinct;
    for (Index v : soup.polygon(f)) {
      EXPECT_LT(v, soup.num_vertices()) << "face " << f;
      distinct.insert(v);
    }
    EXPECT_EQ(distinct.size(), soup.arity(f)) << "face " << f << " repeats a vertex";
  }
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const Point& p = soup.positions[v];
    EXPECT_TRUE(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2])) << v;
  }
}

//! Welded: no two vertices at the same position, and every vertex is used.
void expect_welded(const Soup& soup) {
  std::set<std::array<double, 3>> seen;
  for (const Point& p : soup.positions) {
    EXPECT_TRUE(seen.insert({p[0], p[1], p[2]}).second)
        << "duplicate position " << p[0] << " " << p[1] << " " << p[2];
  }
  std::vector<bool> used(soup.num_vertices(), false);
  for (Index v : soup.corner_vertices)
    used[v] = true;
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0) << "unused vertices";
}

//! Faces [first, last) form a closed, consistently oriented solid with positive volume:
//! every directed side (a, b) occurs exactly once and its reverse (b, a) occurs too.
void expect_closed_outward_solid(const Soup& soup, std::size_t first, std::size_t last) {
  SCOPED_TRACE("solid of faces [" + std::to_string(first) + ", " + std::to_string(last) + ")");
  std::map<Pair, int> count;
  for (const auto& side : directed_sides(soup, first, last))
    ++count[side];
  for (const auto& [side, k] : count) {
    EXPECT_EQ(k, 1) << "directed side " << side.first << "->" << side.second;
    EXPECT_EQ(count.count({side.second, side.first}), 1u)
        << "directed side " << side.first << "->" << side.second << " has no opposite";
  }
  EXPECT_GT(signed_volume(soup, first, last), 0);
}

//! Solids of equal face count `faces_per_solid`, back to back.
void expect_solids(const Soup& soup, std::size_t faces_per_solid) {
  ASSERT_EQ(soup.num_faces() % faces_per_solid, 0u);
  for (std::size_t f = 0; f < soup.num_faces(); f += faces_per_solid) {
    expect_closed_outward_solid(soup, f, f + faces_per_solid);
  }
}

TEST(CanonicalModels, two_cubes_sharing_edge) {
  const Soup soup = models::two_cubes_sharing_edge();
  EXPECT_EQ(soup.num_vertices(), 14u);
  EXPECT_EQ(soup.num_faces(), 24u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  expect_solids(soup, 12);
  EXPECT_NEAR(signed_volume(soup, 0, 12), 1.0, 1e-12);
  EXPECT_NEAR(signed_volume(soup, 12, 24), 1.0, 1e-12);
  EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{2, 34}, {4, 1}}));
  const auto count = contenders(soup);
  const Point a = soup.positions[3], b = soup.positions[7];
  EXPECT_EQ(a, Point(1, 1, 0));
  EXPECT_EQ(b, Point(1, 1, 1));
  EXPECT_EQ(count.at(undirected(3, 7)), 4);
}

TEST(CanonicalModels, hourglass) {
  const Soup soup = models::hourglass();
  EXPECT_EQ(soup.num_vertices(), 7u);
  EXPECT_EQ(soup.num_faces(), 8u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  expect_solids(soup, 4);
  EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{2, 12}}));
  // The apex is the only shared vertex: in 3 faces of each tetrahedron.
  int apex_faces = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto poly = soup.polygon(f);
    apex_faces += std::count(poly.begin(), poly.end(), Index{0});
  }
  EXPECT_EQ(apex_faces, 6);
}

TEST(CanonicalModels, bowtie) {
  const Soup soup = models::bowtie();
  EXPECT_EQ(soup.num_vertices(), 5u);
  EXPECT_EQ(soup.num_faces(), 2u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{1, 6}}));
  for (std::size_t f = 0; f < 2; ++f) {
    EXPECT_GT(face_normal(soup, f)[2], 0) << f;
    const auto poly = soup.polygon(f);
    EXPECT_EQ(std::count(poly.begin(), poly.end(), Index{0}), 1);
  }
}

TEST(CanonicalModels, book_of_three) {
  const Soup soup = models::book_of_three();
  EXPECT_EQ(soup.num_vertices(), 5u);
  EXPECT_EQ(soup.num_faces(), 3u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{1, 6}, {3, 1}}));
  EXPECT_EQ(contenders(soup).at(undirected(0, 1)), 3);
  for (std::size_t f = 0; f < 3; ++f) {
    const auto poly = soup.polygon(f);
    EXPECT_EQ(poly[0], 0u);
    EXPECT_EQ(poly[1], 1u);
    EXPECT_EQ(poly[2], 2u + f);
  }
  // Apexes at 0, 120, 240 degrees around the z axis.
  for (std::size_t i = 0; i < 3; ++i) {
    const Point& p = soup.positions[2 + i];
    const double angle = std::atan2(p[1], p[0]);
    const double expected = 2 * kPi / 3 * static_cast<double>(i);
    EXPECT_NEAR(std::remainder(angle - expected, 2 * kPi), 0, 1e-12) << i;
    EXPECT_NEAR(std::hypot(p[0], p[1]), 1, 1e-12) << i;
  }
}

TEST(CanonicalModels, t_junction_plate_rib) {
  const Soup soup = models::t_junction_plate_rib();
  EXPECT_EQ(soup.num_vertices(), 20u);
  EXPECT_EQ(soup.num_faces(), 24u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  const auto count = contenders(soup);
  int joints = 0;
  for (const auto& [edge, k] : count) {
    const Point& a = soup.positions[edge.first];
    const Point& b = soup.positions[edge.second];
    const bool on_joint = a[1] == 0 && b[1] == 0 && a[2] == 0 && b[2] == 0;
    if (on_joint) {
      ++joints;
      EXPECT_EQ(k, 3) << edge.first << "-" << edge.second;
    } else {
      EXPECT_LE(k, 2) << edge.first << "-" << edge.second;
    }
  }
  EXPECT_EQ(joints, 4);
  EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{1, 18}, {2, 21}, {3, 4}}));
  for (std::size_t f = 0; f < 16; ++f) {
    const Point n = face_normal(soup, f);
    EXPECT_GT(n[2], 0) << f;
    EXPECT_EQ(n[0], 0) << f;
    EXPECT_EQ(n[1], 0) << f;
  }
  for (std::size_t f = 16; f < 24; ++f) {
    const Point n = face_normal(soup, f);
    EXPECT_LT(n[1], 0) << f;
    for (Index v : soup.polygon(f))
      EXPECT_EQ(soup.positions[v][1], 0) << f;
  }
}

TEST(CanonicalModels, plate_with_box_rib) {
  const Soup soup = models::plate_with_box_rib();
  EXPECT_EQ(soup.num_vertices(), 36u);
  EXPECT_EQ(soup.num_faces(), 72u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  expect_closed_outward_solid(soup, 0, 60);
  expect_closed_outward_solid(soup, 60, 72);
  EXPECT_NEAR(signed_volume(soup, 0, 60), 4.0, 1e-12);
  EXPECT_NEAR(signed_volume(soup, 60, 72), 2.0, 1e-12);
  EXPECT_GT(signed_volume(soup), 0);
  // The 4 sides of the footprint [1,3]x[0.5,1.5] and its diagonal have 4 contenders.
  for (const auto& [edge, k] : contenders(soup)) {
    const Point& a = soup.positions[edge.first];
    const Point& b = soup.positions[edge.second];
    auto in_footprint = [](const Point& p) {
      return p[2] == 0 && (p[0] == 1 || p[0] == 3) && (p[1] == 0.5 || p[1] == 1.5);
    };
    EXPECT_EQ(k, in_footprint(a) && in_footprint(b) ? 4 : 2) << edge.first << "-" << edge.second;
  }
  EXPECT_EQ(contender_histogram(soup)[4], 5);
  // Exactly 2 plate faces coincide with 2 rib faces, with opposite orientation.
  auto key = [&](std::size_t f) {
    std::vector<Index> v(soup.polygon(f).begin(), soup.polygon(f).end());
    std::sort(v.begin(), v.end());
    return v;
  };
  int coincident = 0;
  for (std::size_t f = 0; f < 60; ++f) {
    for (std::size_t g = 60; g < 72; ++g) {
      if (key(f) != key(g))
        continue;
      ++coincident;
      const Point nf = face_normal(soup, f), ng = face_normal(soup, g);
      EXPECT_GT(nf[2], 0);
      EXPECT_LT(ng[2], 0);
    }
  }
  EXPECT_EQ(coincident, 2);
}

TEST(CanonicalModels, prisms24_hexagon) {
  const Soup soup = models::prisms24_hexagon();
  EXPECT_EQ(soup.num_vertices(), 38u);
  EXPECT_EQ(soup.num_faces(), 120u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  int triangles = 0, quads = 0;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    triangles += soup.arity(f) == 3;
    quads += soup.arity(f) == 4;
    EXPECT_EQ(soup.arity(f), f % 5 < 2 ? 3u : 4u) << f;
  }
  EXPECT_EQ(triangles, 48);
  EXPECT_EQ(quads, 72);
  expect_solids(soup, 5);
  const double hexagon_area = 3 * std::sqrt(3.0) / 2;
  for (std::size_t p = 0; p < 24; ++p) {
    EXPECT_NEAR(signed_volume(soup, 5 * p, 5 * p + 5), hexagon_area / 24, 1e-12) << p;
  }
  EXPECT_NEAR(signed_volume(soup), hexagon_area, 1e-12);
  // 60 interior horizontal edges (4), 24 rim edges (2), vertical edges 2t: 6 hexagon corners
  // (t = 2), 6 rim midpoints (t = 3), centre and 6 spoke midpoints (t = 6).
  EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{2, 24}, {4, 66}, {6, 6}, {12, 7}}));
  // 30 pairs of coincident side quads with opposite orientation.
  std::map<std::vector<Index>, std::vector<std::size_t>> by_corners;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    std::vector<Index> v(soup.polygon(f).begin(), soup.polygon(f).end());
    std::sort(v.begin(), v.end());
    by_corners[v].push_back(f);
  }
  int pairs = 0;
  for (const auto& [corners, faces] : by_corners) {
    ASSERT_LE(faces.size(), 2u);
    if (faces.size() == 2) {
      ++pairs;
      EXPECT_LT(dot(face_normal(soup, faces[0]), face_normal(soup, faces[1])), 0);
    }
  }
  EXPECT_EQ(pairs, 30);
}

TEST(CanonicalModels, moebius_strip) {
  for (int segments : {3, 12, 13}) {
    SCOPED_TRACE(segments);
    const Soup soup = models::moebius_strip(segments);
    const auto s = static_cast<std::size_t>(segments);
    EXPECT_EQ(soup.num_vertices(), 2 * s);
    EXPECT_EQ(soup.num_faces(), s);
    expect_indices_in_range(soup);
    expect_welded(soup);
    for (std::size_t f = 0; f < s; ++f)
      EXPECT_EQ(soup.arity(f), 4u);
    // s rungs with 2 contenders, 2s boundary edges; Euler characteristic 0.
    EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{1, 2 * segments}, {2, segments}}));
    // Exactly one edge (the seam rung {0, 1}) is traversed twice in the same direction.
    std::map<Pair, int> directed;
    for (const auto& side : directed_sides(soup))
      ++directed[side];
    int same_direction = 0;
    for (const auto& [side, k] : directed) {
      if (k == 2) {
        ++same_direction;
        EXPECT_EQ(undirected(side.first, side.second), Pair(0, 1));
      }
    }
    EXPECT_EQ(same_direction, 1);
  }
  EXPECT_THROW(models::moebius_strip(2), std::invalid_argument);
}

TEST(CanonicalModels, icosphere) {
  for (int level = 0; level <= 3; ++level) {
    SCOPED_TRACE(level);
    const Soup soup = models::icosphere(level);
    const std::size_t faces = std::size_t{20} << (2 * level);
    EXPECT_EQ(soup.num_vertices(), faces / 2 + 2);
    EXPECT_EQ(soup.num_faces(), faces);
    expect_indices_in_range(soup);
    expect_welded(soup);
    expect_closed_outward_solid(soup, 0, soup.num_faces());
    EXPECT_LT(signed_volume(soup), 4 * kPi / 3);
    for (const Point& p : soup.positions)
      EXPECT_NEAR(p.norm(), 1, 1e-12);
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      EXPECT_GT(dot(face_normal(soup, f), soup.positions[soup.polygon(f)[0]]), 0) << f;
    }
  }
  const Soup level1 = models::icosphere();
  EXPECT_EQ(level1.num_vertices(), 42u);
  EXPECT_EQ(level1.num_faces(), 80u);
  EXPECT_THROW(models::icosphere(-1), std::invalid_argument);
}

TEST(CanonicalModels, cube_with_hole) {
  const Soup soup = models::cube_with_hole();
  EXPECT_EQ(soup.num_vertices(), 8u);
  EXPECT_EQ(soup.num_faces(), 10u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{1, 4}, {2, 13}}));
  std::map<Pair, int> directed;
  for (const auto& side : directed_sides(soup))
    ++directed[side];
  for (const auto& [side, k] : directed) {
    EXPECT_EQ(k, 1);
    if (directed.count({side.second, side.first}) == 0) {
      // Boundary: the rim of the missing top face.
      EXPECT_EQ(soup.positions[side.first][2], 1);
      EXPECT_EQ(soup.positions[side.second][2], 1);
    }
  }
  // Closing the hole with the top face (normal +z) gives the unit cube.
  Soup closed = soup;
  closed.add_polygon({4, 5, 7, 6});
  expect_closed_outward_solid(closed, 0, closed.num_faces());
  EXPECT_NEAR(signed_volume(closed), 1.0, 1e-12);
}

TEST(CanonicalModels, checkerboard_cubes) {
  const int n = 4;
  const Soup soup = models::checkerboard_cubes(n);
  expect_indices_in_range(soup);
  expect_welded(soup);

  // Brute force over cells and lattice points.
  auto filled = [&](int i, int j, int k) {
    return i >= 0 && j >= 0 && k >= 0 && i < n && j < n && k < n && (i + j + k) % 2 == 0;
  };
  int cubes = 0;
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i)
        cubes += filled(i, j, k);
    }
  }
  int used_points = 0;
  for (int z = 0; z <= n; ++z) {
    for (int y = 0; y <= n; ++y) {
      for (int x = 0; x <= n; ++x) {
        bool used = false;
        for (int c = 0; c < 8; ++c)
          used = used || filled(x - (c & 1), y - ((c >> 1) & 1), z - (c >> 2));
        used_points += used;
      }
    }
  }
  // A unit lattice edge has 4 contenders iff 2 of the 4 cells around it are cubes.
  int four_contender_edges = 0;
  for (int axis = 0; axis < 3; ++axis) {
    for (int a = 0; a < n; ++a) {     // position along the edge's axis
      for (int b = 0; b <= n; ++b) {  // lattice line coordinates
        for (int c = 0; c <= n; ++c) {
          int around = 0;
          for (int db = 0; db < 2; ++db) {
            for (int dc = 0; dc < 2; ++dc) {
              std::array<int, 3> cell{};
              cell[axis] = a;
              cell[(axis + 1) % 3] = b - db;
              cell[(axis + 2) % 3] = c - dc;
              around += filled(cell[0], cell[1], cell[2]);
            }
          }
          four_contender_edges += around == 2;
        }
      }
    }
  }
  EXPECT_EQ(cubes, 32);
  EXPECT_EQ(soup.num_faces(), 12u * static_cast<std::size_t>(cubes));
  EXPECT_EQ(soup.num_vertices(), static_cast<std::size_t>(used_points));
  EXPECT_EQ(used_points, 121);
  EXPECT_EQ(four_contender_edges, 3 * n * (n - 1) * (n - 1));
  const auto histogram = contender_histogram(soup);
  EXPECT_EQ(histogram.size(), 2u);
  EXPECT_EQ(histogram.at(4), four_contender_edges);
  EXPECT_GT(histogram.at(2), 0);
  // Every cube is a closed outward solid of 12 consecutive triangles, volume 1.
  expect_solids(soup, 12);
  EXPECT_NEAR(signed_volume(soup), cubes, 1e-9);
  // Vertices are integer lattice points in lattice order (x fastest, then y, then z).
  for (std::size_t v = 1; v < soup.num_vertices(); ++v) {
    const Point& p = soup.positions[v - 1];
    const Point& q = soup.positions[v];
    EXPECT_TRUE(std::make_tuple(p[2], p[1], p[0]) < std::make_tuple(q[2], q[1], q[0])) << v;
  }
}

TEST(CanonicalModels, checkerboard_cubes_sizes) {
  EXPECT_EQ(models::checkerboard_cubes(0).num_faces(), 0u);
  const Soup one = models::checkerboard_cubes(1);
  EXPECT_EQ(one.num_vertices(), 8u);
  EXPECT_EQ(one.num_faces(), 12u);
  const Soup odd = models::checkerboard_cubes(3);
  EXPECT_EQ(odd.num_vertices(), 64u);
  EXPECT_EQ(odd.num_faces(), 12u * 14u);
  const Soup stress = models::checkerboard_cubes(56);
  EXPECT_EQ(stress.num_faces(), 1053696u);
  EXPECT_EQ(stress.num_faces() / 12, 87808u);
  EXPECT_EQ(stress.num_vertices(), 185189u);
  EXPECT_EQ(stress.num_corners(), 3u * 1053696u);
  EXPECT_THROW(models::checkerboard_cubes(-1), std::invalid_argument);
}

TEST(CanonicalModels, torus_grid) {
  const Soup soup = models::torus_grid(8, 6);
  EXPECT_EQ(soup.num_vertices(), 48u);
  EXPECT_EQ(soup.num_faces(), 96u);
  expect_indices_in_range(soup);
  expect_welded(soup);
  expect_closed_outward_solid(soup, 0, soup.num_faces());
  EXPECT_EQ(contender_histogram(soup), (std::map<int, int>{{2, 144}}));
  EXPECT_LT(signed_volume(soup), 2 * kPi * kPi * 1.0 * 0.25 * 0.25);
  EXPECT_THROW(models::torus_grid(2, 6), std::invalid_argument);
}

TEST(CanonicalModels, canonical_models_resource_set) {
  const auto set = models::canonical_models();
  const std::vector<std::string> names = {
      "twocubes",      "hourglass", "bowtie",  "book_of_three", "t_junction_rib",
      "plate_box_rib", "prisms24",  "moebius", "icosphere",     "cube_with_hole"};
  ASSERT_EQ(set.size(), names.size());
  for (std::size_t i = 0; i < set.size(); ++i) {
    SCOPED_TRACE(names[i]);
    EXPECT_EQ(set[i].name, names[i]);
    EXPECT_GT(set[i].soup.num_faces(), 0u);
    expect_indices_in_range(set[i].soup);
  }
  EXPECT_EQ(set[0].soup.num_faces(), 24u);
  EXPECT_EQ(set[7].soup.num_faces(), 12u);  // moebius, 12 segments
  EXPECT_EQ(set[8].soup.num_faces(), 80u);  // icosphere, 1 subdivision
}

TEST(CanonicalModels, deterministic) {
  const auto a = models::canonical_models();
  const auto b = models::canonical_models();
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].soup.positions, b[i].soup.positions) << a[i].name;
    EXPECT_EQ(a[i].soup.corner_vertices, b[i].soup.corner_vertices) << a[i].name;
    EXPECT_EQ(a[i].soup.face_begin, b[i].soup.face_begin) << a[i].name;
  }
}

}  // namespace
