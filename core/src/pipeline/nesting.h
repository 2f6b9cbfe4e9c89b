// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Nesting of closed shells: which shells lie inside which (used by orientation).

#include "meshbridge/soup.h"

#include <vector>

namespace meshbridge::detail {

//! The nesting depth of every closed shell: the number of other shells that contain it (0 for
//! an outer boundary, 1 for a cavity, 2 for an island inside a cavity, ...).
//!
//! \param flipped #F: faces that run reversed (as SidePairing::flipped): a shell is consistently
//!        oriented once these are taken into account.
//! \param face_shell #F: shell of each face in 0..num_shells-1, or kNoIndex for faces of no
//!        closed shell (they neither contain nor are contained).
//! The result depends on positions only, not on vertex numbering or on which way each face is
//! stored, so repairing the output again gives the same depths.
//! Shell T contains shell S if S's bounding box lies within T's and points of S are inside T:
//! at the centroids of up to 8 faces spread over S, the generalized winding number of T's faces
//! (sum of signed solid angles / 4 pi, either orientation of T) is within 0.1 of a nonzero
//! integer at every point where it is decided, and decided at one at least. A point on T
//! (shells that touch or coincide) is undecided; any other value (outside, or S crossing T)
//! means S is not inside T.
//! Candidates come from a uniform grid over the shells' boxes (about one cell per shell), so
//! shells that do not nest cost O(#F + #shells); each candidate pair costs O(faces of T), except
//! that a T of 256 faces or more that contains some box answers by ray crossings (RayCrossings:
//! the integer winding number), at about the triangles of one grid cell per point, and by the
//! solid angles only where its ray meets an edge or a corner: many shells inside one large shell
//! (cavities in a block, the cells of an inside-out grid) no longer cost #shells x #F.
std::vector<Index> nesting_depths(const Soup& soup, const std::vector<char>& flipped,
                                  const std::vector<Index>& face_shell, std::size_t num_shells);

//! The nesting of closed shells: depth (as nesting_depths()) and the innermost shell that
//! contains each one (its parent: the container of largest depth), kNoIndex at depth 0.
struct Nesting {
  std::vector<Index> depth;   //!< #shells
  std::vector<Index> parent;  //!< #shells: innermost container, or kNoIndex
};

//! nesting_depths() with each shell's parent; same parameters, same cost.
Nesting shell_nesting(const Soup& soup, const std::vector<char>& flipped,
                      const std::vector<Index>& face_shell, std::size_t num_shells);

//! Generalized winding number (Jacobson et al. 2013) of the given faces of `soup`, face f
//! reversed where flipped[f], at `p`; NaN if `p` lies on one of them (within rounding).
double winding_number(const Soup& soup, const std::vector<char>& flipped, const Index* faces_begin,
                      const Index* faces_end, const Point& p);

}  // namespace meshbridge::detail
