// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Part of stage 3, orientation: a component that only the pairs made at singular edges make
// non-orientable keeps the input's own edges; those pairs yield.

#include "meshbridge/edge_bridges.h"
#include "meshbridge/soup.h"

#include "pipeline/corner_faces.h"
#include "pipeline/parity_union_find.h"

#include <vector>

namespace meshbridge::detail {

//! Orients the faces `faces` (one component of the faces joined through `mate`, where some pair
//! runs against the rest) through their pairs at two-sided edges (the input's own edges, which
//! pairing never chose) into *blocks*, then turns whole blocks so that the pairs made at singular
//! edges (more than two contenders) agree with them where they can:
//! 1. the singular pairs that join the same two blocks with the same relative orientation form a
//!    group; groups are admitted largest first (ties: the one whose first edge comes first in
//!    `bridges`, then by face key), a group that contradicts what is admitted is left out;
//! 2. single blocks (numbered as the edges, by vertex pair, first meet them) are turned while a
//!    turn leaves fewer sides open at the component's singular edges (at most min(along, against)
//!    pairs fit on an edge, so |along - against| sides stay open there), a few passes;
//! 3. the singular pairs that then run the same way are cut (a pair within one block that runs
//!    with it always is). Stitching can glue their sides again where orientation allows (to the
//!    side left open at an edge with an odd number of sides, say).
//! The result does not depend on the order of faces.
//!
//! On success sets `flipped` for `faces` (relative to the component, not yet turned as a whole)
//! and returns the sides cut (2 per pair). Returns kNoIndex and changes neither `mate` nor
//! `flipped` if the two-sided pairs among `faces` conflict already: the input is non-orientable
//! there itself. `edge_of_side` holds each side's edge in `bridges`; `blocks` is scratch over all
//! faces, each component using only its own faces.
Index yield_singular_pairs(const Soup& soup, const CornerFaces& corner_face,
                           const EdgeBridges& bridges, const std::vector<Index>& edge_of_side,
                           const std::vector<Index>& faces, ParityUnionFind& blocks,
                           std::vector<Index>& mate, std::vector<char>& flipped);

//! The edge of every side in `bridges` (#C entries).
std::vector<Index> edge_of_sides(const Soup& soup, const EdgeBridges& bridges);

}  // namespace meshbridge::detail
