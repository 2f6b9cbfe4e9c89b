// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The narrow phase of find_self_intersections(): does one pair of triangles intersect, by the
// rules of self_intersections.h, with CGAL's filtered exact predicates (Epick).

#include "meshbridge/soup.h"

#include <array>

namespace meshbridge::detail {

//! A triangle as three vertex ids where equal ids mean equal positions.
using TriangleCorners = std::array<Index, 3>;

//! True if this build has the predicates (CGAL at build time).
bool triangle_predicates_available();

//! True if the corners of `t` are collinear (exactly), a repeated position included.
bool is_degenerate_triangle(const Point* positions, const TriangleCorners& t);

//! True if non-degenerate triangles `t` and `u` intersect: any common point if they share no
//! vertex id; with one shared id, a common point off it; with two, coplanar on the same side of
//! the shared edge; with three, always.
bool triangles_intersect(const Point* positions, const TriangleCorners& t,
                         const TriangleCorners& u);

}  // namespace meshbridge::detail
