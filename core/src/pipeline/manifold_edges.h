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
  std::size_t rounds = 0;               //!< rounds of cuts (each cut at least one pair)
};

//! A fan that winds twice around a vertex (self-intersecting input) can put several sides of
//! one input edge onto one output edge. First, in rounds until none is needed: per crowded
//! output edge, extra pairs are cut (stitched ones first), keeping one pair; a pair sharing its
//! edge with unpaired sides is cut; `split` is recomputed. At most #pairs + 1 rounds: each cuts
//! a pair and none is made. Then two opposite unpaired sides left on one output edge are paired
//! (the output glues them anyway; their fans are already one). Faces are never detached.
//! \throw std::logic_error if an output edge still holds unpaired sides running the same way,
//! or three of them: impossible while every pair runs opposite ways (see the .cpp).
ManifoldEdgeCounts make_output_edges_manifold(const Soup& soup, const GroupedSides& grouped,
                                              SidePairing& pairing, VertexSplit& split);

}  // namespace meshbridge::detail
