// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the pipeline did to the polygons that a midpoint split gives a corner: counted from the
// pairing before the output is emitted.

#include "pipeline/corner_faces.h"
#include "pipeline/side_pairing.h"

#include <vector>

namespace meshbridge::detail {

//! The polygons given a corner by the pairs split at their midpoint (`pairing.midpoint`), and
//! how many of them are triangles.
struct MidpointFaces {
  std::size_t faces = 0;
  std::size_t triangles = 0;
};
MidpointFaces midpoint_faces(const Soup& soup, const CornerFaces& corner_face,
                             const SidePairing& pairing);

}  // namespace meshbridge::detail
