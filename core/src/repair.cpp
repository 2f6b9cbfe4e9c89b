// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/repair.h"

#include "meshbridge/counted.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/validate.h"

#include "close_gaps_detail.h"
#include "detection.h"
#include "parallel_parts.h"
#include "pipeline/orientation.h"
#include "repair_run.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <sstream>

namespace meshbridge {

namespace {

using detail::DefectBalance;
using detail::KnownInput;
using detail::repair_guarded;

// Calls `options.progress`, when set, for the stage boundaries of repair().
void tell(const RepairOptions& options, Stage stage, double fraction) {
  if (options.progress)
    options.progress(stage, fraction);
}

// When repair() would return `soup` itself, its report (and `known` is left empty); otherwise
// nothing, with `known` holding the detection of `soup` (`working` is its simple polygons) when
// repair() makes one, and the grouping that detection kept. repair()
// returns the soup unchanged exactly when it is a closed, consistently oriented 2-manifold (no
// degenerate polygon, every edge with two opposite sides, no pinch vertex), every component of
// which already faces the way orientation turns it, with nothing the options would remove or
// fill: pairing takes the two sides of every edge, orientation and stitching change nothing,
// every vertex has one fan, and gap closing finds no boundary to work on.
std::optional<RepairReport> report_if_unchanged(const Soup& soup,
                                                const detail::WorkingSoup& working,
                                                const RepairOptions& options, KnownInput& known) {
  const bool filtering = options.remove_duplicate_faces || options.remove_degenerate_faces ||
                         options.remove_zero_area_faces;
  if (!options.detect_before_after && !filtering)
    return std::nullopt;  // no detection asked for: the pipeline's own path
  std::vector<Index> mate;
  // Without removals (which read the input's report first), a soup that has to go through the
  // pipeline gets the rest of its detection made beside it.
  const bool alongside = !filtering && detail::worker_threads() > 1;
  known.before_later = detail::detect_alongside(working, &mate, &known.grouped, alongside);
  const bool pipeline = !known.grouped.bridges.contenders.empty();  // a boundary or singular edge
  if (pipeline && alongside)
    return std::nullopt;  // the run takes the report after its pipeline
  DefectReport& before = known.before.emplace(known.before_later.get());
  if (!working.is_identity() || !before.watertight || options.fill_holes.max_edges > 0 ||
      (options.remove_duplicate_faces && !before.duplicate_faces.empty()) ||
      (options.remove_zero_area_faces && !before.zero_area_faces.empty()) ||
      (options.remove_isolated_vertices && !before.isolated_vertices.empty()))
    return std::nullopt;
  std::size_t ambiguous = 0;
  if (options.orient) {
    detail::SidePairing pairing;
    pairing.mate = std::move(mate);
    pairing.flipped.assign(soup.num_faces(), 0);
    const detail::GroupedSides grouped{detail::CornerFaces(soup), EdgeBridges()};
    ambiguous = detail::orient_components(soup, grouped, pairing, options.nested_shells);
    if (std::find(pairing.flipped.begin(), pairing.flipped.end(), 1) != pairing.flipped.end())
      return std::nullopt;
  }
  mate = std::vector<Index>();
  RepairReport report;
  report.ambiguous_nested_shells = ambiguous;
  report.nested_shells = options.nested_shells;
  ClosedGaps gaps;
  const std::vector<Index> no_boundary;
  detail::close_gaps_if_any(soup, options.close_gaps, gaps, &no_boundary);  // the tolerance
  report.gaps = gaps.report;
  report.faces_in = report.faces_out = soup.num_faces();
  report.vertices_in = report.vertices_out = soup.num_vertices();
  report.components_before = report.components_after = before.num_components;
  report.boundary_edges_before = report.boundary_edges_after = before.boundary_edges.size();
  report.before = std::move(before);
  report.after = report.before;
  return report;
}

}  // namespace

RepairResult repair(const Soup& input, const RepairOptions& options) {
  validate_soup(input);
  return repair_guarded(input, options, KnownInput());
}

RepairResult repair(Soup&& soup, const RepairOptions& options) {
  validate_soup(soup);
  std::optional<RepairReport> unchanged;
  {
    const detail::WorkingSoup working(soup);
    KnownInput known;  // (its future's destructor waits for a thread reading `working`)
    known.simple = &working;
    unchanged = report_if_unchanged(soup, working, options, known);
    if (!unchanged)
      return repair_guarded(soup, options, std::move(known));
  }
  for (Stage stage : {Stage::group, Stage::pair, Stage::detect}) {
    tell(options, stage, 0);
    tell(options, stage, 1);
  }
  RepairResult result;
  result.report = std::move(*unchanged);
  IndexedMesh& mesh = result.mesh;
  mesh.vertex_origin.resize(soup.num_vertices());
  std::iota(mesh.vertex_origin.begin(), mesh.vertex_origin.end(), Index(0));
  mesh.face_origin.resize(soup.num_faces());
  std::iota(mesh.face_origin.begin(), mesh.face_origin.end(), Index(0));
  mesh.corner_origin.resize(soup.num_corners());
  std::iota(mesh.corner_origin.begin(), mesh.corner_origin.end(), Index(0));
  mesh.soup = std::move(soup);
  return result;
}

namespace detail {

// A RepairRun held to the no-new-defects rule for gap closing (DESIGN 8a): welds and
// T-junction closings stay only if the repaired mesh has fewer open edges with them than the
// input has (pairing alone never closes an edge that has one side), or, when not, fewer than the
// repair without them, and no more non-orientable components. Otherwise the repair runs again
// without gap closing, and the report says what was refused and why. Gap closing that is kept
// costs nothing more; a refused one costs a second repair.
RepairResult repair_guarded(const Soup& input, const RepairOptions& options, KnownInput&& known,
                            Detections detections) {
  const WorkingSoup* simple = known.simple;
  RepairRun closing(input, options, std::move(known), detections);
  RepairResult result = closing.run();
  const DefectBalance& closed = closing.balance();
  const CloseGapsReport tried = result.report.gaps;
  if (!tried.changed() ||
      (closed.open_edges_out < closed.open_edges_in && closed.nonorientable_out == 0))
    return result;
  RepairOptions without = options;
  without.close_gaps.tolerance = 0;
  KnownInput again;  // the input's simple polygons and detection, as the first run made them
  again.simple = simple;
  if (options.detect_before_after || options.remove_duplicate_faces ||
      options.remove_degenerate_faces || options.remove_zero_area_faces)
    again.before = result.report.before;  // (made by the first run: RepairRun::detect_input())
  RepairRun not_closing(input, without, std::move(again), detections);
  RepairResult plain = not_closing.run();
  const DefectBalance& open = not_closing.balance();
  if (closed.open_edges_out < open.open_edges_out &&
      closed.nonorientable_out <= open.nonorientable_out)
    return result;
  CloseGapsReport& gaps = plain.report.gaps;
  gaps = CloseGapsReport();
  gaps.tolerance = tried.tolerance;
  gaps.automatic = tried.automatic;
  gaps.welds_refused = tried.welds_refused;
  gaps.welds_too_long = tried.welds_too_long;
  gaps.t_junctions_too_wide = tried.t_junctions_too_wide;
  gaps.welds_undone = tried.vertices_welded;
  gaps.t_junctions_undone = tried.t_junctions_closed;
  std::ostringstream why;
  why << "with them the repaired mesh would have " << counted(closed.open_edges_out, "open edge")
      << " (without: " << open.open_edges_out << ")";
  if (closed.nonorientable_out > open.nonorientable_out) {
    why << " and " << counted(closed.nonorientable_out, "non-orientable component")
        << " (without: " << open.nonorientable_out << ")";
  }
  gaps.refused_reason = why.str();
  return plain;
}

}  // namespace detail

}  // namespace meshbridge
