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
//! - more: by `policy` (the rules are stated in meshbridge/pairing.h, PairingPolicy). Pairs made
//!   here always run in opposite directions; what cannot be paired that way stays unpaired
//!   ("cut"), for stitching to glue back after orientation.
//!
//! Geometric policy, in the order the code runs: the angular order of every singular edge
//! (angular_order.h: local directions, flat faces set apart, ties by face key); regions of space
//! joined across every wedge, each voted material or void by the area of the faces around it;
//! sheets (same region, or same kind, on both sides: ribs, fins, membranes); then per edge
//! (a) non-sheet cyclic neighbours with the wedge behind both (in a component that encloses a
//! negative volume as written, in front of both: it is read as if reversed, so reversing every
//! face of the input pairs the same sides), (b) the same among the rest,
//! (c) elimination of what is left, opposite-running only, the flat faces last.
//!
//! These pairs are final except where two of them would share an output edge: stage 6
//! (manifold_edges.h) then glues copies of one polygon back to back, or cuts pairs.
std::vector<Index> pair_contenders(const Soup& soup, const GroupedSides& grouped,
                                   PairingPolicy policy);

}  // namespace meshbridge::detail
