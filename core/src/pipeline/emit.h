// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 7, emit: the output polygons, on split vertices, reversed where flipped.

#include "meshbridge/indexed_mesh.h"

#include "pipeline/side_pairing.h"
#include "working_soup.h"

#include <vector>

namespace meshbridge::detail {

//! The working faces in order, each corner on its output vertex, reversed where
//! `pairing.flipped` (reversal keeps the first corner); origins refer to the *input* soup of
//! `working`. A pair marked in `pairing.midpoint` (make_output_edges_manifold()) gets one new
//! vertex at the middle of its edge, appended after the split vertices with origin kNoIndex and
//! inserted as a corner into both faces of the pair (the corner's origin is the corner that
//! starts the side, as a T-junction split's); `pairing.mate` is read only for those.
IndexedMesh emit_mesh(const WorkingSoup& working, VertexSplit split, const SidePairing& pairing);

}  // namespace meshbridge::detail
