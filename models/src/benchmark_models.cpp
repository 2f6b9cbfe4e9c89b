// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/models/benchmark_models.h"

#include "meshbridge/models/canonical_models.h"
#include "model_builders.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <vector>

namespace meshbridge::models {

namespace detail {

//! splitmix64 (Steele, Lea, Flood 2014): tiny, seedable, identical on every platform.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  //! Uniform in [0, bound) up to a bias below bound / 2^64 (deterministic, no rejection).
  std::uint64_t below(std::uint64_t bound) { return next() % bound; }

 private:
  std::uint64_t state_;
};

}  // namespace detail

Soup random_singular_soup(const RandomSoupOptions& options) {
  const int n = options.n, m = options.m, max_fins = options.max_fins;
  const double fraction = options.singular_fraction;
  detail::check_argument(
      n >= 3 && m >= 3 && static_cast<std::int64_t>(n) * m <= (1 << 26) && fraction >= 0 &&
          fraction <= 1 && max_fins >= 1 && max_fins <= 8,
      "random_singular_soup: need n >= 3, m >= 3, n * m <= 2^26, singular_fraction in [0, 1], "
      "max_fins in [1, 8], got n = " +
          std::to_string(n) + ", m = " + std::to_string(m) + ", singular_fraction = " +
          std::to_string(fraction) + ", max_fins = " + std::to_string(max_fins));
  Soup soup = torus_grid(n, m);
  const std::size_t edges = 3 * static_cast<std::size_t>(n) * m;
  const std::size_t chosen = static_cast<std::size_t>(std::llround(fraction * edges));

  // Partial Fisher-Yates: the first `chosen` entries are a uniform sample; then edge order.
  detail::SplitMix64 random(options.seed);
  std::vector<Index> order(edges);
  std::iota(order.begin(), order.end(), Index{0});
  for (std::size_t i = 0; i < chosen; ++i)
    std::swap(order[i], order[i + random.below(edges - i)]);
  order.resize(chosen);
  std::sort(order.begin(), order.end());

  soup.reserve(soup.num_vertices() + chosen * max_fins, soup.num_faces() + chosen * max_fins,
               soup.num_corners() + 3 * chosen * max_fins);
  const Index nn = static_cast<Index>(n), mm = static_cast<Index>(m);
  auto vertex = [&](Index i, Index j) { return (i % nn) * mm + j % mm; };
  for (const Index e : order) {
    const Index q = e / 3, i = q / mm, j = q % mm;
    const Index a = vertex(i, j);
    const Index b = e % 3 == 0   ? vertex(i + 1, j)
                    : e % 3 == 1 ? vertex(i, j + 1)
                                 : vertex(i + 1, j + 1);
    const Point pa = soup.positions[a], pb = soup.positions[b];
    const Point mid = (pa + pb) * 0.5;
    // Outward torus normal at the midpoint: away from the nearest point of the core circle.
    const Point core = Point(mid[0], mid[1], 0).normalized();
    const Point normal = (mid - core).normalized();
    const Point tangent = cross(pb - pa, normal).normalized();
    const double height = 0.5 * (pb - pa).norm();
    const int fins = 1 + static_cast<int>(random.below(static_cast<std::uint64_t>(max_fins)));
    for (int k = 0; k < fins; ++k) {
      const double angle = detail::kPi / 3 * (2.0 * (k + 0.5) / fins - 1);  // in (-60, 60) deg
      const Index apex =
          soup.add_vertex(mid + (normal * std::cos(angle) + tangent * std::sin(angle)) * height);
      if (random.below(2) == 0) {
        soup.add_polygon({a, b, apex});
      } else {
        soup.add_polygon({b, a, apex});
      }
    }
  }
  return soup;
}

Soup prisms_hexagon(int k) {
  detail::check_argument(k >= 1 && k <= 64,
                         "prisms_hexagon: k must be in [1, 64], got " + std::to_string(k));
  const int s = 2 * k;
  const Index points = static_cast<Index>(3 * s * s + 3 * s + 1);
  const std::size_t prisms = 6 * static_cast<std::size_t>(s) * s;
  Soup soup;
  soup.reserve(2 * points, 5 * prisms, prisms * (2 * 3 + 3 * 4));

  // Lattice point (a, b), |a|, |b|, |a + b| <= s, numbered with b slowest, a ascending.
  const int width = 2 * s + 1;
  std::vector<Index> lattice(static_cast<std::size_t>(width) * width, kNoIndex);
  auto inside = [s](int a, int b) {
    return std::abs(a) <= s && std::abs(b) <= s && std::abs(a + b) <= s;
  };
  auto slot = [&](int a, int b) -> Index& {
    return lattice[static_cast<std::size_t>(b + s) * width + (a + s)];
  };
  const double h = std::sqrt(3.0) / 2;
  std::vector<Point> bottom;
  bottom.reserve(points);
  for (int b = -s; b <= s; ++b) {
    for (int a = -s; a <= s; ++a) {
      if (!inside(a, b))
        continue;
      slot(a, b) = static_cast<Index>(bottom.size());
      bottom.emplace_back((a + 0.5 * b) / s, h * b / s, 0.0);
    }
  }
  for (const Point& p : bottom)
    soup.add_vertex(p);
  for (const Point& p : bottom)
    soup.add_vertex(Point(p[0], p[1], 1));

  auto add_prism = [&](Index p0, Index p1, Index p2) {          // counter-clockwise seen from +z
    soup.add_polygon({p0, p2, p1});                             // bottom, -z
    soup.add_polygon({p0 + points, p1 + points, p2 + points});  // top, +z
    const std::array<Index, 3> t = {p0, p1, p2};
    for (int e = 0; e < 3; ++e) {
      const Index a = t[e], b = t[(e + 1) % 3];
      soup.add_polygon({a, b, b + points, a + points});  // side: along the edge, then up
    }
  };
  for (int b = -s; b < s; ++b) {
    for (int a = -s; a < s; ++a) {
      if (inside(a, b) && inside(a + 1, b) && inside(a, b + 1))
        add_prism(slot(a, b), slot(a + 1, b), slot(a, b + 1));  // "up" triangle
      if (inside(a + 1, b) && inside(a + 1, b + 1) && inside(a, b + 1))
        add_prism(slot(a + 1, b), slot(a + 1, b + 1), slot(a, b + 1));  // "down" triangle
    }
  }
  return soup;
}

