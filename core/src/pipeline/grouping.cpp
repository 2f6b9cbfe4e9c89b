// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/grouping.h"

#include <algorithm>

namespace meshbridge::detail {

CornerFaces::CornerFaces(const Soup& soup) {
  const std::size_t num_faces = soup.num_faces();
  const Index k = num_faces == 0 ? 0 : static_cast<Index>(soup.arity(0));
  bool uniform = true;
  for (std::size_t f = 1; f <= num_faces && uniform; ++f)
    uniform = soup.face_begin[f] - soup.face_begin[f - 1] == k;
  if (uniform) {
    arity_ = k;
  } else {
    owned_ = corner_faces(soup);
    table_ = owned_.data();
  }
}

GroupedSides group_sides(const Soup& soup) {
  GroupedSides grouped{CornerFaces(soup), EdgeBridges()};
  grouped.bridges = group_sides(soup, grouped.corner_face);
  return grouped;
}

std::vector<Index> boundary_sides(const EdgeBridges& bridges) {
  std::vector<Index> sides;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    if (bridges.num_contenders(e) == 1)
      sides.push_back(bridges.contenders[bridges.begin[e]]);
  }
  std::sort(sides.begin(), sides.end());
  return sides;
}

}  // namespace meshbridge::detail
