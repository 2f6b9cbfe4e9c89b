// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 7, emit: the output polygons, on split vertices, reversed where flipped.

#include "meshbridge/indexed_mesh.h"

#include "pipeline/side_pairing.h"
#include "working_soup.h"

#include <vector>

namespace meshbridge::detail {

//! The working faces in order, each corner on its output vertex, reversed where `flipped`
//! (reversal keeps the first corner); origins refer to the *input* soup of `working`.
IndexedMesh emit_mesh(const WorkingSoup& working, VertexSplit split,
                      const std::vector<char>& flipped);

}  // namespace meshbridge::detail
