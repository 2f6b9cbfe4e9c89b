// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/models/canonical_models.h"

#include "model_builders.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

namespace meshbridge::models {

namespace detail {

//! The 6 faces of a box as corner quads, outward (counter-clockwise seen from outside).
//! Corner c is at (c & 1, (c >> 1) & 1, (c >> 2) & 1) in the box's unit frame.
//! Order: -x, +x, -y, +y, -z, +z.
constexpr std::array<std::array<int, 4>, 6> kBoxQuads = {{
    {0, 4, 6, 2},  // -x
    {1, 3, 7, 5},  // +x
    {0, 1, 5, 4},  // -y
    {2, 6, 7, 3},  // +y
    {0, 2, 3, 1},  // -z
    {4, 5, 7, 6},  // +z
}};

//! Appends the 12 outward triangles of a box whose corner c is vertex corners[c].
//! \param skip_top leaves out the 2 triangles of the +z face
void add_box(Soup& soup, const std::array<Index, 8>& corners, bool skip_top = false) {
  for (std::size_t q = 0; q < kBoxQuads.size(); ++q) {
    if (skip_top && q == 5)
      continue;
    const auto& quad = kBoxQuads[q];
    add_split_quad(soup, corners[quad[0]], corners[quad[1]], corners[quad[2]], corners[quad[3]]);
  }
}

//! Appends the outward surface of the box spanned by the coordinate lists xs, ys, zs (strictly
//! increasing, at least 2 each), gridded at those coordinates, every grid quad split in two.
//! `lattice` holds the vertex of grid point (i, j, k) at (k * ys.size() + j) * xs.size() + i;
//! entries equal to kNoIndex are created on first use, others are reused (welding to an
//! existing solid). Faces are emitted per box side in the order of kBoxQuads.
void add_grid_box(Soup& soup, const std::vector<double>& xs, const std::vector<double>& ys,
                  const std::vector<double>& zs, std::vector<Index>& lattice) {
  const std::size_t nx = xs.size(), ny = ys.size(), nz = zs.size();
  lattice.resize(nx * ny * nz, kNoIndex);
  const std::array<std::size_t, 3> size = {nx, ny, nz};
  auto vertex = [&](std::array<std::size_t, 3> g) {
    Index& v = lattice[(g[2] * ny + g[1]) * nx + g[0]];
    if (v == kNoIndex)
      v = soup.add_vertex(Point(xs[g[0]], ys[g[1]], zs[g[2]]));
    return v;
  };
  for (std::size_t side = 0; side < kBoxQuads.size(); ++side) {
    const std::size_t axis = side / 2;  // fixed axis of this side
    const std::size_t u = (axis + 1) % 3, w = (axis + 2) % 3;
    const std::size_t fixed = side % 2 == 0 ? 0 : size[axis] - 1;
    const auto& quad = kBoxQuads[side];
    for (std::size_t iw = 0; iw + 1 < size[w]; ++iw) {
      for (std::size_t iu = 0; iu + 1 < size[u]; ++iu) {
        std::array<Index, 4> q{};
        for (int c = 0; c < 4; ++c) {
          // Corner bit d of the unit box selects the upper grid line along axis d.
          std::array<std::size_t, 3> g{};
          g[axis] = fixed;
          g[u] = iu + ((quad[c] >> u) & 1);
          g[w] = iw + ((quad[c] >> w) & 1);
          q[c] = vertex(g);
        }
        add_split_quad(soup, q[0], q[1], q[2], q[3]);
      }
    }
  }
}

//! Appends the 4 outward triangles of the tetrahedron (a, b, c, d), whatever its orientation.
void add_tetrahedron(Soup& soup, Index a, Index b, Index c, Index d) {
  const Point& pa = soup.positions[a];
  const double volume =
      dot(cross(soup.positions[b] - pa, soup.positions[c] - pa), soup.positions[d] - pa);
  if (volume < 0)
    std::swap(b, c);
  // Now d lies on the positive side of (a, b, c), so (a, b, c) faces inward.
  soup.add_polygon({a, c, b});
  soup.add_polygon({a, b, d});
  soup.add_polygon({b, c, d});
  soup.add_polygon({a, d, c});
}

}  // namespace detail

Soup two_cubes_sharing_edge() {
  Soup soup;
  soup.reserve(14, 24, 72);
  std::array<Index, 8> a{};
  for (int c = 0; c < 8; ++c)
    a[c] = soup.add_vertex(Point(c & 1, (c >> 1) & 1, (c >> 2) & 1));
  // Cube B = [1,2]x[1,2]x[0,1]: its corners 0 (1,1,0) and 4 (1,1,1) are A's corners 3 and 7.
  std::array<Index, 8> b{};
  for (int c = 0; c < 8; ++c) {
    if (c == 0 || c == 4)
      continue;
    b[c] = soup.add_vertex(Point(1 + (c & 1), 1 + ((c >> 1) & 1), (c >> 2) & 1));
  }
  b[0] = a[3];
  b[4] = a[7];
  detail::add_box(soup, a);
  detail::add_box(soup, b);
  return soup;
}

Soup hourglass() {
  Soup soup;
  soup.reserve(7, 8, 24);
  const Index apex = soup.add_vertex(Point(0, 0, 0));
  std::array<Index, 3> lower{}, upper{};
  const double base[3][2] = {{1, 0}, {-1, 1}, {-1, -1}};
  for (int i = 0; i < 3; ++i)
    lower[i] = soup.add_vertex(Point(base[i][0], base[i][1], -1));
  for (int i = 0; i < 3; ++i)
    upper[i] = soup.add_vertex(Point(base[i][0], base[i][1], 1));
  detail::add_tetrahedron(soup, apex, lower[0], lower[1], lower[2]);
  detail::add_tetrahedron(soup, apex, upper[0], upper[1], upper[2]);
  return soup;
}

Soup bowtie() {
  Soup soup;
  soup.reserve(5, 2, 6);
  const Index centre = soup.add_vertex(Point(0, 0, 0));
  const Index l0 = soup.add_vertex(Point(-1, 1, 0));
  const Index l1 = soup.add_vertex(Point(-1, -1, 0));
  const Index r0 = soup.add_vertex(Point(1, -1, 0));
  const Index r1 = soup.add_vertex(Point(1, 1, 0));
  soup.add_polygon({centre, l0, l1});
  soup.add_polygon({centre, r0, r1});
  return soup;
}

Soup book_of_three() {
  Soup soup;
  soup.reserve(5, 3, 9);
  const Index v0 = soup.add_vertex(Point(0, 0, 0));
  const Index v1 = soup.add_vertex(Point(0, 0, 1));
  const double h = std::sqrt(3.0) / 2;
  const double apex[3][2] = {{1, 0}, {-0.5, h}, {-0.5, -h}};  // 0, 120, 240 degrees
  for (const auto& xy : apex) {
    const Index a = soup.add_vertex(Point(xy[0], xy[1], 0.5));
    soup.add_polygon({v0, v1, a});
  }
  return soup;
}

Soup t_junction_plate_rib() {
  Soup soup;
  soup.reserve(20, 24, 72);
  // Plate grid point (i, j) at (i - 2, j - 1, 0), vertex j * 5 + i.
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 5; ++i)
      soup.add_vertex(Point(i - 2, j - 1, 0));
  }
  auto plate = [](int i, int j) { return static_cast<Index>(j * 5 + i); };
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 4; ++i) {
      detail::add_split_quad(soup, plate(i, j), plate(i + 1, j), plate(i + 1, j + 1),
                             plate(i, j + 1));
    }
  }
  // Rib on y = 0: bottom row = plate row j = 1, top row at z = 1. Quads run +x then +z: -y.
  std::array<Index, 5> top{};
  for (int i = 0; i < 5; ++i)
    top[i] = soup.add_vertex(Point(i - 2, 0, 1));
  for (int i = 0; i < 4; ++i) {
    detail::add_split_quad(soup, plate(i, 1), plate(i + 1, 1), top[i + 1], top[i]);
  }
  return soup;
}

