// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/stitching.h"

#include "pipeline/angular_order.h"
#include "pipeline/parity_union_find.h"

#include <algorithm>

namespace meshbridge::detail {

std::size_t stitch(const Soup& soup, const GroupedSides& grouped, SidePairing& pairing,
                   bool may_flip) {
  const CornerFaces& corner_face = grouped.corner_face;
  const EdgeBridges& bridges = grouped.bridges;
  std::vector<Index>& mate = pairing.mate;
  std::vector<char>& flipped = pairing.flipped;
  // Only edges with two or more unpaired sides can be stitched.
  std::vector<std::size_t> candidates;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    if (bridges.num_contenders(e) < 2)
      continue;
    Index open_sides = 0;
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i) {
      open_sides += mate[bridges.contenders[i]] == kNoIndex ? 1 : 0;
    }
    if (open_sides >= 2)
      candidates.push_back(e);
  }
  if (candidates.empty())
    return 0;

  const std::size_t num_faces = soup.num_faces();
  ParityUnionFind components(num_faces);
  char unused = 0;
  for (Index c = 0; c < mate.size(); ++c) {
    const Index m = mate[c];
    if (m == kNoIndex || m < c)
      continue;
    const Index a = components.find(corner_face[c], unused);
    const Index b = components.find(corner_face[m], unused);
    if (a != b)
      components.unite_roots(std::min(a, b), std::max(a, b), false);
  }
  std::size_t stitched = 0;
  std::vector<Index> open, key_s, key_t;
  for (std::size_t e : candidates) {
    open.clear();
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i) {
      if (mate[bridges.contenders[i]] == kNoIndex)
        open.push_back(bridges.contenders[i]);
    }
    // Angular order, so that what is glued does not depend on the order of faces.
    sort_by_angle(soup, grouped, e, open);
    for (std::size_t i = 0; i < open.size(); ++i) {
      const Index s = open[i];
      if (mate[s] != kNoIndex)
        continue;
      for (std::size_t j = i + 1; j < open.size(); ++j) {
        const Index t = open[j];
        if (mate[t] != kNoIndex)
          continue;
        char flip_s = 0, flip_t = 0;
        const Index root_s = components.find(corner_face[s], flip_s);
        const Index root_t = components.find(corner_face[t], flip_t);
        const bool along_s = runs_along(soup, corner_face, s) != (flipped[corner_face[s]] ^ flip_s);
        const bool along_t = runs_along(soup, corner_face, t) != (flipped[corner_face[t]] ^ flip_t);
        // Sides running the same way need one component reversed: never within a component,
        // and across components only when faces may be flipped (orientation on).
        if (along_s == along_t && (root_s == root_t || !may_flip))
          continue;
        if (root_s != root_t) {
          // Keep the larger component as it is; on a tie the one whose face at this edge has the
          // smaller face key (not the smaller root, which depends on face order).
          bool keep_s = components.size(root_s) > components.size(root_t);
          if (components.size(root_s) == components.size(root_t)) {
            face_key(soup, corner_face[s], key_s);
            face_key(soup, corner_face[t], key_t);
            keep_s = key_s != key_t ? key_s < key_t : root_s < root_t;
          }
          const Index keep = keep_s ? root_s : root_t;
          const Index other = keep_s ? root_t : root_s;
          components.unite_roots(keep, other, along_s == along_t);
        }
        mate[s] = t;
        mate[t] = s;
        pairing.stitched[s] = pairing.stitched[t] = 1;
        stitched += 2;
        break;
      }
    }
  }
  for (Index f = 0; f < num_faces; ++f) {
    char flip = 0;
    components.find(f, flip);
    flipped[f] ^= flip;
  }
  return stitched;
}

}  // namespace meshbridge::detail
