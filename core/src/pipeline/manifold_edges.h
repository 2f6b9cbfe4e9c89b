// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 6, manifold edges: no two pairs, and no pair and a boundary side, on one output edge
// (copies of one face glued back to back where they can be, else pairs cut).

#include "pipeline/grouping.h"
#include "pipeline/side_pairing.h"

namespace meshbridge::detail {

struct ManifoldEdgeCounts {
  std::size_t implicitly_stitched = 0;  //!< sides of open pairs that the output glued anyway
  std::size_t unstitched = 0;           //!< sides whose stitch was undone
  std::size_t pairs_cut = 0;            //!< sides of pairs cut and glued again in their new fans
  std::size_t edges_split_to_stay_manifold =
      0;  //!< pairs split at their midpoint (one new vertex each)
  std::size_t sides_paired_with_copies = 0;  //!< sides given a new mate by exchanges (4 each)
  std::size_t rounds = 0;  //!< rounds of exchanges or cuts (each changed at least one pair)
};

//! Two pairs of one input edge can land on one output edge: a fan that winds twice around a
//! vertex (self-intersecting input), or both layers of a sheet given once per orientation where
//! an edge of the sheet joins two of its rim vertices (each rim vertex has one fan, where the
//! layers fold into each other, so the two layers' sides share both ends). In rounds until no
//! output edge is shared:
//! - *copies glue back to back*: on such an output edge, two sides of two copies of one polygon
//!   (the same vertex cycle, either way round) that run opposite ways as written, neither yet
//!   paired with a copy of its own polygon, become a pair, and their former mates another. No
//!   side is unpaired, so no boundary edge is made (a slicer sees none there either); copies
//!   glued so on every side close into a pillow of no volume, as a slicer pairs them;
//! - only in a round where none exists: per crowded output edge, extra pairs are cut (stitched
//!   ones first), keeping one pair; a pair sharing its edge with unpaired sides is cut. The fans
//!   split anew, and sides that then share an output edge are glued again (three tetrahedra on
//!   one edge come apart, each closed);
//! - if that leaves open any side that was paired, everything restarts from the pairing as it
//!   came, and extra pairs are *split at their midpoint* instead of cut: a split pair stays
//!   paired, and emit_mesh() gives its two faces a new vertex in the middle of the edge
//!   (`pairing.midpoint`), so the two sheets touch without sharing an edge. So no side that was
//!   paired is ever left open (DESIGN 8a, closed stays closed).
//! `split` is recomputed after each round. Each round either adds a pair of copies keeping the
//! number of pairs, or takes pairs off the crowded edges, so there are at most 3 x #pairs + 1
//! rounds. Then two
//! opposite unpaired sides left on one output edge are paired (the output glues them anyway;
//! their fans are already one). Faces are never detached.
//! \throw std::logic_error if an output edge still holds unpaired sides running the same way,
//! or three of them: impossible while every pair runs opposite ways (see the .cpp).
ManifoldEdgeCounts make_output_edges_manifold(const Soup& soup, const GroupedSides& grouped,
                                              SidePairing& pairing, VertexSplit& split);

}  // namespace meshbridge::detail
