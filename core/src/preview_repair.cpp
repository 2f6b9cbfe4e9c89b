// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/preview_repair.h"

#include "meshbridge/counted.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/validate.h"

#include "detection.h"
#include "parallel_parts.h"
#include "pipeline/orientation.h"
#include "repair_run.h"
#include "working_soup.h"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <vector>

namespace meshbridge {

namespace {

// What orientation would reverse on a watertight soup of simple polygons (`report` its
// detection, `working` its simple polygons, `mate` the other side of each side from detection);
// not computed on any other.
OrientationPreview preview_orientation(const Soup& soup, const detail::WorkingSoup& working,
                                       const DefectReport& report, std::vector<Index>&& mate,
                                       AmbiguousNesting nested) {
  OrientationPreview orientation;
  if (!report.watertight || !working.is_identity())
    return orientation;
  detail::SidePairing pairing;
  pairing.mate = std::move(mate);
  pairing.flipped.assign(soup.num_faces(), 0);
  const detail::GroupedSides grouped{detail::CornerFaces(soup), EdgeBridges()};
  orientation.computed = true;
  orientation.ambiguous_nested_shells = detail::orient_components(soup, grouped, pairing, nested);
  for (char f : pairing.flipped)
    orientation.faces_flipped += f;
  return orientation;
}

// Whether detection and the orientation preview tell all repair would do: a watertight soup of
// simple polygons with nothing the options remove or fill (repair()'s own shortcut,
// report_if_unchanged() in repair.cpp, finds the same).
bool detection_tells(const DefectReport& before, const OrientationPreview& orientation,
                     const RepairOptions& options) {
  const bool removes = (options.remove_duplicate_faces && !before.duplicate_faces.empty()) ||
                       (options.remove_zero_area_faces && !before.zero_area_faces.empty()) ||
                       (options.remove_isolated_vertices && !before.isolated_vertices.empty());
  return orientation.computed && options.orient && !removes && options.fill_holes.max_edges == 0;
}

}  // namespace

DefectReport detect_defects(const Soup& soup, OrientationPreview* orientation,
                            AmbiguousNesting nested) {
  if (orientation == nullptr)
    return detect_defects(soup);
  validate_soup(soup);
  const detail::WorkingSoup working(soup);
  std::vector<Index> mate;
  DefectReport report = detail::detect(working, &mate);
  *orientation = preview_orientation(soup, working, report, std::move(mate), nested);
  return report;
}

bool repair_changes_input(const RepairReport& r) {
  const std::size_t changes[] = {r.faces_set_aside,
                                 r.faces_split,
                                 r.slits_set_aside,
                                 r.duplicate_faces_removed,
                                 r.degenerate_faces_removed,
                                 r.zero_area_faces_removed,
                                 r.isolated_vertices_removed,
                                 r.vertices_split,
                                 r.sides_cut,
                                 r.sides_cut_for_orientation,
                                 r.sides_cut_to_stay_manifold,
                                 r.sides_paired_with_copies,
                                 r.edges_split_to_stay_manifold,
                                 r.faces_flipped,
                                 r.holes.faces_added};
  return r.gaps.changed() || r.faces_out != r.faces_in || r.vertices_out != r.vertices_in ||
         std::any_of(std::begin(changes), std::end(changes), [](std::size_t n) { return n != 0; });
}

RepairPreview preview_repair(const Soup& soup, const DefectReport& before,
                             const OrientationPreview& orientation, const RepairOptions& options) {
  RepairPreview preview;
  if (detection_tells(before, orientation, options)) {
    // Watertight, simple polygons only: pairing takes the two sides of every edge and changes
    // nothing.
    RepairReport& r = preview.report;
    r.faces_in = r.faces_out = soup.num_faces();
    r.vertices_in = r.vertices_out = soup.num_vertices();
    r.faces_flipped = orientation.faces_flipped;
    r.ambiguous_nested_shells = orientation.ambiguous_nested_shells;
    r.nested_shells = options.nested_shells;
    r.components_before = r.components_after = before.num_components;
    r.before = r.after = before;
  } else {
    RepairOptions quiet = options;
    quiet.progress = nullptr;
    quiet.detect_before_after = false;  // the input's detection is `before`; no result's
    preview.report = repair(soup, quiet).report;
    preview.report.before = before;
    preview.report.boundary_edges_before = before.boundary_edges.size();
    preview.report.components_before = before.num_components;
    preview.ran_repair = true;
  }
  preview.changes = repair_changes_input(preview.report);
  return preview;
}

SoupCheck check_soup(const Soup& soup, const RepairOptions& options) {
  validate_soup(soup);
  SoupCheck check;
  const detail::WorkingSoup working(soup);
  detail::KnownInput known;  // (its future's destructor waits for a thread reading `working`)
  known.simple = &working;
  std::vector<Index> mate;
  const bool filtering = options.remove_duplicate_faces || options.remove_degenerate_faces ||
                         options.remove_zero_area_faces;  // cleanup reads `before` first
  const bool alongside = !filtering && detail::worker_threads() > 1;
  known.before_later = detail::detect_alongside(working, &mate, &known.grouped, alongside, true);
  // A boundary or singular edge: the grouping is kept, and with `alongside` the detection is
  // still being made (repair's run takes it after its pipeline).
  const bool later = !known.grouped.bridges.contenders.empty() && alongside;
  if (!later) {
    check.report = known.before_later.get();
    check.orientation =
        preview_orientation(soup, working, check.report, std::move(mate), options.nested_shells);
    if (detection_tells(check.report, check.orientation, options)) {
      check.preview = preview_repair(soup, check.report, check.orientation, options);
      return check;
    }
    known.before = check.report;
  }
  RepairOptions quiet = options;
  quiet.progress = nullptr;
  quiet.detect_before_after = true;  // the input's; not the result's (Detections::before_only)
  RepairPreview& preview = check.preview;
  preview.report =
      detail::repair_guarded(soup, quiet, std::move(known), detail::Detections::before_only).report;
  if (later)
    check.report = preview.report.before;
  preview.ran_repair = true;
  preview.changes = repair_changes_input(preview.report);
  return check;
}

namespace {

// "13 vertex copies" and the like, each only when its count is not 0.
void add(std::vector<std::string>& parts, std::size_t n, const std::string& what) {
  if (n != 0)
    parts.push_back(what);
}

}  // namespace

std::string to_text(const RepairPreview& preview) {
  const RepairReport& r = preview.report;
  std::vector<std::string> parts;
  const CloseGapsReport& g = r.gaps;
  add(parts, g.vertices_welded, "weld " + counted(g.vertices_welded, "vertex"));
  add(parts, g.t_junctions_closed, "close " + counted(g.t_junctions_closed, "T-junction"));
  add(parts, r.faces_set_aside,
      "set aside " + counted(r.faces_set_aside, "face") + " with < 3 distinct corners");
  // Keyhole polygons are among the faces split (into their triangles, the holes left open).
  const std::size_t keyholes = r.keyhole_polygons_triangulated;
  const std::size_t pieces = r.faces_split + r.faces_added_by_split;
  if (keyholes == 0) {
    add(parts, r.faces_split,
        "split " + counted(r.faces_split, "pinched polygon") + " into " + std::to_string(pieces) +
            " pieces");
  } else if (keyholes == r.faces_split) {
    parts.push_back("cut " + counted(keyholes, "keyhole polygon") + " into " +
                    std::to_string(pieces) + " triangles (the holes left open)");
  } else {
    parts.push_back("split " + counted(r.faces_split, "polygon") + " (" + std::to_string(keyholes) +
                    " keyhole, " + std::to_string(r.faces_split - keyholes) + " pinched) into " +
                    std::to_string(pieces) + " pieces");
  }
  add(parts, r.slits_set_aside, "set aside " + counted(r.slits_set_aside, "slit"));
  add(parts, r.duplicate_faces_removed,
      "remove " + counted(r.duplicate_faces_removed, "duplicate face"));
  add(parts, r.degenerate_faces_removed,
      "remove " + counted(r.degenerate_faces_removed, "degenerate face"));
  add(parts, r.zero_area_faces_removed,
      "remove " + counted(r.zero_area_faces_removed, "zero-area face"));
  add(parts, r.isolated_vertices_removed,
      "remove " + counted(r.isolated_vertices_removed, "isolated vertex"));
  add(parts, r.vertices_split,
      "make " + counted(r.vertices_split, "vertex copy") + " (split fans)");
  const std::size_t cut = r.sides_cut + r.sides_cut_for_orientation + r.sides_cut_to_stay_manifold;
  add(parts, cut, "cut " + counted(cut, "side") + " open");
  add(parts, r.sides_paired_with_copies,
      "pair " + counted(r.sides_paired_with_copies, "side") +
          " with copies of their faces (doubled sheets glued back to back)");
  add(parts, r.sides_stitched, "stitch " + counted(r.sides_stitched, "side") + " back");
  add(parts, r.edges_split_to_stay_manifold,
      "split " + counted(r.edges_split_to_stay_manifold, "edge") + " at the midpoint (" +
          counted(r.edges_split_to_stay_manifold, "vertex") + " added to " +
          counted(r.faces_given_midpoints, "face") + ")");
  add(parts, r.faces_flipped, "reverse " + counted(r.faces_flipped, "face"));
  std::size_t by_cuts = 0, by_stacked_copies = 0;  // the causes, as repair's report names them
  for (const TopologyChange& change : r.topology_changes) {
    by_cuts += change.cut_for_orientation ? 1 : 0;
    by_stacked_copies += !change.cut_for_orientation && change.stacked_copies != 0 ? 1 : 0;
  }
  std::string causes;
  if (by_cuts != 0)
    causes += std::to_string(by_cuts) + " where sides are cut for orientation";
  if (by_stacked_copies != 0) {
    causes += (causes.empty() ? "" : ", ") + std::to_string(by_stacked_copies) +
              " by pairing stacked face copies";
  }
  add(parts, r.topology_changes.size(),
      "change the topology (Euler characteristic) of " +
          counted(r.topology_changes.size(), "component") +
          (causes.empty() ? "" : " (" + causes + ")"));
  add(parts, r.holes.faces_added,
      "fill " + counted(r.holes.holes_filled, "hole") + " with " +
          counted(r.holes.faces_added, "triangle"));
  std::ostringstream out;
  if (parts.empty()) {
    out << "repair would change nothing";
  } else {
    out << "repair would:";
    for (std::size_t i = 0; i < parts.size(); ++i)
      out << (i == 0 ? " " : ", ") << parts[i];
  }
  if (r.ambiguous_nested_shells != 0 && r.nested_shells == AmbiguousNesting::cavity) {
    out << "; its reversed faces turn "
        << counted(r.ambiguous_nested_shells, "ambiguous nested shell")
        << " (wound like the shell around it) into voids (--nested-shells cavity)";
  } else if (r.ambiguous_nested_shells != 0) {
    out << (parts.empty() ? " (" : "; ") << "it keeps "
        << counted(r.ambiguous_nested_shells, "ambiguous nested shell")
        << " wound like the shell around it (an insert; --nested-shells cavity: a void)"
        << (parts.empty() ? ")" : "");
  }
  if (parts.empty() && r.boundary_edges_before != 0)
    out << " (" << counted(r.boundary_edges_before, "boundary edge") << " stay open)";
  if (g.welds_undone + g.t_junctions_undone != 0) {
    out << "; it refuses " << counted(g.welds_undone, "weld") << " and "
        << counted(g.t_junctions_undone, "T-junction closing") << " (" << g.refused_reason << ")";
  }
  out << "\n";
  return out.str();
}

}  // namespace meshbridge
