// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/run_pipeline.h"

#include "pipeline/emit.h"
#include "pipeline/fans.h"
#include "pipeline/manifold_edges.h"
#include "pipeline/orientation.h"
#include "pipeline/pairing.h"
#include "pipeline/stitching.h"
#include "pipeline/topology.h"

namespace meshbridge::detail {

namespace {

// Contenders of singular edges that pairing left unpaired.
std::size_t unpaired_singular_sides(const GroupedSides& grouped, const std::vector<Index>& mate) {
  const EdgeBridges& bridges = grouped.bridges;
  std::size_t unpaired = 0;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    if (bridges.num_contenders(e) <= 2)
      continue;
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i)
      unpaired += mate[bridges.contenders[i]] == kNoIndex ? 1 : 0;
  }
  return unpaired;
}

}  // namespace

PipelineResult run_pipeline(const WorkingSoup& working, const PipelineOptions& options) {
  return run_pipeline(working, group_sides(working.soup()), options);
}

PipelineResult run_pipeline(const WorkingSoup& working, GroupedSides grouped,
                            const PipelineOptions& options) {
  const Soup& soup = working.soup();
  PipelineResult result;
  PipelineCounts& counts = result.counts;
  SidePairing& pairing = result.pairing;

  // 1. Grouping (done by the caller): the contenders of every vertex pair.
  // 2. Pairing: two contenders make a manifold edge; singular edges pair by angular order.
  pairing.mate = pair_contenders(soup, grouped, options.pairing);
  counts.sides_cut = unpaired_singular_sides(grouped, pairing.mate);

  // 3. Orientation: faces joined through pairs run consistently (pairs that cannot are cut).
  //    The pairs as pairing made them are kept when orientation can cut one (some pair runs the
  //    same way), to tell which topology changes its cuts made.
  std::vector<Index> paired;
  if (has_inconsistent_pair(soup, pairing.mate))
    paired = pairing.mate;
  if (options.orient) {
    const OrientationCounts oriented =
        orient_consistently(soup, grouped.corner_face, options.cut_nonorientable, pairing.mate,
                            pairing.flipped, &grouped.bridges);
    counts.nonorientable_components = oriented.nonorientable_components;
    counts.sides_cut_for_orientation = oriented.sides_cut;
  } else {
    pairing.flipped.assign(soup.num_faces(), 0);
    counts.sides_cut_for_orientation = cut_inconsistent_pairs(soup, pairing.mate);
  }
  std::vector<char> cut_for_orientation;  // per side, when orientation cut any
  if (counts.sides_cut_for_orientation != 0) {
    cut_for_orientation.assign(soup.num_corners(), 0);
    for (Index c = 0; c < paired.size(); ++c)
      cut_for_orientation[c] = paired[c] != kNoIndex && pairing.mate[c] == kNoIndex ? 1 : 0;
  }
  paired = std::vector<Index>();

  // 4. Stitching: unpaired sides of one edge glued back where orientation allows; then each
  //    component turned as a whole (closed ones outward).
  pairing.stitched.assign(soup.num_corners(), 0);
  if (options.stitch)
    counts.sides_stitched = stitch(soup, grouped, pairing, options.orient);
  if (options.orient)
    counts.ambiguous_nested_shells = orient_components(soup, grouped, pairing, options.nested);

  // 5. Fans: one vertex copy per fan.  6. Manifold edges: a fan winding twice around a vertex
  //    (or both layers of a doubled sheet) can still crowd an output edge; resolving that (copies
  //    of one face glued back to back, else pairs split at their midpoint) re-splits the fans.
  VertexSplit split = split_fans(soup, grouped.corner_face, pairing.mate);
  const ManifoldEdgeCounts crowded = make_output_edges_manifold(soup, grouped, pairing, split);
  counts.sides_stitched += crowded.implicitly_stitched;
  counts.sides_stitched -= crowded.unstitched;
  counts.sides_paired_with_copies = crowded.sides_paired_with_copies;
  counts.edges_split_to_stay_manifold = crowded.edges_split_to_stay_manifold;
  // Cuts (glued again in their new fans) can leave a closed part of a component that was open:
  // orient again (fans do not depend on orientation).
  if (crowded.rounds > 0 && options.orient)
    counts.ambiguous_nested_shells = orient_components(soup, grouped, pairing, options.nested);

  // 7. Emit the output polygons once, after counting what the steps did to the topology.
  result.topology_changes = topology_changes(soup, grouped, pairing, split, cut_for_orientation);
  const MidpointFaces given = midpoint_faces(soup, grouped.corner_face, pairing);
  counts.faces_given_midpoints = given.faces;
  counts.triangles_given_midpoints = given.triangles;
  counts.vertices_split = split.vertex_origin.size() - soup.num_vertices();
  for (char f : pairing.flipped)
    counts.faces_flipped += f;
  for (Index m : pairing.mate)
    counts.open_sides += m == kNoIndex ? 1 : 0;
  if (!options.keep_state) {
    grouped = GroupedSides();
    pairing.stitched = std::vector<char>();
  }
  result.mesh = emit_mesh(working, std::move(split), pairing);
  if (!options.keep_state)
    pairing.mate = std::vector<Index>();
  if (options.keep_state)
    result.grouped = std::move(grouped);
  else
    pairing.flipped = std::vector<char>();
  return result;
}

}  // namespace meshbridge::detail
