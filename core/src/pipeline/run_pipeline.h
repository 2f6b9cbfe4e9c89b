// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The two-phase bridged construction shared by build_bridged_mesh() and repair(): (1) group the
// sides, pair them, orient, stitch, split fans, keep output edges manifold; (2) emit the final
// indexed mesh once. One stage per file in this folder; run_pipeline.cpp tells the story.

#include "meshbridge/indexed_mesh.h"
#include "meshbridge/pairing.h"
#include "meshbridge/repair.h"

#include "pipeline/grouping.h"
#include "pipeline/side_pairing.h"
#include "working_soup.h"

#include <vector>

namespace meshbridge::detail {

struct PipelineOptions {
  PairingPolicy pairing = PairingPolicy::geometric;
  bool orient = true;
  bool cut_nonorientable = false;
  bool stitch = true;
  AmbiguousNesting nested = AmbiguousNesting::material;  //!< see orient_components()
  //! Keep the grouping and the pairing in the result (PipelineResult::grouped, ::pairing; default
  //! true). false frees them before the output mesh is emitted, so the emitted arrays take their
  //! room instead of adding to it (repair() reads only the mesh and the counts).
  bool keep_state = true;
};

//! What the pipeline did, counted in sides (polygon sides) or faces.
struct PipelineCounts {
  std::size_t sides_cut = 0;                     //!< singular-edge contenders pairing left unpaired
  std::size_t sides_cut_for_orientation = 0;     //!< pairs cut because orientation conflicts
  std::size_t sides_stitched = 0;                //!< net: stitched, implicitly stitched, unstitched
  std::size_t faces_flipped = 0;                 //!< faces reversed
  std::size_t sides_cut_to_stay_manifold = 0;    //!< always 0 (make_output_edges_manifold())
  std::size_t sides_paired_with_copies = 0;      //!< re-paired so copies of a face glue, not cut
  std::size_t edges_split_to_stay_manifold = 0;  //!< pairs given a midpoint vertex, not cut
  std::size_t faces_given_midpoints = 0;         //!< polygons given a corner by those splits
  std::size_t triangles_given_midpoints = 0;     //!< of them, triangles
  std::size_t vertices_split = 0;                //!< vertex copies added
  std::size_t nonorientable_components = 0;
  std::size_t ambiguous_nested_shells = 0;  //!< closed shells wound like their container
  std::size_t open_sides = 0;               //!< sides left unpaired: the output's boundary edges
};

struct PipelineResult {
  GroupedSides grouped;  //!< over the working soup (empty unless PipelineOptions::keep_state)
  //! Final pairing and flips of the working soup's sides and faces (empty unless
  //! PipelineOptions::keep_state)
  SidePairing pairing;
  IndexedMesh mesh;  //!< origins refer to the *input* soup
  PipelineCounts counts;
  //! Components whose Euler characteristic pairing changed (topology_changes()); first faces
  //! are the working soup's (the output's, face for face).
  std::vector<TopologyChange> topology_changes;
};

//! Runs on `working` with its sides already grouped (as from group_sides(working.soup()));
//! the grouping is moved into the result.
PipelineResult run_pipeline(const WorkingSoup& working, GroupedSides grouped,
                            const PipelineOptions& options);
//! Same, grouping the sides itself.
PipelineResult run_pipeline(const WorkingSoup& working, const PipelineOptions& options);

}  // namespace meshbridge::detail
