// SPDX-License-Identifier: GPL-3.0-or-later
// The only file of find_self_intersections() that includes CGAL: its Epick kernel's predicates
// are filtered (interval arithmetic, then exact numbers where the intervals cannot decide), so
// every answer here is exact for the double coordinates given.
#include "triangle_pairs.h"

#ifdef MESHBRIDGE_WITH_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>
#endif

#include <cmath>
#include <stdexcept>

namespace meshbridge::detail {

#ifdef MESHBRIDGE_WITH_CGAL

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using P3 = Kernel::Point_3;

P3 point(const Point* positions, Index v) {
  const Point& p = positions[v];
  return P3(p[0], p[1], p[2]);
}

//! True if segment [s, t] meets triangle (a, b, c): a cheap rejection when both ends lie
//! strictly on one side of the triangle's plane, then CGAL's exact test.
bool segment_meets_triangle(const P3& s, const P3& t, const P3& a, const P3& b, const P3& c) {
  const CGAL::Orientation os = CGAL::orientation(a, b, c, s);
  const CGAL::Orientation ot = CGAL::orientation(a, b, c, t);
  if (os != CGAL::COPLANAR && os == ot)
    return false;
  return CGAL::do_intersect(Kernel::Segment_3(s, t), Kernel::Triangle_3(a, b, c));
}

//! True if all three points lie strictly on one side of plane (a, b, c).
bool strictly_one_side(const P3& a, const P3& b, const P3& c, const P3& p, const P3& q,
                       const P3& r) {
  const CGAL::Orientation op = CGAL::orientation(a, b, c, p);
  if (op == CGAL::COPLANAR)
    return false;
  return CGAL::orientation(a, b, c, q) == op && CGAL::orientation(a, b, c, r) == op;
}

//! True if triangles (p, a, b) and (p, c, d), which share only p, meet through side (a, b)
//! only where they touch along a side from p: `a` lies on side p-c or p-d of the other triangle
//! (so its side p-a runs along that side), and `b` is off the other's plane (side (a, b) meets
//! it at `a` alone) or in it across that side (the two touch along p-a only). Repair leaves such
//! contacts where it splits one pair's edge at its midpoint: the midpoint lies on the edge of
//! the other pair's faces, which do not have it as a corner.
bool touch_along_a_side(const P3& p, const P3& a, const P3& b, const P3& c, const P3& d) {
  for (int k = 0; k < 2; ++k) {
    const P3& e = k == 0 ? c : d;  // the side p-e that `a` may lie on, `f` the third corner
    const P3& f = k == 0 ? d : c;
    if (!CGAL::collinear(p, a, e) || !CGAL::collinear_are_ordered_along_line(p, a, e))
      continue;
    if (CGAL::orientation(p, c, d, b) != CGAL::COPLANAR)
      return true;
    return CGAL::coplanar_orientation(p, e, f, b) == CGAL::NEGATIVE;
  }
  return false;
}

//! True if side (a, b) of triangle (p, a, b) meets triangle (p, c, d) (sharing only p) other than
//! by touching along a side from p (touch_along_a_side(), with either end of the side).
bool side_folds_into(const P3& p, const P3& a, const P3& b, const P3& c, const P3& d) {
  return segment_meets_triangle(a, b, p, c, d) && !touch_along_a_side(p, a, b, c, d) &&
         !touch_along_a_side(p, b, a, c, d);
}

//! Rotates `t` so that its corner i comes first (the winding is kept).
TriangleCorners rotated(const TriangleCorners& t, int i) {
  return {t[i], t[(i + 1) % 3], t[(i + 2) % 3]};
}

}  // namespace

bool triangle_predicates_available() {
  return true;
}

bool is_degenerate_triangle(const Point* positions, const TriangleCorners& t) {
  if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    return true;
  // A component of the cross product far above its rounding error settles it without CGAL:
  // the differences and products are each within 2^-53 relative, so 1e-14 of the terms' size
  // bounds the error of the double result by a wide margin.
  const Point& a = positions[t[0]];
  const Point u = positions[t[1]] - a, v = positions[t[2]] - a;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double l = u[j] * v[k], r = u[k] * v[j];
    const double size = std::abs(l) + std::abs(r);
    if (size > 1e-250 && std::abs(l - r) > 1e-14 * size)  // (far from underflow)
      return false;
  }
  return CGAL::collinear(point(positions, t[0]), point(positions, t[1]), point(positions, t[2]));
}

bool triangles_intersect(const Point* positions, const TriangleCorners& t,
                         const TriangleCorners& u) {
  // Which corners are shared: ti[k] in t matches ui[k] in u.
  int shared = 0;
  int ti[3] = {0, 0, 0}, ui[3] = {0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (t[i] == u[j]) {
        ti[shared] = i;
        ui[shared] = j;
        ++shared;
      }
  if (shared == 3)
    return true;  // the same triangle twice: they overlap
  if (shared == 0) {
    const P3 a = point(positions, t[0]), b = point(positions, t[1]), c = point(positions, t[2]);
    const P3 d = point(positions, u[0]), e = point(positions, u[1]), f = point(positions, u[2]);
    if (strictly_one_side(a, b, c, d, e, f) || strictly_one_side(d, e, f, a, b, c))
      return false;
    return CGAL::do_intersect(Kernel::Triangle_3(a, b, c), Kernel::Triangle_3(d, e, f));
  }
  if (shared == 1) {
    // t = (p, a, b), u = (p, c, d): a fold if a side opposite p meets the other triangle
    // (touching along a side from p is no fold).
    const TriangleCorners tr = rotated(t, ti[0]), ur = rotated(u, ui[0]);
    const P3 p = point(positions, tr[0]);
    const P3 a = point(positions, tr[1]), b = point(positions, tr[2]);
    const P3 c = point(positions, ur[1]), d = point(positions, ur[2]);
    return side_folds_into(p, a, b, c, d) || side_folds_into(p, c, d, a, b);
  }
  // shared == 2: t = (p, q, a), u = (., ., b) around the shared edge p-q; they meet off that
  // edge only when coplanar with a and b on the same side of it.
  const int t_other = 3 - ti[0] - ti[1], u_other = 3 - ui[0] - ui[1];
  const P3 p = point(positions, t[ti[0]]), q = point(positions, t[ti[1]]);
  const P3 a = point(positions, t[t_other]), b = point(positions, u[u_other]);
  if (CGAL::orientation(p, q, a, b) != CGAL::COPLANAR)
    return false;
  return CGAL::coplanar_orientation(p, q, a, b) == CGAL::POSITIVE;
}

#else  // no CGAL

bool triangle_predicates_available() {
  return false;
}

bool is_degenerate_triangle(const Point*, const TriangleCorners&) {
  throw std::runtime_error("self-intersections need CGAL's predicates (built without CGAL)");
}

bool triangles_intersect(const Point*, const TriangleCorners&, const TriangleCorners&) {
  throw std::runtime_error("self-intersections need CGAL's predicates (built without CGAL)");
}

#endif  // MESHBRIDGE_WITH_CGAL

}  // namespace meshbridge::detail
