// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the pipeline did to each component's topology (RepairReport::topology_changes), and to
// the polygons that a midpoint split gives a corner: counted from the pairing before the output
// is emitted.

#include "meshbridge/repair.h"

#include "pipeline/grouping.h"
#include "pipeline/side_pairing.h"

#include <vector>

namespace meshbridge::detail {

//! The output components (faces joined through `pairing.mate`) whose V - E + F differs from
//! that of the same faces of `soup`, each vertex and each vertex pair counted once. The output's
//! edges are the pairs and the unpaired sides (a pair split at its midpoint adds one edge and one
//! vertex: no change), its vertices those of `split`. O(#C + #V); when every vertex pair is a
//! boundary side or one pair and no vertex is split, nothing can change and the answer is
//! found in one pass over the vertex pairs. Each change also gets its faces, its stacked copies
//! (faces with the sides of an earlier face of it; O(F log F) over the changed components' faces)
//! and whether a side of it that orientation cut is open: `cut_for_orientation` has one entry per
//! side (1: orientation unpaired it), or is empty when orientation cut nothing.
std::vector<TopologyChange> topology_changes(const Soup& soup, const GroupedSides& grouped,
                                             const SidePairing& pairing, const VertexSplit& split,
                                             const std::vector<char>& cut_for_orientation = {});

//! The polygons given a corner by the pairs split at their midpoint (`pairing.midpoint`), and
//! how many of them are triangles.
struct MidpointFaces {
  std::size_t faces = 0;
  std::size_t triangles = 0;
};
MidpointFaces midpoint_faces(const Soup& soup, const CornerFaces& corner_face,
                             const SidePairing& pairing);

}  // namespace meshbridge::detail
