// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 2, pairing: the contenders of every edge bridge in pairs (DESIGN section 4).

#include "meshbridge/pairing.h"

#include "pipeline/grouping.h"

#include <vector>

namespace meshbridge::detail {

//! The pairing of every side: `mate[c]` is the side paired with side c, or kNoIndex.
//!
//! - 1 contender: unpaired (boundary side).
//! - 2 contenders: paired with each other, whichever way they run (orientation decides later
//!   whether the pair is kept).
//! - more: by `policy`. Pairs made here always run in opposite directions; what cannot be paired
//!   that way stays unpaired ("cut"), for stitching to glue back after orientation.
//!
//! Geometric policy, per singular edge with axis from its smaller to its larger vertex:
//! contender faces are sorted by the angle of their in-face direction around the axis (Newell
//! normals); faces at the same angle (coincident, within about 1e-7 rad) are ordered
//! along-running first by increasing corner, then against-running by decreasing corner, so two
//! solids touching face to face are never paired across the empty zero-width gap and coincident
//! copies nest (see PairingPolicy::geometric). Regions of space are labelled by joining the face
//! sides that see each other across every wedge of every edge; a face whose two sides lie in one
//! region is a sheet. Then: (a) among non-sheet faces, cyclic neighbours whose wedge lies behind
//! both are paired; (b) the same among everything still unpaired; (c) elimination pairs what is
//! left, opposite-running sides only, in cyclic order. An edge with a contender face of zero area,
//! or with coincident end points, falls back to the combinatorial rule.
//!
//! Combinatorial policy: in corner order, each unpaired side takes the first later unpaired side
//! that runs the other way.
std::vector<Index> pair_contenders(const Soup& soup, const GroupedSides& grouped,
                                   PairingPolicy policy);

}  // namespace meshbridge::detail
