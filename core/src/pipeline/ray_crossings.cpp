// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/ray_crossings.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshbridge::detail {

namespace {

// The ray's direction and two axes across it. Axis-aligned rays would pass through the edges of
// axis-aligned models (CAD grids, voxel shells) all the time, leaving points undecided; this
// direction is generic, so such coincidences need more than a grid to happen.
struct Frame {
  Point u, v, d;
  Frame() {
    d = Point(0.3181, 0.5477, 0.7739).normalized();
    u = OpenMesh::cross(d, Point(1, 0, 0)).normalized();
    v = OpenMesh::cross(d, u);
  }
  Point operator()(const Point& p) const {
    return Point(OpenMesh::dot(p, u), OpenMesh::dot(p, v), OpenMesh::dot(p, d));
  }
};
const Frame kFrame;

// Twice the signed area of (a, b, c) projected on the xy plane: > 0 counter-clockwise.
double orient_xy(const Point& a, const Point& b, const Point& c) {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

// Whether |o|, an orient_xy() of (a, b, p), is within rounding of 0: p on the line through a, b.
bool near_zero(double o, const Point& a, const Point& b, const Point& p) {
  const double scale = (std::abs(b[0] - a[0]) + std::abs(b[1] - a[1])) *
                       (std::abs(p[0] - a[0]) + std::abs(p[1] - a[1]));
  return std::abs(o) <= 1e-12 * scale;
}

}  // namespace

RayCrossings::RayCrossings(const Soup& soup, const std::vector<char>& flipped,
                           const Index* faces_begin, const Index* faces_end) {
  for (const Index* f = faces_begin; f != faces_end; ++f) {
    const PolygonView polygon = soup.polygon(*f);
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      Triangle t{kFrame(soup.positions[polygon[0]]), kFrame(soup.positions[polygon[i]]),
                 kFrame(soup.positions[polygon[i + 1]]), 0};
      if (flipped[*f])
        std::swap(t.b, t.c);
      t.z_normal = orient_xy(t.a, t.b, t.c);
      if (t.z_normal != 0)  // seen edge-on from +z: no ray crosses it, only grazes its edges
        triangles_.push_back(t);
    }
  }
  if (triangles_.empty())
    return;
  double max[2] = {-std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity()};
  min_[0] = min_[1] = std::numeric_limits<double>::infinity();
  for (const Triangle& t : triangles_) {
    for (const Point* p : {&t.a, &t.b, &t.c}) {
      for (int axis = 0; axis < 2; ++axis) {
        min_[axis] = std::min(min_[axis], (*p)[axis]);
        max[axis] = std::max(max[axis], (*p)[axis]);
      }
    }
  }
  const std::size_t side = std::clamp<std::size_t>(
      static_cast<std::size_t>(std::sqrt(static_cast<double>(triangles_.size()))), 1, 1024);
  for (int axis = 0; axis < 2; ++axis) {
    extent_[axis] = max[axis] - min_[axis];
    cells_[axis] = extent_[axis] > 0 ? side : 1;
  }
  // Each triangle in every cell its projected box touches (two passes: count, then fill).
  begin_.assign(cells_[0] * cells_[1] + 1, 0);
  std::vector<Index> fill;
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      for (std::size_t c = 0; c + 1 < begin_.size(); ++c)
        begin_[c + 1] += begin_[c];
      listed_.resize(begin_.back());
      fill.assign(begin_.begin(), begin_.end() - 1);
    }
    for (Index i = 0; i < triangles_.size(); ++i) {
      const Triangle& t = triangles_[i];
      std::size_t first[2], last[2];
      for (int axis = 0; axis < 2; ++axis) {
        first[axis] = cell(std::min({t.a[axis], t.b[axis], t.c[axis]}), axis);
        last[axis] = cell(std::max({t.a[axis], t.b[axis], t.c[axis]}), axis);
      }
      for (std::size_t y = first[1]; y <= last[1]; ++y) {
        for (std::size_t x = first[0]; x <= last[0]; ++x) {
          const std::size_t c = y * cells_[0] + x;
          if (pass == 0)
            ++begin_[c + 1];
          else
            listed_[fill[c]++] = i;
        }
      }
    }
  }
}

std::size_t RayCrossings::cell(double value, int axis) const {
  if (!(extent_[axis] > 0))
    return 0;
  const double t = (value - min_[axis]) / extent_[axis] * static_cast<double>(cells_[axis]);
  return std::min(cells_[axis] - 1, static_cast<std::size_t>(std::max(0.0, t)));
}

double RayCrossings::at(const Point& position) const {
  if (triangles_.empty())
    return 0;
  const Point p = kFrame(position);
  if (p[0] < min_[0] || p[1] < min_[1] || p[0] > min_[0] + extent_[0] ||
      p[1] > min_[1] + extent_[1])
    return 0;  // the ray misses the shell's projection
  const std::size_t c = cell(p[1], 1) * cells_[0] + cell(p[0], 0);
  long winding = 0;
  for (Index k = begin_[c]; k < begin_[c + 1]; ++k) {
    const Triangle& t = triangles_[listed_[k]];
    const double sign = t.z_normal > 0 ? 1 : -1;
    const double o[3] = {orient_xy(t.a, t.b, p), orient_xy(t.b, t.c, p), orient_xy(t.c, t.a, p)};
    if (sign * o[0] < 0 || sign * o[1] < 0 || sign * o[2] < 0) {
      // Outside the projected triangle, unless only by rounding.
      if ((sign * o[0] < 0 && !near_zero(o[0], t.a, t.b, p)) ||
          (sign * o[1] < 0 && !near_zero(o[1], t.b, t.c, p)) ||
          (sign * o[2] < 0 && !near_zero(o[2], t.c, t.a, p)))
        continue;
    }
    if (near_zero(o[0], t.a, t.b, p) || near_zero(o[1], t.b, t.c, p) ||
        near_zero(o[2], t.c, t.a, p))
      return std::numeric_limits<double>::quiet_NaN();  // through an edge or a corner
    // The triangle's height above p's projection (barycentric, from the projected areas).
    const double z = (o[1] * t.a[2] + o[2] * t.b[2] + o[0] * t.c[2]) / t.z_normal;
    const double scale = std::abs(t.a[2]) + std::abs(t.b[2]) + std::abs(t.c[2]) + std::abs(p[2]);
    if (std::abs(z - p[2]) <= 1e-12 * scale)
      return std::numeric_limits<double>::quiet_NaN();  // p on the shell
    if (z > p[2])
      winding += t.z_normal > 0 ? 1 : -1;
  }
  return static_cast<double>(winding);
}

}  // namespace meshbridge::detail
