// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file pairing.h
//! How the contenders of an edge bridge are paired (DESIGN section 4).

namespace meshbridge {

//! Pairing policy for edges with more than two contenders.
enum class PairingPolicy {
  //! Per singular edge, with the axis running from its smaller to its larger vertex index:
  //! 1. Each contender face's direction is taken *where it leaves the edge*: for a triangle its
  //!    plane; for a larger polygon the triangles its side makes with the neighbouring corners
  //!    (so a bent polygon sorts like its triangulation there, not by its average normal).
  //!    Faces flat against the edge (zero or near-zero area there: they leave the edge's line by
  //!    at most 1e-7 of their size) take no part in the order; they are paired after the rest.
  //! 2. The faces are sorted by the angle of that direction around the axis. Ties (faces within
  //!    about 1e-7 rad, such as coincident faces) are ordered along-running sides first, then
  //!    against-running ones, each by face key (sorted vertex list, then the polygon from its
  //!    smallest vertex); copies of one face by increasing corner index if along-running, by
  //!    decreasing if against; so two solids touching face to face are never paired across the
  //!    zero-width gap between them, and coincident copies nest instead of interleaving. The
  //!    circle is cut in its widest gap, so no run of ties straddles it.
  //! 3. Regions of space are labelled by joining the face sides that see each other across every
  //!    wedge of every edge (boundary edges join a face's two sides). Each region is material or
  //!    void by the area-weighted vote of the faces around it (the back of a face says material,
  //!    the front void). A face whose two sides lie in one region, or in two regions of the same
  //!    kind, separates nothing: it is a *sheet* (a rib on a plate, any open surface, a fin
  //!    inside a solid, and a membrane with material on both sides, whatever its winding).
  //! 4. Among non-sheet faces, cyclic neighbours whose wedge lies behind both (the first runs
  //!    against the axis, the next along it) are paired: solids close before sheets are used.
  //! 5. The same rule among everything still unpaired.
  //! 6. Elimination: what is left pairs in cyclic order, opposite-running sides only, then the
  //!    faces without a direction (step 1) in face-key order; the rest stay unpaired (boundary
  //!    sides, which repair may stitch after orientation).
  //! An edge whose two end points coincide, or with fewer than two directed faces, pairs all its
  //! contenders by elimination in face-key order.
  //! Deterministic, and independent of the order of faces and of where polygons start (only
  //! copies of one polygon are told apart by corner index, and they are interchangeable).
  geometric,
  //! In corner (file) order, each unpaired side takes the first later unpaired side that runs
  //! the other way; sides left without such a partner stay unpaired (boundary sides, which
  //! repair may stitch after orientation). Uses no geometry; depends on face order.
  combinatorial,
};

//! What repair makes of a closed shell nested inside another closed shell when both are
//! consistently wound as written and the same way (outward inside outward, or inward inside
//! inward): an insert of an assembly, or a cavity wound the wrong way. Either way it is counted
//! as ambiguous (DESIGN 8a, intent).
enum class AmbiguousNesting {
  material,  //!< as written: the inner shell runs like its container (solid material, an insert)
  cavity,    //!< even-odd nesting: the inner shell is turned against its container (a void)
};

}  // namespace meshbridge
