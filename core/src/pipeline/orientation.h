// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 3, orientation: faces connected through paired sides made consistent (before
// stitching), then each component turned as a whole (after stitching).

#include "meshbridge/edge_bridges.h"
#include "meshbridge/pairing.h"
#include "meshbridge/soup.h"

#include "pipeline/grouping.h"
#include "pipeline/side_pairing.h"

#include <vector>

namespace meshbridge::detail {

struct OrientationCounts {
  std::size_t nonorientable_components = 0;
  std::size_t sides_cut = 0;  //!< sides unpaired because their pair could not be made consistent
};

//! Breadth-first over the faces connected through `mate`, choosing per face whether to reverse
//! it (`flipped`) so that every pair runs in opposite directions. Where that is impossible:
//! - without `cut_nonorientable`, given the `bridges` `mate` pairs, and the component's faces
//!   orient consistently through their two-sided edges (it is the pairs made at singular edges
//!   that conflict): those pairs yield (yield_singular_pairs()), their sides are counted in
//!   `sides_cut`, and the component is not counted as non-orientable (the input is not);
//! - otherwise the component is non-orientable: with `cut_nonorientable` its conflicting pairs
//!   (the ones the search meets after the faces are fixed) are cut and its flips kept; without,
//!   its faces keep their direction and every same-running pair of it is cut.
//! `flipped` has one entry per face.
OrientationCounts orient_consistently(const Soup& soup, const CornerFaces& corner_face,
                                      bool cut_nonorientable, std::vector<Index>& mate,
                                      std::vector<char>& flipped,
                                      const EdgeBridges* bridges = nullptr);

//! Without orientation: every pair whose sides run the same way is cut.
std::size_t cut_inconsistent_pairs(const Soup& soup, std::vector<Index>& mate);

//! True if some pair's sides run the same way (start at the same vertex).
bool has_inconsistent_pair(const Soup& soup, const std::vector<Index>& mate);

//! Reverses whole components (faces joined through `pairing.mate`):
//! - closed shells with a volume by their nesting (shell_nesting()) and their own winding
//!   (DESIGN 8a, intent): an outermost shell faces outward; a shell inside another runs against
//!   its container (a cavity toward the void, an island in a cavity outward again), except that
//!   a shell consistently wound as written the same way as its consistently wound container (an
//!   insert, or a cavity wound the wrong way) is *ambiguous*: counted, and with
//!   AmbiguousNesting::material kept running like its container (as written), with
//!   AmbiguousNesting::cavity turned against it. Only relative windings count, so reversing every
//!   face of the input gives the same result;
//! - open components, and closed ones of no volume (|volume| <= 1e-9 times the sum of its terms'
//!   magnitudes, or within a bound on its rounding error: two faces glued back to back, a
//!   zero-area sliver pair), on their best evidence: their volume when capping their holes could
//!   not change its sign and it is far above its rounding error, otherwise the area-weighted
//!   majority of their faces' windings as given (see orientation.cpp). Rounding noise never
//!   decides, so repairing the output again reverses nothing.
//! Returns the number of ambiguous shells.
std::size_t orient_components(const Soup& soup, const GroupedSides& grouped, SidePairing& pairing,
                              AmbiguousNesting nested = AmbiguousNesting::material);

}  // namespace meshbridge::detail
