// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Stage 1, grouping: every polygon side of the working soup filed under its vertex pair.
// Detection uses this stage only (plus the fan and orientation labelling it shares).

#include "meshbridge/edge_bridges.h"
#include "meshbridge/soup.h"

#include "pipeline/corner_faces.h"

#include <vector>

namespace meshbridge::detail {

//! The sides of a soup grouped by vertex pair: what every later stage reads.
struct GroupedSides {
  CornerFaces corner_face;  //!< face of each corner (and of the side it starts)
  EdgeBridges bridges;      //!< the contenders of every vertex pair
};

//! Groups the sides of `soup` in O(#C). \pre `soup` passes validate_soup()
GroupedSides group_sides(const Soup& soup);

//! meshbridge::group_sides() with the corners' faces as CornerFaces.
EdgeBridges group_sides(const Soup& soup, const CornerFaces& corner_face);

//! The boundary sides (the one contender of a vertex pair), as corners in increasing order.
std::vector<Index> boundary_sides(const EdgeBridges& bridges);

//! True if side c runs from the smaller to the larger vertex of its edge.
inline bool runs_along(const Soup& soup, const CornerFaces& corner_face, Index c) {
  return soup.corner_vertices[c] < soup.corner_vertices[soup.next_corner(c, corner_face[c])];
}

}  // namespace meshbridge::detail
