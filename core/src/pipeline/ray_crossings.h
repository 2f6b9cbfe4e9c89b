// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The winding number of a large closed shell at many points, by counting signed ray crossings
// (used by nesting_depths() where the solid-angle sum over every face would cost too much).

#include "meshbridge/soup.h"

#include <vector>

namespace meshbridge::detail {

//! A closed, consistently oriented shell (the given faces of `soup`, face f reversed where
//! flipped[f]) prepared for winding-number queries: each polygon as a fan of triangles from its
//! first corner, projected on the plane across a fixed generic direction d (no axis, so the rays
//! of axis-aligned models do not run along their edges) and listed in a uniform grid of cells
//! (about one triangle per cell, at most 1024 a side), so a query costs the triangles of one cell
//! instead of every face. The winding number at p is the number of triangles the ray from p
//! along d leaves the shell through minus those it enters through: for points off a closed
//! shell, the same integer the generalized winding number gives.
class RayCrossings {
 public:
  RayCrossings(const Soup& soup, const std::vector<char>& flipped, const Index* faces_begin,
               const Index* faces_end);

  //! The winding number at `position`; NaN (undecided) where the ray meets an edge or a corner
  //! of a triangle (in projection, within 1e-12 relative) or the point lies on the shell.
  double at(const Point& position) const;

 private:
  struct Triangle {
    Point a, b, c;    //!< as the shell runs (counter-clockwise seen from outside)
    double z_normal;  //!< twice the projected area, signed: > 0 if the normal points to +z
  };
  std::size_t cell(double value, int axis) const;

  std::vector<Triangle> triangles_;
  double min_[2] = {0, 0}, extent_[2] = {0, 0};
  std::size_t cells_[2] = {1, 1};
  std::vector<Index> begin_;   //!< cell -> first entry in listed_ (CSR)
  std::vector<Index> listed_;  //!< triangles of each cell
};

}  // namespace meshbridge::detail
