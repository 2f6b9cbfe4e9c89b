// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/repair.h"

#include "meshbridge/counted.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/validate.h"

#include "close_gaps_detail.h"
#include "detection.h"
#include "parallel_parts.h"
#include "pipeline/orientation.h"
#include "pipeline/run_pipeline.h"
#include "working_soup.h"

#include <algorithm>
#include <future>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>

namespace meshbridge {

namespace {

// The input without the polygons cleanup removes; origins map back to the input.
struct FilteredSoup {
  Soup soup;
  std::vector<Index> face_origin;
  std::vector<Index> corner_origin;
};

FilteredSoup without_faces(const Soup& input, const std::vector<char>& remove) {
  FilteredSoup filtered;
  filtered.soup.positions = input.positions;
  for (Index f = 0; f < input.num_faces(); ++f) {
    if (remove[f])
      continue;
    for (Index c = input.face_begin[f]; c < input.face_begin[f + 1]; ++c) {
      filtered.corner_origin.push_back(c);
    }
    filtered.soup.add_polygon(input.polygon(f));
    filtered.face_origin.push_back(f);
  }
  return filtered;
}

// Drops vertices no polygon uses; returns how many.
std::size_t remove_unused_vertices(IndexedMesh& mesh) {
  Soup& soup = mesh.soup;
  std::vector<Index> new_index(soup.num_vertices(), kNoIndex);
  for (Index v : soup.corner_vertices)
    new_index[v] = 0;
  Index next = 0;
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    if (new_index[v] == kNoIndex)
      continue;
    new_index[v] = next;
    soup.positions[next] = soup.positions[v];
    mesh.vertex_origin[next] = mesh.vertex_origin[v];
    ++next;
  }
  const std::size_t removed = soup.num_vertices() - next;
  soup.positions.resize(next);
  mesh.vertex_origin.resize(next);
  for (Index& v : soup.corner_vertices)
    v = new_index[v];
  return removed;
}

// Calls `options.progress`, when set, for the stage boundaries of repair().
void tell(const RepairOptions& options, Stage stage, double fraction) {
  if (options.progress)
    options.progress(stage, fraction);
}

// What repair(Soup&&) made of the input before deciding to run the pipeline, handed on so that
// nothing is made twice.
struct KnownInput {
  const detail::WorkingSoup* simple = nullptr;  //!< the input made simple; null: make it
  DefectReport* before = nullptr;               //!< its detection (moved from); null: detect
  //! its detection still being made beside the pipeline (detect_alongside()); taken after it
  std::future<DefectReport>* before_later = nullptr;
  detail::GroupedSides grouped;  //!< its grouping; no contenders: group again
};

// What the no-new-defects rule compares (DESIGN 8a): the input's open edges (one side), its
// singular edges with an odd number of sides (each may leave one side open), and the output's
// open edges and non-orientable components.
struct DefectBalance {
  std::size_t open_edges_in = 0;
  std::size_t odd_singular_edges_in = 0;
  std::size_t open_edges_out = 0;
  std::size_t nonorientable_out = 0;
};

DefectBalance input_balance(const detail::GroupedSides& grouped) {
  DefectBalance balance;
  const EdgeBridges& bridges = grouped.bridges;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index k = bridges.num_contenders(e);
    balance.open_edges_in += k == 1 ? 1 : 0;
    balance.odd_singular_edges_in += k > 2 && k % 2 == 1 ? 1 : 0;
  }
  return balance;
}

