// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/topology.h"

namespace meshbridge::detail {

MidpointFaces midpoint_faces(const Soup& soup, const CornerFaces& corner_face,
                             const SidePairing& pairing) {
  MidpointFaces counted;
  Index last = kNoIndex;  // a polygon's corners are consecutive
  for (Index c = 0; c < pairing.midpoint.size(); ++c) {
    if (!pairing.midpoint[c] || corner_face[c] == last)
      continue;
    last = corner_face[c];
    ++counted.faces;
    counted.triangles += soup.face_begin[last + 1] - soup.face_begin[last] == 3 ? 1 : 0;
  }
  return counted;
}

}  // namespace meshbridge::detail
