// SPDX-License-Identifier: GPL-3.0-or-later
// Polygons to triangles for the formats that hold triangles only (STL, 3MF, and the STL round
// trip that predicts what a reader gets back): ear clipping in the polygon's plane, so that a
// non-convex polygon is covered by triangles inside it, not by a fan that can reach outside.

#pragma once

#include "meshbridge/soup.h"

#include <array>
#include <vector>

namespace meshbridge::detail {

//! Reusable buffers of triangulate_polygon().
struct Triangulation {
  std::vector<std::array<Index, 3>> triangles;  //!< the result: corners as vertex indices
  std::vector<double> u, v;                     // (scratch) the corners in the polygon's plane
  std::vector<Index> previous, next;            // (scratch) the ring of corners left
};

//! The n - 2 triangles of polygon `f` of `soup` (n >= 3 corners), each running the polygon's
//! way round, into `t.triangles`: a triangle as it is; larger polygons by ear clipping
//! (Meisters 1975; O(n^2)) in the plane of their Newell normal, cutting off at each step the
//! first convex corner whose triangle holds no other corner of the ring. A polygon with no such
//! corner left (self-intersecting, pinched, or flat to a line), a zero normal, or more than
//! 4096 corners has the rest fanned from its first remaining corner, as before.
void triangulate_polygon(const Soup& soup, std::size_t f, Triangulation& t);

}  // namespace meshbridge::detail