Soup plate_with_box_rib() {
  Soup soup;
  soup.reserve(36, 72, 216);
  const std::vector<double> xs = {0, 1, 3, 4}, ys = {0, 0.5, 1.5, 2}, zs = {-0.5, 0};
  std::vector<Index> plate;
  detail::add_grid_box(soup, xs, ys, zs, plate);
  // The rib's bottom layer is the plate's top-centre quad (grid points (1..2, 1..2, 1)).
  std::vector<Index> rib(8, kNoIndex);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i)
      rib[j * 2 + i] = plate[(1 * 4 + (j + 1)) * 4 + (i + 1)];
  }
  detail::add_grid_box(soup, {1, 3}, {0.5, 1.5}, {0, 1}, rib);
  return soup;
}

Soup prisms24_hexagon() {
  Soup soup;
  soup.reserve(38, 120, 48 * 3 + 72 * 4);
  // The 19 points at z = 0: centre, hexagon corners, spoke midpoints, rim midpoints.
  const double h = std::sqrt(3.0) / 2;
  const double corner_xy[6][2] = {{1, 0}, {0.5, h}, {-0.5, h}, {-1, 0}, {-0.5, -h}, {0.5, -h}};
  std::vector<Point> points;
  points.reserve(19);
  points.emplace_back(0, 0, 0);
  for (const auto& xy : corner_xy)
    points.emplace_back(xy[0], xy[1], 0);
  for (int k = 0; k < 6; ++k)
    points.push_back((points[0] + points[1 + k]) * 0.5);
  for (int k = 0; k < 6; ++k)
    points.push_back((points[1 + k] + points[1 + (k + 1) % 6]) * 0.5);
  const Index n = static_cast<Index>(points.size());
  for (const Point& p : points)
    soup.add_vertex(p);
  for (const Point& p : points)
    soup.add_vertex(Point(p[0], p[1], 1));

  // The 24 triangles, counter-clockwise seen from +z.
  std::vector<std::array<Index, 3>> triangles;
  triangles.reserve(24);
  for (Index k = 0; k < 6; ++k) {
    const Index c = 0, a = 1 + k, b = 1 + (k + 1) % 6;  // centre triangle (c, a, b)
    const Index ca = 7 + k, ab = 13 + k, bc = 7 + (k + 1) % 6;
    triangles.push_back({c, ca, bc});
    triangles.push_back({ca, a, ab});
    triangles.push_back({bc, ab, b});
    triangles.push_back({ca, ab, bc});
  }
  for (const auto& t : triangles) {
    soup.add_polygon({t[0], t[2], t[1]});              // bottom, -z
    soup.add_polygon({t[0] + n, t[1] + n, t[2] + n});  // top, +z
    for (int e = 0; e < 3; ++e) {
      const Index a = t[e], b = t[(e + 1) % 3];
      soup.add_polygon({a, b, b + n, a + n});  // side: along the edge, then up
    }
  }
  return soup;
}

