// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The placements of 3MF build items and components (3MF Core Specification 1.2, sections 3.4 and
// 4.1) as affine maps, composed down the component tree and applied to positions (read_3mf.cpp).

#include "meshbridge/soup.h"

#include <array>

namespace meshbridge::detail {

// An affine map p -> A p + t as lib3mf stores it: row j of `m` gives output coordinate j,
// m[j][3] is the translation (the file's "m00 m01 m02 m10 ... m32" is m[0][0] m[1][0] m[2][0]
// m[0][1] ..., row vectors times the matrix as the specification writes them).
using Affine = std::array<std::array<double, 4>, 3>;

constexpr Affine kIdentity = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}}};

// outer after inner: p -> outer(inner(p)).
inline Affine compose(const Affine& outer, const Affine& inner) {
  Affine c{};
  for (int j = 0; j < 3; ++j) {
    for (int i = 0; i < 4; ++i) {
      double s = i == 3 ? outer[j][3] : 0.0;
      for (int k = 0; k < 3; ++k)
        s += outer[j][k] * inner[k][i];
      c[j][i] = s;
    }
  }
  return c;
}

// True if `a` mirrors (its linear part has a negative determinant): the triangles it places
// would be turned inside out unless their corner order is reversed, as slicers do (PrusaSlicer
// reverses them). `a` is the whole placement, composed down the component tree: two mirrors
// cancel.
inline bool mirrors(const Affine& a) {
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  return det < 0;
}

inline Point apply(const Affine& a, const Point& p) {
  Point q;
  for (int j = 0; j < 3; ++j)
    q[j] = a[j][0] * p[0] + a[j][1] * p[1] + a[j][2] * p[2] + a[j][3];
  return q;
}

}  // namespace meshbridge::detail
