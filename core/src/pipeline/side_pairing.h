// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The state the pipeline's stages hand on after grouping (see run_pipeline.h for the order).

#include "meshbridge/soup.h"

#include <vector>

namespace meshbridge::detail {

//! Which sides are glued to which, and which faces are reversed. Pairing fills `mate`;
//! orientation fills `flipped` and may cut pairs; stitching glues more pairs (marking them
//! `stitched`); making output edges manifold exchanges partners between copies of one polygon
//! or splits pairs at their midpoint.
struct SidePairing {
  std::vector<Index> mate;     //!< #C: side paired with side c, or kNoIndex (a boundary side)
  std::vector<char> stitched;  //!< #C: 1 if c's pair was made by stitching, not by pairing
  std::vector<char> flipped;   //!< #F: 1 if the face's corner order is to be reversed
  //! #C, or empty when none: 1 if c's pair is split at its midpoint to stay manifold (its two
  //! faces get a new vertex in the middle of the edge when emitted)
  std::vector<char> midpoint;
};

//! Two paired sides c and m run the same way (their faces disagree in orientation) iff they
//! start at the same vertex.
inline bool same_way(const Soup& soup, Index c, Index m) {
  return soup.corner_vertices[c] == soup.corner_vertices[m];
}

//! Output vertices: one per fan of every input vertex.
struct VertexSplit {
  std::vector<Index> corner_vertex;  //!< #C: output vertex of each corner
  std::vector<Index> vertex_origin;  //!< #V_out: input vertex of each output vertex
};

}  // namespace meshbridge::detail