Soup moebius_strip(int segments) {
  detail::check_argument(segments >= 3,
                         "moebius_strip: segments must be >= 3, got " + std::to_string(segments));
  const Index s = static_cast<Index>(segments);
  Soup soup;
  soup.reserve(2 * s, s, 4 * s);
  const double radius = 1, half_width = 0.3;
  for (Index i = 0; i < s; ++i) {
    const double u = 2 * detail::kPi * i / s;
    for (double v : {-half_width, half_width}) {
      const double r = radius + v * std::cos(u / 2);
      soup.add_vertex(Point(r * std::cos(u), r * std::sin(u), v * std::sin(u / 2)));
    }
  }
  for (Index i = 0; i + 1 < s; ++i) {
    soup.add_polygon({2 * i, 2 * i + 2, 2 * i + 3, 2 * i + 1});
  }
  // At u = 2 pi the strip comes back flipped: station s is station 0 with v negated.
  soup.add_polygon({2 * s - 2, 1, 0, 2 * s - 1});
  return soup;
}

Soup icosphere(int subdivisions) {
  detail::check_argument(
      subdivisions >= 0 && subdivisions <= 10,
      "icosphere: subdivisions must be in [0, 10], got " + std::to_string(subdivisions));
  Soup soup;
  const std::size_t final_faces = std::size_t{20} << (2 * subdivisions);
  soup.reserve(final_faces / 2 + 2, final_faces, 3 * final_faces);
  const double t = (1 + std::sqrt(5.0)) / 2;
  const double xyz[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                             {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                             {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (const auto& p : xyz)
    soup.add_vertex(Point(p[0], p[1], p[2]).normalized());
  std::vector<std::array<Index, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int level = 0; level < subdivisions; ++level) {
    std::unordered_map<std::uint64_t, Index> midpoints;
    midpoints.reserve(faces.size() * 3 / 2);
    auto midpoint = [&](Index a, Index b) {
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      auto [it, inserted] = midpoints.emplace(key, kNoIndex);
      if (inserted) {
        it->second = soup.add_vertex(((soup.positions[a] + soup.positions[b]) * 0.5).normalized());
      }
      return it->second;
    };
    std::vector<std::array<Index, 3>> finer;
    finer.reserve(faces.size() * 4);
    for (const auto& f : faces) {
      const Index ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      finer.push_back({f[0], ab, ca});
      finer.push_back({ab, f[1], bc});
      finer.push_back({ca, bc, f[2]});
      finer.push_back({ab, bc, ca});
    }
    faces.swap(finer);
  }
  for (const auto& f : faces)
    soup.add_polygon({f[0], f[1], f[2]});
  return soup;
}

Soup cube_with_hole() {
  Soup soup;
  soup.reserve(8, 10, 30);
  std::array<Index, 8> corners{};
  for (int c = 0; c < 8; ++c) {
    corners[c] = soup.add_vertex(Point(c & 1, (c >> 1) & 1, (c >> 2) & 1));
  }
  detail::add_box(soup, corners, /*skip_top=*/true);
  return soup;
}

Soup checkerboard_cubes(int n) {
  detail::check_argument(n >= 0 && n <= 600,
                         "checkerboard_cubes: n must be in [0, 600], got " + std::to_string(n));
  Soup soup;
  if (n == 0)
    return soup;
  const std::size_t cells = static_cast<std::size_t>(n) * n * n;
  const std::size_t cubes = (cells + 1) / 2;
  const std::size_t side = static_cast<std::size_t>(n) + 1;  // lattice points per axis
  soup.face_begin.reserve(12 * cubes + 1);
  soup.corner_vertices.reserve(36 * cubes);

  // Pass 1: faces on lattice point ids (x fastest), marking the points used.
  std::vector<Index> lattice(side * side * side, kNoIndex);  // later: lattice id -> vertex
  const std::array<std::size_t, 8> offset = {0,
                                             1,
                                             side,
                                             side + 1,
                                             side * side,
                                             side * side + 1,
                                             side * side + side,
                                             side * side + side + 1};
  std::array<Index, 8> corners{};
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = (j + k) % 2; i < n; i += 2) {
        const std::size_t base = (static_cast<std::size_t>(k) * side + j) * side + i;
        for (int c = 0; c < 8; ++c) {
          corners[c] = static_cast<Index>(base + offset[c]);
          lattice[base + offset[c]] = 0;
        }
        detail::add_box(soup, corners);
      }
    }
  }
  // Pass 2: number the used points in lattice order and create them.
  Index used = 0;
  for (Index& v : lattice) {
    if (v != kNoIndex)
      v = used++;
  }
  soup.positions.reserve(used);
  for (std::size_t id = 0; id < lattice.size(); ++id) {
    if (lattice[id] == kNoIndex)
      continue;
    soup.positions.emplace_back(static_cast<double>(id % side),
                                static_cast<double>(id / side % side),
                                static_cast<double>(id / (side * side)));
  }
  for (Index& v : soup.corner_vertices)
    v = lattice[v];
  return soup;
}

