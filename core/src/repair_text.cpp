// SPDX-License-Identifier: GPL-3.0-or-later
// meshbridge::to_text(const RepairReport&): the repair report as the CLI prints it.
#include "meshbridge/repair.h"

#include "meshbridge/counted.h"

#include <sstream>
#include <string>
#include <vector>

namespace meshbridge {

namespace {

// What the midpoint splits added ("" when there were none): a vertex each, and a corner to the
// polygons of each pair split.
std::string midpoint_note(const RepairReport& r) {
  const std::size_t edges = r.edges_split_to_stay_manifold;
  if (edges == 0)
    return std::string();
  std::string note = ": " + counted(edges, "vertex") + " added, ";
  const std::size_t faces = r.faces_given_midpoints, triangles = r.triangles_given_midpoints;
  if (triangles == faces && faces == 2 * edges)  // each a triangle given one corner
    return note + std::to_string(triangles) + " triangles became quads";
  if (triangles == faces)
    return note + std::to_string(triangles) + " triangles given corners (quads or larger now)";
  note += counted(faces, "polygon") + " given corners";
  if (triangles != 0)
    note += ", " + std::to_string(triangles) + " of them triangles (quads or larger now)";
  return note;
}

// "2 -> -2"; for a component with stacked face copies, its value with each face counted once:
// "4 -> -8 (2194 faces, 484 of them copies: 488 counting them)".
std::string euler_change(const TopologyChange& change) {
  if (change.stacked_copies == 0)
    return std::to_string(change.euler_before) + " -> " + std::to_string(change.euler_after);
  const long long once = change.euler_before - static_cast<long long>(change.stacked_copies);
  return std::to_string(once) + " -> " + std::to_string(change.euler_after) + " (" +
         std::to_string(change.faces) + " faces, " + std::to_string(change.stacked_copies) +
         " of them copies: " + std::to_string(change.euler_before) + " counting them)";
}

// Which line of the topology note a change is on.
enum class TopologyCause { pairing, pairing_stacked_copies, cut_for_orientation };

TopologyCause cause_of(const TopologyChange& change) {
  if (change.cut_for_orientation)
    return TopologyCause::cut_for_orientation;
  return change.stacked_copies != 0 ? TopologyCause::pairing_stacked_copies
                                    : TopologyCause::pairing;
}

// One line of the changes made by `cause` ("" when there are none), listing the first few.
std::string topology_line(const std::vector<TopologyChange>& changes, TopologyCause cause,
                          const char* what) {
  std::size_t count = 0;
  for (const TopologyChange& change : changes)
    count += cause_of(change) == cause ? 1 : 0;
  if (count == 0)
    return std::string();
  constexpr std::size_t kListed = 5;
  std::string note = std::to_string(count) + (count == 1 ? " component's" : " components'") +
                     " topology changed " + what + "Euler characteristic";
  std::size_t listed = 0;
  for (const TopologyChange& change : changes) {
    if (cause_of(change) != cause || listed == kListed)
      continue;
    note += (listed++ > 0 ? ", " : " ") + euler_change(change);
  }
  return note + (count > kListed ? ", ...\n" : "\n");
}

// "1 component's topology changed by pairing: Euler characteristic 2 -> -2", the components
// holding stacked face copies on a line of their own (their value with each face counted once),
// and those where orientation cut sides open on another ("" when none).
std::string topology_note(const RepairReport& r) {
  const std::vector<TopologyChange>& changes = r.topology_changes;
  return topology_line(changes, TopologyCause::pairing, "by pairing: ") +
         topology_line(changes, TopologyCause::pairing_stacked_copies,
                       "by pairing stacked face copies (faces on the corners of another face), "
                       "with each face counted once: ") +
         topology_line(changes, TopologyCause::cut_for_orientation,
                       "where sides were cut for orientation: ");
}

}  // namespace

std::string to_text(const RepairReport& r) {
  std::ostringstream out;
  const CloseGapsReport& g = r.gaps;
  if (g.tolerance > 0) {
    out << "gaps (tolerance " << g.tolerance << "): " << counted(g.vertices_welded, "vertex")
        << " welded (largest move " << g.largest_weld_distance << ", " << g.welds_refused
        << " refused: same polygon), " << counted(g.t_junctions_closed, "T-junction") << " closed ("
        << counted(g.sides_split, "side") << " split)\n";
    if (g.welds_too_long != 0 || g.t_junctions_too_wide != 0) {
      out << "gaps kept open: " << counted(g.welds_too_long, "weld") << " and "
          << counted(g.t_junctions_too_wide, "T-junction closing")
          << " would move a vertex by more than a quarter of the shortest edge there\n";
    }
  } else if (g.automatic) {
    out << "gaps: none to close (no boundary edge)\n";
  } else {
    out << "gaps: not closed (tolerance 0)\n";
  }
  if (g.welds_undone != 0 || g.t_junctions_undone != 0) {
    out << "gaps refused: " << counted(g.welds_undone, "weld") << " and "
        << counted(g.t_junctions_undone, "T-junction closing") << " undone: " << g.refused_reason
        << "\n";
  }
  out << "faces: " << r.faces_in << " in, " << r.faces_out << " out (" << r.faces_set_aside
      << " set aside, " << r.faces_split << " split into " << r.faces_added_by_split << " more"
      << (r.keyhole_polygons_triangulated != 0
              ? " (" + counted(r.keyhole_polygons_triangulated, "keyhole polygon") +
                    " triangulated, holes left open)"
              : std::string())
      << (r.slits_set_aside != 0 ? " (" + counted(r.slits_set_aside, "keyhole slit") + " set aside)"
                                 : std::string())
      << ", " << counted(r.duplicate_faces_removed, "duplicate") << " and "
      << r.degenerate_faces_removed << " degenerate removed, "
      << (r.zero_area_faces_removed != 0
              ? std::to_string(r.zero_area_faces_removed) + " of zero area removed, "
              : std::string())
      << r.faces_flipped << " flipped)\n";
  out << "vertices: " << r.vertices_in << " in, " << r.vertices_out << " out ("
      << counted(r.vertices_split, "copy") << " from split fans, " << r.isolated_vertices_removed
      << " isolated removed)\n";
  out << "sides: " << r.sides_cut << " cut on singular edges, " << r.sides_cut_for_orientation
      << " cut for orientation, " << r.sides_cut_to_stay_manifold << " cut to stay manifold ("
      << r.sides_paired_with_copies << " paired with copies and "
      << counted(r.edges_split_to_stay_manifold, "edge") << " split at the midpoint instead"
      << midpoint_note(r) << "), " << r.sides_stitched << " stitched\n";
  const FillHolesReport& h = r.holes;
  if (h.max_edges > 0) {
    out << "holes (up to " << h.max_edges << " edges): " << h.holes_filled << " filled with "
        << counted(h.faces_added, "new triangle") << ", " << h.holes_left << " left open";
    if (h.patches_refused > 0) {
      out << " (" << h.patches_refused << " of them no hole: a patch would lie on the surface, "
          << "as on the outline of an open sheet)";
    }
    out << "\n";
  } else {
    out << "holes: not filled (off)\n";
  }
  out << "components: " << r.components_before << " -> " << r.components_after
      << "; boundary edges: " << r.boundary_edges_before << " -> " << r.boundary_edges_after
      << "; non-orientable components met by orientation: " << r.nonorientable_after_pairing
      << "\n";
  out << topology_note(r);
  if (r.ambiguous_nested_shells != 0) {
    out << "nested shells: " << r.ambiguous_nested_shells
        << " wound like the shell around them (an insert, or a cavity wound the wrong way): "
        << (r.nested_shells == AmbiguousNesting::cavity
                ? "reversed into voids (--nested-shells cavity)\n"
                : "left as written (--nested-shells cavity: voids)\n");
  }
  out << "after: singular edges " << r.after.singular_edges.size() << ", singular vertices "
      << r.after.num_singular_vertices() << ", non-orientable components "
      << r.after.num_nonorientable_components << ", watertight "
      << (r.after.watertight ? "yes" : "no") << "\n";
  return out.str();
}

}  // namespace meshbridge
