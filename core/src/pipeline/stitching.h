// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 4, stitching: unpaired sides of one edge glued back where orientation allows.

#include "pipeline/grouping.h"
#include "pipeline/side_pairing.h"

namespace meshbridge::detail {

//! Glues unpaired sides of one edge back in pairs (in the edge's angular order) where the result
//! stays consistently oriented, reversing a whole (smaller) component when that makes two sides
//! run opposite ways and `may_flip` (false with orientation off: then only sides that already
//! run opposite ways are glued, and no face is reversed). Marks the new pairs in
//! `pairing.stitched` (sized #C by the caller). Returns the number of sides stitched.
std::size_t stitch(const Soup& soup, const GroupedSides& grouped, SidePairing& pairing,
                   bool may_flip = true);

}  // namespace meshbridge::detail