Soup stiffened_plate(const StiffenedPlateOptions& options) {
  const std::int64_t r = options.resolution, R = options.ribs, C = options.cross_ribs;
  const std::int64_t nx = 2 * (C + 1) * r, ny = (R + 1) * r;
  const bool ok_args =
      r >= 1 && R >= 0 && C >= 0 && r <= (1 << 14) && R <= (1 << 14) && C <= (1 << 14);
  detail::check_argument(
      ok_args && 2 * nx * ny + 2 * R * nx * r + 2 * C * ny * r <= (std::int64_t{1} << 28),
      "stiffened_plate: need resolution >= 1, ribs >= 0, cross_ribs >= 0 and at most 2^28 faces, "
      "got resolution = " +
          std::to_string(r) + ", ribs = " + std::to_string(R) +
          ", cross_ribs = " + std::to_string(C));
  Soup soup;
  soup.reserve((nx + 1) * (ny + 1) + R * (nx + 1) * r + C * (ny + 1) * r,
               2 * nx * ny + 2 * R * nx * r + 2 * C * ny * r,
               3 * (2 * nx * ny + 2 * R * nx * r + 2 * C * ny * r));
  const double step = 1.0 / static_cast<double>(r);

  // Plate: (i, j) is vertex j (nx + 1) + i.
  for (std::int64_t j = 0; j <= ny; ++j) {
    for (std::int64_t i = 0; i <= nx; ++i)
      soup.add_vertex(Point(i * step, j * step, 0));
  }
  auto plate = [&](std::int64_t i, std::int64_t j) { return static_cast<Index>(j * (nx + 1) + i); };
  for (std::int64_t j = 0; j < ny; ++j) {
    for (std::int64_t i = 0; i < nx; ++i)
      detail::add_split_quad(soup, plate(i, j), plate(i + 1, j), plate(i + 1, j + 1),
                             plate(i, j + 1));
  }

  // Ribs along x at y = rib; their vertex (i, k) for k >= 1 is stored for the cross ribs.
  std::vector<std::vector<Index>> rib_vertices(static_cast<std::size_t>(R));
  for (std::int64_t rib = 1; rib <= R; ++rib) {
    const std::int64_t j = rib * r;  // plate grid line
    std::vector<Index>& grid = rib_vertices[static_cast<std::size_t>(rib - 1)];
    grid.resize(static_cast<std::size_t>((nx + 1) * (r + 1)));
    auto at = [&](std::int64_t i, std::int64_t k) -> Index& {
      return grid[static_cast<std::size_t>(k * (nx + 1) + i)];
    };
    for (std::int64_t i = 0; i <= nx; ++i)
      at(i, 0) = plate(i, j);
    for (std::int64_t k = 1; k <= r; ++k) {
      for (std::int64_t i = 0; i <= nx; ++i)
        at(i, k) = soup.add_vertex(Point(i * step, j * step, k * step));
    }
    for (std::int64_t k = 0; k < r; ++k) {
      for (std::int64_t i = 0; i < nx; ++i)  // +x then +z: normal -y
        detail::add_split_quad(soup, at(i, k), at(i + 1, k), at(i + 1, k + 1), at(i, k + 1));
    }
  }

  // Cross ribs along y at x = 2 c, sharing the vertical line where they cross a rib.
  for (std::int64_t c = 1; c <= C; ++c) {
    const std::int64_t i = 2 * c * r;  // plate grid column
    std::vector<Index> grid(static_cast<std::size_t>((ny + 1) * (r + 1)));
    auto at = [&](std::int64_t j, std::int64_t k) -> Index& {
      return grid[static_cast<std::size_t>(k * (ny + 1) + j)];
    };
    for (std::int64_t j = 0; j <= ny; ++j)
      at(j, 0) = plate(i, j);
    for (std::int64_t k = 1; k <= r; ++k) {
      for (std::int64_t j = 0; j <= ny; ++j) {
        if (j % r == 0 && j / r >= 1 && j / r <= R) {
          at(j, k) = rib_vertices[static_cast<std::size_t>(j / r - 1)]
                                 [static_cast<std::size_t>(k * (nx + 1) + i)];
        } else {
          at(j, k) = soup.add_vertex(Point(i * step, j * step, k * step));
        }
      }
    }
    for (std::int64_t k = 0; k < r; ++k) {
      for (std::int64_t j = 0; j < ny; ++j)  // +y then +z: normal +x
        detail::add_split_quad(soup, at(j, k), at(j + 1, k), at(j + 1, k + 1), at(j, k + 1));
    }
  }
  return soup;
}

}  // namespace meshbridge::models
