// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 6, manifold edges: no two pairs, and no pair and a boundary side, on one output edge.

#include "pipeline/grouping.h"
#include "pipeline/side_pairing.h"

namespace meshbridge::detail {

struct ManifoldEdgeCounts {
  std::size_t implicitly_stitched = 0;  //!< sides of open pairs that the output glued anyway
  std::size_t unstitched = 0;           //!< sides whose stitch was undone
  std::size_t pairs_cut = 0;            //!< sides of pairs cut (pairing's, not stitching's)
  std::size_t faces_detached = 0;       //!< faces cut loose (last resort)
  std::size_t rounds = 0;               //!< rounds that changed something
};

//! A fan that winds twice around a vertex (self-intersecting input) can put several sides of
//! one input edge onto one output edge. Repeats, until no output edge has more than two sides:
//! per crowded output edge, two opposite unpaired sides are paired (the output glues them
//! anyway); extra pairs are cut, stitched ones first, keeping one pair; a pair sharing its edge
//! with unpaired sides is cut; then `split` is recomputed from the new pairing.
ManifoldEdgeCounts make_output_edges_manifold(const Soup& soup, const GroupedSides& grouped,
                                              SidePairing& pairing, VertexSplit& split);

}  // namespace meshbridge::detail
