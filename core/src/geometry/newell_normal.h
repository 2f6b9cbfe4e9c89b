// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Newell's normal of a polygon (Newell 1972; Sutherland, Sproull and Schumacker 1974): the sum
// over its sides of the cross products' components, twice the polygon's vector area. Exact for
// planar polygons and a good plane for nearly planar ones; any corner count, any convexity.

#include "meshbridge/soup.h"

#include <cstddef>

namespace meshbridge::detail {

//! Newell normal (twice the vector area) of polygon f of `soup`. \pre f < soup.num_faces()
Point newell_normal(const Soup& soup, std::size_t f);

//! Newell normal of the polygon with the corners `polygon` (vertices of `soup`).
Point newell_normal(const Soup& soup, PolygonView polygon);

//! Sum of the magnitudes of the products newell_normal() adds up for polygon f: its rounding
//! error is at most a few epsilons of this.
double newell_rounding_scale(const Soup& soup, Index f);

}  // namespace meshbridge::detail
