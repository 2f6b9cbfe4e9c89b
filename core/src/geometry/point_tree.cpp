// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/point_tree.h"

#include <algorithm>

namespace meshbridge::detail {

void PointTree::build(std::size_t slot, std::size_t first, std::size_t last) {
  Point lo = positions_[points_[first]], hi = lo;
  for (std::size_t i = first; i < last; ++i) {
    lo.minimize(positions_[points_[i]]);
    hi.maximize(positions_[points_[i]]);
  }
  nodes_[slot].lo = lo;
  nodes_[slot].hi = hi;
  nodes_[slot].first = first;
  nodes_[slot].last = last;
  if (last - first <= 8)
    return;
  const Point extent = hi - lo;
  const int axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0
                   : extent[1] >= extent[2]                         ? 1
                                                                    : 2;
  const std::size_t middle = first + (last - first) / 2;
  std::nth_element(points_.begin() + first, points_.begin() + middle, points_.begin() + last,
                   [&](Index x, Index y) { return positions_[x][axis] < positions_[y][axis]; });
  const std::size_t children = nodes_.size();
  nodes_.resize(children + 2);
  nodes_[slot].left = children;
  build(children, first, middle);
  build(children + 1, middle, last);
}

bool PointTree::segment_meets_box(const Point& a, const Point& b, const Point& lo,
                                  const Point& hi) {
  double t0 = 0, t1 = 1;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = b[axis] - a[axis];
    if (d == 0) {
      if (a[axis] < lo[axis] || a[axis] > hi[axis])
        return false;
      continue;
    }
    double u0 = (lo[axis] - a[axis]) / d, u1 = (hi[axis] - a[axis]) / d;
    if (u0 > u1)
      std::swap(u0, u1);
    t0 = std::max(t0, u0);
    t1 = std::min(t1, u1);
    if (t0 > t1)
      return false;
  }
  return true;
}

}  // namespace meshbridge::detail