Soup torus_grid(int n, int m) {
  detail::check_argument(n >= 3 && m >= 3 && static_cast<std::int64_t>(n) * m <= (1 << 28),
                         "torus_grid: need n >= 3, m >= 3, n * m <= 2^28, got n = " +
                             std::to_string(n) + ", m = " + std::to_string(m));
  const Index nn = static_cast<Index>(n), mm = static_cast<Index>(m);
  Soup soup;
  soup.reserve(std::size_t{nn} * mm, 2 * std::size_t{nn} * mm, 6 * std::size_t{nn} * mm);
  const double major = 1, minor = 0.25;
  for (Index i = 0; i < nn; ++i) {
    const double u = 2 * detail::kPi * i / nn;
    for (Index j = 0; j < mm; ++j) {
      const double v = 2 * detail::kPi * j / mm;
      const double r = major + minor * std::cos(v);
      soup.add_vertex(Point(r * std::cos(u), r * std::sin(u), minor * std::sin(v)));
    }
  }
  auto vertex = [&](Index i, Index j) { return (i % nn) * mm + j % mm; };
  for (Index i = 0; i < nn; ++i) {
    for (Index j = 0; j < mm; ++j) {
      // d/du x d/dv points away from the tube's core: outward.
      detail::add_split_quad(soup, vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1),
                             vertex(i, j + 1));
    }
  }
  return soup;
}

std::vector<NamedModel> canonical_models() {
  std::vector<NamedModel> models;
  models.push_back({"twocubes", two_cubes_sharing_edge()});
  models.push_back({"hourglass", hourglass()});
  models.push_back({"bowtie", bowtie()});
  models.push_back({"book_of_three", book_of_three()});
  models.push_back({"t_junction_rib", t_junction_plate_rib()});
  models.push_back({"plate_box_rib", plate_with_box_rib()});
  models.push_back({"prisms24", prisms24_hexagon()});
  models.push_back({"moebius", moebius_strip(12)});
  models.push_back({"icosphere", icosphere(1)});
  models.push_back({"cube_with_hole", cube_with_hole()});
  return models;
}

}  // namespace meshbridge::models
