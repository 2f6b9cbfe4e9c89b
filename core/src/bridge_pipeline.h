// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The two-phase bridged construction shared by build_bridged_mesh() and repair():
// (1) group sides, pair, orient, stitch, split fans; (2) emit the final indexed mesh once.

#include "meshbridge/edge_bridges.h"
#include "meshbridge/indexed_mesh.h"
#include "meshbridge/pairing.h"

#include "working_soup.h"

#include <vector>

namespace meshbridge::detail {

struct PipelineOptions {
  PairingPolicy pairing = PairingPolicy::geometric;
  bool orient = true;
  bool cut_nonorientable = false;
  bool stitch = true;
};

struct PipelineResult {
  std::vector<Index> corner_face;  //!< working-soup corner -> face
  EdgeBridges bridges;             //!< over the working soup
  std::vector<Index> mate;         //!< final pairing of working-soup sides
  std::vector<char> flipped;       //!< per working-soup face
  IndexedMesh mesh;                //!< origins refer to the *input* soup
  std::size_t sides_cut = 0;
  std::size_t sides_cut_for_orientation = 0;
  std::size_t sides_stitched = 0;
  std::size_t faces_flipped = 0;
  std::size_t sides_cut_to_stay_manifold = 0;
  std::size_t faces_detached = 0;
  std::size_t vertices_split = 0;
  std::size_t nonorientable_components = 0;
};

//! Runs on `working` with its sides already grouped (corner_face and bridges as from
//! corner_faces() and group_sides() of working.soup()); they are moved into the result.
PipelineResult run_pipeline(const WorkingSoup& working, std::vector<Index> corner_face,
                            EdgeBridges bridges, const PipelineOptions& options);
//! Same, grouping the sides itself.
PipelineResult run_pipeline(const WorkingSoup& working, const PipelineOptions& options);

//! Splits every vertex into one copy per fan of the faces joined through `mate`.
//! Returns the output vertex of every corner; `vertex_origin` gets the input vertex of each output
//! vertex (input vertices keep their index for their first fan; copies are appended).
std::vector<Index> split_fans(const Soup& soup, const std::vector<Index>& corner_face,
                              const std::vector<Index>& mate, std::vector<Index>& vertex_origin);

}  // namespace meshbridge::detail