// Everything repair() does, on a valid soup; `known` holds what was already made of `input`.
// `balance`, when given, gets the counts the no-new-defects rule compares.
RepairResult repair_valid(const Soup& input, const RepairOptions& options, KnownInput&& known,
                          DefectBalance* balance = nullptr) {
  tell(options, Stage::group, 0);
  RepairResult result;
  RepairReport& report = result.report;
  // The input's simple polygons, grouped: detection of the input reads them, and so does gap
  // closing, which only looks at boundary sides (the grouping lists them when the polygons are
  // the input's own). Gap closing runs on the soup before everything else; when it changed
  // nothing the input and this grouping are used as they are (no copy), otherwise the rest runs
  // on the closed soup and origins are composed at the end.
  std::optional<detail::WorkingSoup> own_simple;
  const detail::WorkingSoup& input_simple =
      known.simple != nullptr ? *known.simple : own_simple.emplace(input);
  detail::GroupedSides grouped = known.grouped.bridges.contenders.empty()
                                     ? detail::group_sides(input_simple.soup())
                                     : std::move(known.grouped);
  if (balance != nullptr)
    *balance = input_balance(grouped);
  ClosedGaps gaps;
  bool gaps_closed = false;
  if (input_simple.is_identity()) {
    const std::vector<Index> boundary = detail::boundary_sides(grouped.bridges);
    gaps_closed = detail::close_gaps_if_any(input, options.close_gaps, gaps, &boundary);
  } else {
    gaps_closed = detail::close_gaps_if_any(input, options.close_gaps, gaps);
  }
  report.gaps = gaps.report;
  const bool filtering = options.remove_duplicate_faces || options.remove_degenerate_faces ||
                         options.remove_zero_area_faces;
  const bool detecting = options.detect_before_after || filtering;
  const bool before_later = known.before_later != nullptr && known.before_later->valid();
  if (detecting && !before_later) {
    report.before =
        known.before != nullptr ? std::move(*known.before) : detail::detect(input_simple, grouped);
  }
  // The simple polygons actually built; their grouping is reused below when nothing is removed.
  std::unique_ptr<detail::WorkingSoup> closed_simple;
  if (gaps_closed) {
    grouped = detail::GroupedSides();  // freed before the closed soup's grouping is made
    closed_simple = std::make_unique<detail::WorkingSoup>(gaps.soup);
    grouped = detail::group_sides(closed_simple->soup());
  }
  const detail::WorkingSoup& simple = gaps_closed ? *closed_simple : input_simple;
  const Soup& soup = simple.input();
  report.faces_in = input.num_faces();
  report.vertices_in = input.num_vertices();

  // Cleanup removals, on the simple polygons (a collapsed polygon can duplicate another one), so
  // that a second repair finds nothing more to remove.
  FilteredSoup filtered;
  std::unique_ptr<detail::WorkingSoup> filtered_working;
  if (filtering) {
    const Soup& polygons = simple.soup();
    std::vector<char> remove(polygons.num_faces(), 0);
    if (options.remove_duplicate_faces) {
      for (Index f : detail::duplicate_polygons(polygons)) {
        remove[f] = 1;
        ++report.duplicate_faces_removed;
      }
    }
    // The simple polygons of the listed input faces, not removed already, counted in `removed`.
    const auto remove_input_faces = [&](const std::vector<Index>& input_faces,
                                        std::size_t& removed) {
      std::vector<char> listed(soup.num_faces(), 0);
      for (Index f : input_faces)
        listed[f] = 1;
      for (Index f = 0; f < polygons.num_faces(); ++f) {
        if (listed[simple.face_origin(f)] && !remove[f]) {
          remove[f] = 1;
          ++removed;
        }
      }
    };
    if (options.remove_degenerate_faces)
      remove_input_faces(report.before.degenerate_faces, report.degenerate_faces_removed);
    if (options.remove_zero_area_faces)
      remove_input_faces(report.before.zero_area_faces, report.zero_area_faces_removed);
    filtered = without_faces(polygons, remove);
    for (Index& f : filtered.face_origin)
      f = simple.face_origin(f);
    for (Index& c : filtered.corner_origin)
      c = simple.corner_origin(c);
    filtered_working = std::make_unique<detail::WorkingSoup>(filtered.soup);  // already simple
    grouped = detail::group_sides(filtered_working->soup());
  }
  const detail::WorkingSoup& working = filtering ? *filtered_working : simple;
  tell(options, Stage::group, 1);
  tell(options, Stage::pair, 0);
  detail::PipelineOptions pipeline_options;
  pipeline_options.pairing = options.pairing;
  pipeline_options.orient = options.orient;
  pipeline_options.cut_nonorientable = options.cut_nonorientable;
  pipeline_options.stitch = options.stitch;
  pipeline_options.nested = options.nested_shells;
  pipeline_options.keep_state = false;  // only the mesh and the counts are read below
  detail::PipelineResult pipeline =
      detail::run_pipeline(working, std::move(grouped), pipeline_options);
  if (before_later)
    report.before = known.before_later->get();

  IndexedMesh& mesh = result.mesh;
  mesh = std::move(pipeline.mesh);
  if (filtering) {
    for (Index& f : mesh.face_origin)
      f = filtered.face_origin[f];
    for (Index& c : mesh.corner_origin)
      c = filtered.corner_origin[c];
  }
  if (gaps_closed) {
    for (Index& v : mesh.vertex_origin)
      v = v == kNoIndex ? kNoIndex : gaps.vertex_origin[v];  // kNoIndex: a midpoint vertex
    for (Index& c : mesh.corner_origin)
      c = gaps.corner_origin[c];
  }
  if (options.remove_isolated_vertices) {
    report.isolated_vertices_removed = remove_unused_vertices(mesh);
  }
  // On the repaired mesh (manifold, consistently oriented): new triangles go after every kept
  // face, so face_origin stays non-decreasing (kNoIndex is the largest index).
  report.holes = fill_holes(mesh, options.fill_holes);

  report.faces_out = mesh.soup.num_faces();
  // With remove_degenerate_faces, degenerate polygons left with < 3 corners count as removed.
  report.faces_set_aside = options.remove_degenerate_faces ? 0 : simple.excluded_faces().size();
  if (options.remove_degenerate_faces)
    report.degenerate_faces_removed += simple.excluded_faces().size();
  report.faces_split = simple.faces_split();
  report.faces_added_by_split = simple.faces_added_by_split();
  report.slits_set_aside = simple.slits().size();
  report.vertices_out = mesh.soup.num_vertices();
  report.vertices_split = pipeline.counts.vertices_split;
  report.sides_cut = pipeline.counts.sides_cut;
  report.sides_cut_for_orientation = pipeline.counts.sides_cut_for_orientation;
  report.sides_stitched = pipeline.counts.sides_stitched;
  report.faces_flipped = pipeline.counts.faces_flipped;
  report.sides_cut_to_stay_manifold = pipeline.counts.sides_cut_to_stay_manifold;
  report.sides_paired_with_copies = pipeline.counts.sides_paired_with_copies;
  report.edges_split_to_stay_manifold = pipeline.counts.edges_split_at_midpoint;
  report.nonorientable_components = pipeline.counts.nonorientable_components;
  report.ambiguous_nested_shells = pipeline.counts.ambiguous_nested_shells;
  if (balance != nullptr) {
    balance->open_edges_out = pipeline.counts.open_sides;
    balance->nonorientable_out = pipeline.counts.nonorientable_components;
  }
  // The pipeline's grouping and pairing (about 20 bytes per side) are not needed any more: free
  // them before the second detection allocates its own.
  pipeline = detail::PipelineResult();
  tell(options, Stage::pair, 1);
  tell(options, Stage::detect, 0);
  // The output is the input itself when nothing was split, flipped, removed or rewritten: its
  // detection is then the input's. Otherwise detect again, independently of the pipeline.
  const bool unchanged = !gaps_closed && !filtering && simple.is_identity() &&
                         report.vertices_split == 0 && report.faces_flipped == 0 &&
                         report.edges_split_to_stay_manifold == 0 &&
                         report.isolated_vertices_removed == 0 && report.holes.faces_added == 0;
  if (detecting) {
    // (The output is valid by construction: detect_defects() would check it again.)
    report.after = unchanged ? report.before : detail::detect(detail::WorkingSoup(mesh.soup));
  }
  tell(options, Stage::detect, 1);
  report.components_before = report.before.num_components;
  report.components_after = report.after.num_components;
  report.boundary_edges_before = report.before.boundary_edges.size();
  report.boundary_edges_after = report.after.boundary_edges.size();
  return result;
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
                                                const RepairOptions& options, DefectReport& before,
                                                KnownInput& known) {
  const bool filtering = options.remove_duplicate_faces || options.remove_degenerate_faces ||
                         options.remove_zero_area_faces;
  if (!options.detect_before_after && !filtering)
    return std::nullopt;  // no detection asked for: the pipeline's own path
  std::vector<Index> mate;
  // Without removals (which read the input's report first), a soup that has to go through the
  // pipeline gets the rest of its detection made beside it.
  const bool alongside = !filtering && detail::worker_threads() > 1;
  *known.before_later = detail::detect_alongside(working, &mate, &known.grouped, alongside);
  const bool pipeline = !known.grouped.bridges.contenders.empty();  // a boundary or singular edge
  if (pipeline && alongside)
    return std::nullopt;  // repair_valid() takes the report after its pipeline
  before = known.before_later->get();
  known.before = &before;
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

// repair_valid() held to the no-new-defects rule for gap closing (DESIGN 8a): welds and
// T-junction closings stay only if the repaired mesh has fewer open edges with them than the
// input has (pairing alone never closes an edge that has one side), or, when not, fewer than the
// repair without them, and no more non-orientable components. Otherwise the repair runs again
// without gap closing, and the report says what was refused and why. Gap closing that is kept
// costs nothing more; a refused one costs a second repair.
RepairResult repair_guarded(const Soup& input, const RepairOptions& options, KnownInput&& known) {
  DefectBalance closed;
  RepairResult result = repair_valid(input, options, std::move(known), &closed);
  const CloseGapsReport tried = result.report.gaps;
  if (!tried.changed() ||
      (closed.open_edges_out < closed.open_edges_in && closed.nonorientable_out == 0))
    return result;
  RepairOptions without = options;
  without.close_gaps.tolerance = 0;
  DefectBalance open;
  RepairResult plain = repair_valid(input, without, KnownInput(), &open);
  if (closed.open_edges_out < open.open_edges_out &&
      closed.nonorientable_out <= open.nonorientable_out)
    return result;
  CloseGapsReport& gaps = plain.report.gaps;
  gaps = CloseGapsReport();
  gaps.tolerance = tried.tolerance;
  gaps.welds_refused = tried.welds_refused;
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

}  // namespace

RepairResult repair(const Soup& input, const RepairOptions& options) {
  validate_soup(input);
  return repair_guarded(input, options, KnownInput());
}

RepairResult repair(Soup&& soup, const RepairOptions& options) {
  validate_soup(soup);
  DefectReport before;
  KnownInput known;
  std::optional<RepairReport> unchanged;
  {
    const detail::WorkingSoup working(soup);
    std::future<DefectReport> before_later;  // (its destructor waits for a thread reading working)
    known.simple = &working;
    known.before_later = &before_later;
    unchanged = report_if_unchanged(soup, working, options, before, known);
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
      << counted(r.edges_split_to_stay_manifold, "edge") << " split at the midpoint instead), "
      << r.sides_stitched << " stitched\n";
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
      << "; non-orientable components met by orientation: " << r.nonorientable_components << "\n";
  if (r.ambiguous_nested_shells != 0) {
    out << "nested shells: " << r.ambiguous_nested_shells
        << " wound like the shell around them (an insert, or a cavity wound the wrong way): "
           "left as written\n";
  }
  out << "after: singular edges " << r.after.singular_edges.size() << ", singular vertices "
      << r.after.num_singular_vertices() << ", non-orientable components "
      << r.after.num_nonorientable_components << ", watertight "
      << (r.after.watertight ? "yes" : "no") << "\n";
  return out.str();
}

}  // namespace meshbridge
