// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The signed volume a closed surface encloses, summed polygon by polygon (the divergence
// theorem; as in CGAL PMP's volume() and pmp-library's volume()): each polygon, fanned from its
// first corner p0, adds for every fan triangle (p0, pi, pi+1) the triple product
// (p0 - o) . ((pi - o) x (pi+1 - o)), six times the signed volume of the tetrahedron it makes
// with the origin o. For a closed surface the sum does not depend on o (up to rounding; an o
// near the surface keeps the rounding small); it is positive when the faces wind outward.

#include "meshbridge/soup.h"

#include <OpenMesh/Core/Geometry/VectorT.hh>

#include <cmath>

namespace meshbridge::detail {

//! Adds polygon `polygon`'s fan terms about `origin` to `volume` (each term, so the sum rounds
//! as term-by-term accumulation) and their absolute values to `magnitude` (the scale of the
//! rounding error: a sum within ~1e-9 of it is zero); with `noise`, also |p0 - o| |pi - o|
//! |pi+1 - o| per term there (a bound far above the triple product's own rounding). Returns
//! nothing: the callers keep one sum per component.
inline void add_fan_volume(const Soup& soup, PolygonView polygon, const Point& origin,
                           double& volume, double& magnitude, double* noise = nullptr) {
  const Point a = soup.positions[polygon[0]] - origin;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Point b = soup.positions[polygon[i]] - origin;
    const Point c = soup.positions[polygon[i + 1]] - origin;
    const double term = OpenMesh::dot(a, OpenMesh::cross(b, c));
    volume += term;
    magnitude += std::abs(term);
    if (noise != nullptr)
      *noise += a.norm() * b.norm() * c.norm();
  }
}

}  // namespace meshbridge::detail
