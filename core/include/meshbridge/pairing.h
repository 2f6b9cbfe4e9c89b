// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file pairing.h
//! How the contenders of an edge bridge are paired (DESIGN section 4).

namespace meshbridge {

//! Pairing policy for edges with more than two contenders.
enum class PairingPolicy {
  //! Per singular edge, with the axis running from its smaller to its larger vertex index:
  //! 1. Contender faces are sorted by the angle of their in-face direction around the axis
  //!    (from Newell normals, so non-planar polygons work too).
  //! 2. Ties: faces within about 1e-7 rad (coincident faces) are ordered along-running sides
  //!    first, by increasing corner index, then against-running ones by decreasing corner index;
  //!    so two solids touching face to face are never paired across the zero-width gap between
  //!    them, and coincident copies of one solid nest instead of interleaving. The circle is cut
  //!    in its widest gap, so no run of ties straddles it.
  //! 3. Regions of space are labelled by joining the face sides that see each other across every
  //!    wedge of every edge (boundary edges join a face's two sides). A face whose two sides lie
  //!    in one region is a *sheet* (a fin inside a solid, a rib on a plate, any open surface).
  //! 4. Among non-sheet faces, cyclic neighbours whose wedge lies behind both (the first runs
  //!    against the axis, the next along it) are paired: solids close before sheets are used.
  //! 5. The same rule among everything still unpaired.
  //! 6. Elimination: what is left pairs in cyclic order, opposite-running sides only; the rest
  //!    stay unpaired (boundary sides, which repair may stitch after orientation).
  //! Fallback: an edge with a contender face of (near) zero area, whose in-face direction is
  //! parallel to the axis, or whose two end points coincide, uses the `combinatorial` rule.
  //! Deterministic, and independent of the order of faces except through corner-index ties.
  geometric,
  //! Opposite-running sides first, in face order; then the rest in face order.
  combinatorial,
};

}  // namespace meshbridge
