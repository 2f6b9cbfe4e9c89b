// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file repair.h
//! Lossless manifold repair: every input face is kept, every output edge is manifold.

#include "meshbridge/close_gaps.h"
#include "meshbridge/defect_report.h"
#include "meshbridge/fill_holes.h"
#include "meshbridge/indexed_mesh.h"
#include "meshbridge/pairing.h"
#include "meshbridge/progress.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <vector>

namespace meshbridge {

//! What repair may do. Defaults give the full repair; the cleanup options are off by default.
struct RepairOptions {
  //! Gap closing before pairing (welding near vertices, splitting T-junction cracks). Default on,
  //! with the automatic tolerance of default_weld_tolerance(); `close_gaps.tolerance = 0` is off.
  CloseGapsOptions close_gaps;
  PairingPolicy pairing = PairingPolicy::geometric;  //!< how contenders of a singular edge pair up
  bool orient = true;  //!< orient orientable components consistently, closed ones outward
  //! Also orient non-orientable components: their faces take the orientation of a breadth-first
  //! spanning tree over the pairs, and every pair that disagrees with it is cut (a valid cut,
  //! not necessarily the fewest edges). Off: a component that only the pairs made at singular
  //! edges make non-orientable (its faces orient consistently through the input's own two-sided
  //! edges) keeps those edges, and singular pairs yield, chosen greedily (the largest groups of
  //! singular pairs that agree are kept first: not necessarily the fewest; counted in
  //! sides_cut_for_orientation; stitching may glue their sides again); any other such component
  //! keeps its faces' directions and every edge whose two faces run the same way is cut (a
  //! valid cut too, not necessarily the fewest).
  bool cut_nonorientable = false;
  bool stitch = true;  //!< glue boundary sides on one vertex pair back when that stays manifold
  //! A closed shell inside another, both consistently wound the same way as written (an insert,
  //! or a cavity wound the wrong way): kept as written (material, default) or turned into a
  //! cavity (even-odd nesting). Counted either way in RepairReport::ambiguous_nested_shells.
  AmbiguousNesting nested_shells = AmbiguousNesting::material;
  bool remove_duplicate_faces = false;  //!< drop polygons whose vertex set an earlier one has
  //! drop polygons that repeat a vertex index (DefectReport::degenerate_faces: not keyhole
  //! polygons, which are cut into triangles with their holes open); default false
  bool remove_degenerate_faces = false;
  //! drop polygons of (near) zero area (DefectReport::zero_area_faces: slivers and needles
  //! whose corners are distinct but on one line or nearly at one point); default false
  bool remove_zero_area_faces = false;
  bool remove_isolated_vertices = false;  //!< drop vertices that no kept polygon uses
  //! Fill RepairReport::before and ::after with full detection reports (two detection passes,
  //! about a third of the time on defective input). Off: both stay empty and the counts that
  //! come from them (components, boundary edges before/after) are 0; everything repair itself
  //! did is still counted. The cleanup options need detection and turn it on.
  bool detect_before_after = true;
  //! Hole filling after the manifold repair, on the repaired (manifold, oriented) mesh, so it
  //! cannot create a singular edge: boundary loops of at most `fill_holes.max_edges` edges are
  //! closed with new triangles (see fill_holes()). Default off (`max_edges` 0);
  //! kDefaultFillHolesMaxEdges (32) is the suggested value.
  FillHolesOptions fill_holes;
  //! Told when the stages group, pair and detect start and end (default empty: not called).
  ProgressCallback progress;
};

//! A component of the repaired mesh whose Euler characteristic is not that of the same faces in
//! the input (RepairReport::topology_changes).
struct TopologyChange {
  Index first_face = 0;        //!< the component's first face in the output
  long long euler_before = 0;  //!< V - E + F of its faces in the input, every edge counted once
  long long euler_after = 0;   //!< V - E + F of the component in the output
  std::size_t faces = 0;       //!< the component's faces (output and input alike)
  //! Of `faces`, stacked copies: polygons with the same sides as an earlier face of the
  //! component (the same corners, either way round). In the input each counts as a face of its
  //! own on edges and vertices it adds nothing to, so `euler_before` - `stacked_copies` is V - E
  //! + F with every face counted once (a closed hull written 3 times over: 2 + 2F, where F is
  //! one layer's faces); pairing makes each copy a face of the output's surface.
  std::size_t stacked_copies = 0;
  //! Some side of the component that orientation cut (RepairReport::sides_cut_for_orientation)
  //! is still open in the output: the change is (at least partly) that cut's, not pairing's (a
  //! Moebius strip cut open: 0 -> 1). false: pairing alone made it (pairs chosen at singular
  //! edges, contenders left unpaired, a pinch vertex split).
  bool cut_for_orientation = false;
};

//! What repair changed. Every count is exact.
struct RepairReport {
  std::size_t faces_in = 0;              //!< polygons in the input soup
  std::size_t faces_out = 0;             //!< polygons in the output (with holes.faces_added)
  std::size_t faces_set_aside = 0;       //!< degenerate, < 3 distinct corners (listed in `before`)
  std::size_t faces_split = 0;           //!< pinched polygons split into simple ones
  std::size_t faces_added_by_split = 0;  //!< extra polygons those splits made
  //! Keyhole polygons (a polygon that runs a -> b and later b -> a: an outline and holes joined
  //! by slits) cut into triangles as one polygon with holes, so that the holes stay open and no
  //! triangle overlaps another; each is also counted in faces_split, its triangles after the
  //! first in faces_added_by_split (DefectReport::keyhole_polygons_triangulated).
  std::size_t keyhole_polygons_triangulated = 0;
  //! Keyhole slits of other pinched polygons set aside (DefectReport::slits_set_aside): a slit
  //! to a loop that is no hole of the outline; the polygon keeps its loops, the two-corner piece
  //! between is no face.
  std::size_t slits_set_aside = 0;
  std::size_t duplicate_faces_removed = 0;    //!< by `remove_duplicate_faces`
  std::size_t degenerate_faces_removed = 0;   //!< by `remove_degenerate_faces`
  std::size_t zero_area_faces_removed = 0;    //!< by `remove_zero_area_faces`
  std::size_t isolated_vertices_removed = 0;  //!< by `remove_isolated_vertices`
  std::size_t vertices_in = 0;
  std::size_t vertices_out = 0;
  std::size_t vertices_split = 0;  //!< extra vertex copies made (one per extra fan)
  std::size_t sides_cut = 0;       //!< contenders of singular edges left unpaired by pairing
  std::size_t sides_cut_for_orientation = 0;  //!< sides unpaired because orientation conflicts
  std::size_t sides_stitched = 0;             //!< unpaired sides glued back in pairs (counts sides)
  std::size_t faces_flipped = 0;              //!< polygons whose corner order was reversed
  //! Sides left unpaired because their fan wound twice around a vertex, putting two pairs on one
  //! output edge. Always 0 now (DESIGN 8a, closed stays closed): such pairs are cut only where
  //! their sides are glued again in the new fans, and otherwise split at their midpoint
  //! (`edges_split_to_stay_manifold`). Kept so reports keep their fields.
  std::size_t sides_cut_to_stay_manifold = 0;
  //! Sides given another mate instead of being cut to stay manifold: where two pairs would share
  //! one output edge and the faces of two of those sides are copies of one polygon (a face given
  //! twice, either way round, as in a sheet written once per orientation), those two are glued
  //! back to back and their former mates glued to each other (4 sides per exchange). Nothing is
  //! unpaired, so no boundary edge is made.
  std::size_t sides_paired_with_copies = 0;
  //! Pairs split at their midpoint instead of cut to stay manifold (DESIGN 8a, closed stays
  //! closed): where two pairs, or a pair and an unpaired side, would share one output edge (the
  //! umbrella of a vertex passes the same neighbour twice), the pair's two faces get a new vertex
  //! in the middle of the edge, so the sheets touch without sharing an edge. Nothing is unpaired.
  //! Each adds one vertex (its IndexedMesh::vertex_origin is kNoIndex: no input vertex) and one
  //! corner to each of the two faces.
  std::size_t edges_split_to_stay_manifold = 0;
  //! Polygons given a corner by those midpoint splits (each counted once, however many it got),
  //! and how many of them were triangles (no longer triangles in the output: one midpoint makes
  //! a quad). A split pair's two faces usually get one corner each: 2 per edge.
  std::size_t faces_given_midpoints = 0;
  std::size_t triangles_given_midpoints = 0;
  std::size_t components_before = 0;  //!< as the user sees the input (through all contenders)
  std::size_t components_after = 0;
  std::size_t boundary_edges_before = 0;
  std::size_t boundary_edges_after = 0;
  //! Components that orientation found non-orientable (after pairing, before any cut): with
  //! `cut_nonorientable` they were oriented by cutting, otherwise left as they were. Without
  //! `cut_nonorientable`, components made non-orientable only by pairs at singular edges are not
  //! counted: those pairs yield (see RepairOptions::cut_nonorientable).
  std::size_t nonorientable_after_pairing = 0;
  //! Closed shells nested in a closed shell and wound like it as written (see
  //! RepairOptions::nested_shells): ambiguous between an insert and a wrongly wound cavity.
  std::size_t ambiguous_nested_shells = 0;
  //! How the ambiguous nested shells were taken (RepairOptions::nested_shells): kept as written
  //! (material, an insert) or reversed (cavity, a void; their faces are in `faces_flipped`).
  //! Not in the JSON report, whose reader knows the option it passed.
  AmbiguousNesting nested_shells = AmbiguousNesting::material;
  //! Components of the output (before hole filling) whose Euler characteristic V - E + F differs
  //! from that of the same faces as pairing got them (after gap closing, a keyhole polygon as
  //! its triangles), where every vertex and every edge counts once, a singular edge too: pairing
  //! that joins two sheets at a singular edge into a handle (a shell of Euler characteristic 2
  //! becomes a torus, 0), sides left unpaired within one component, a pinch vertex split within
  //! one component; or sides that orientation cut open within one component (a Moebius strip
  //! cut open: 0 -> 1; TopologyChange::cut_for_orientation). Components pairing separated keep
  //! theirs (two cubes on one edge: 2 and 2), and so does a component holding stacked face
  //! copies whose value with every face counted once is its output's (a sheet written twice,
  //! glued back to back). In the order of their first faces; the JSON report
  //! gives the count, `components_topology_changed`, and of them those with a cut for
  //! orientation, `components_topology_changed_by_cuts_for_orientation`, and of the others
  //! those holding stacked face copies, `components_topology_changed_by_pairing_stacked_copies`
  //! (the text report's three lines).
  std::vector<TopologyChange> topology_changes;
  CloseGapsReport gaps;   //!< what gap closing did before pairing
  FillHolesReport holes;  //!< what hole filling did after pairing (all 0 when off)
  DefectReport before;    //!< detection on the input (before gap closing)
  DefectReport after;     //!< detection on the result (holes filled): no singular edge or vertex
};

//! The topology changes of `report` where orientation cut sides open
//! (TopologyChange::cut_for_orientation): the JSON's
//! `components_topology_changed_by_cuts_for_orientation`.
inline std::size_t components_topology_changed_by_cuts_for_orientation(const RepairReport& report) {
  std::size_t count = 0;
  for (const TopologyChange& change : report.topology_changes)
    count += change.cut_for_orientation ? 1 : 0;
  return count;
}

//! The other topology changes of `report` in components that hold stacked face copies
//! (TopologyChange::stacked_copies, no cut for orientation): the JSON's
//! `components_topology_changed_by_pairing_stacked_copies`.
inline std::size_t components_topology_changed_by_pairing_stacked_copies(
    const RepairReport& report) {
  std::size_t count = 0;
  for (const TopologyChange& change : report.topology_changes)
    count += !change.cut_for_orientation && change.stacked_copies != 0 ? 1 : 0;
  return count;
}

struct RepairResult {
  IndexedMesh mesh;
  RepairReport report;
};

//! Repairs `soup` into a combinatorial 2-manifold that keeps every face; with
//! `options.fill_holes`, then closes its small holes with new triangles, appended after the
//! repaired faces and marked kNoIndex in `face_origin` and `corner_origin`.
//! \pre `soup` passes validate_soup() \throw InvalidSoupError naming the offending element
//! \throw std::runtime_error if hole filling is asked for in a build without CGAL
RepairResult repair(const Soup& soup, const RepairOptions& options = {});

//! The same result as repair(const Soup&, options), consuming `soup`: when repair changes
//! nothing (a closed, consistently oriented 2-manifold whose components already face outward,
//! cavities inward, with nothing the options remove or fill) the soup itself becomes the
//! output, with identity origins, found by one detection pass: no grouping, pairing or copy, so
//! the peak memory is detection's. Otherwise the full repair runs (that detection pass is its
//! `before`) and `soup` is left valid but unspecified.
//! \pre `soup` passes validate_soup() \throw as repair(const Soup&, options)
RepairResult repair(Soup&& soup, const RepairOptions& options = {});

//! Text form of the counts (JSON: repair_report_json() in report_json.h).
std::string to_text(const RepairReport& report);

}  // namespace meshbridge
