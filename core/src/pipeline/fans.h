// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 5, fans: every vertex split into one copy per fan of the faces joined through pairs.
// Detection uses it too, on the 2-sided edges' pairing, to find pinch vertices.

#include "meshbridge/soup.h"

#include "pipeline/corner_faces.h"
#include "pipeline/side_pairing.h"

#include <vector>

namespace meshbridge::detail {

//! Splits every vertex into one copy per fan of the faces joined through `mate`. Input vertices
//! keep their index for their first fan (in corner order); copies are appended.
VertexSplit split_fans(const Soup& soup, const CornerFaces& corner_face,
                       const std::vector<Index>& mate);

//! 1 for every vertex with more than one fan of the faces joined through `mate` (what
//! split_fans() would copy), else 0: #V entries. Walks each fan once around its vertex, keeping
//! one bit per corner instead of split_fans()' #C labels.
std::vector<char> multi_fan_vertices(const Soup& soup, const CornerFaces& corner_face,
                                     const std::vector<Index>& mate);

}  // namespace meshbridge::detail
