// SPDX-License-Identifier: GPL-3.0-or-later
#include "repair_run.h"

#include "close_gaps_detail.h"
#include "detection.h"

namespace meshbridge::detail {

namespace {

bool removes_faces(const RepairOptions& options) {
  return options.remove_duplicate_faces || options.remove_degenerate_faces ||
         options.remove_zero_area_faces;
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

}  // namespace

RepairRun::RepairRun(const Soup& input, const RepairOptions& options, KnownInput&& known,
                     Detections detections)
    : input_(input),
      options_(options),
      known_(std::move(known)),
      filtering_(removes_faces(options)),
      detecting_(options.detect_before_after || filtering_),
      detections_(detections) {}

RepairResult RepairRun::run() {
  tell(Stage::group, 0);
  group_input();
  close_gaps();
  detect_input();
  group_closed_soup();
  clean_up();
  tell(Stage::group, 1);
  tell(Stage::pair, 0);
  pair_orient_emit();
  compose_origins();
  if (options_.remove_isolated_vertices)
    result_.report.isolated_vertices_removed = remove_unused_vertices(result_.mesh);
  fill_holes();
  count();
  tell(Stage::pair, 1);
  tell(Stage::detect, 0);
  detect_output();
  tell(Stage::detect, 1);
  return std::move(result_);
}

// The input's simple polygons, grouped: detection of the input reads them, and so does gap
// closing, which only looks at boundary sides (the grouping lists them when the polygons are
// the input's own).
void RepairRun::group_input() {
  input_simple_ = known_.simple != nullptr ? known_.simple : &own_simple_.emplace(input_);
  grouped_ = known_.grouped.bridges.contenders.empty() ? group_sides(input_simple_->soup())
                                                       : std::move(known_.grouped);
  const EdgeBridges& bridges = grouped_.bridges;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index k = bridges.num_contenders(e);
    balance_.open_edges_in += k == 1 ? 1 : 0;
    balance_.odd_singular_edges_in += k > 2 && k % 2 == 1 ? 1 : 0;
  }
}

// Welds and T-junction closings, on the input before everything else. When they change
// nothing the input and its grouping are used as they are (no copy); otherwise the rest runs on
// the closed soup (group_closed_soup()), and origins are composed at the end.
void RepairRun::close_gaps() {
  if (input_simple_->is_identity()) {
    const std::vector<Index> boundary = boundary_sides(grouped_.bridges);
    gaps_closed_ = close_gaps_if_any(input_, options_.close_gaps, gaps_, &boundary);
  } else {
    gaps_closed_ = close_gaps_if_any(input_, options_.close_gaps, gaps_);
  }
  result_.report.gaps = gaps_.report;
  simple_ = input_simple_;
}

// report.before, on the input's grouping, when asked for or when cleanup needs it, unless it
// is still being made beside the run (then taken after pairing).
void RepairRun::detect_input() {
  before_later_ = known_.before_later.valid();
  if (!detecting_ || before_later_)
    return;
  result_.report.before =
      known_.before ? std::move(*known_.before) : detect(*input_simple_, grouped_);
}

// The rest runs on the closed soup, when gap closing changed the input: made simple and grouped.
void RepairRun::group_closed_soup() {
  if (!gaps_closed_)
    return;
  grouped_ = GroupedSides();  // freed before the closed soup's grouping is made
  closed_simple_ = std::make_unique<WorkingSoup>(gaps_.soup);
  grouped_ = group_sides(closed_simple_->soup());
  simple_ = closed_simple_.get();
}

// Cleanup removals, on the simple polygons (a collapsed polygon can duplicate another one), so
// that a second repair finds nothing more to remove; and keyhole polygons, split into their
// loops for detection, become their triangles (WorkingSoup::keyholes()), so that the outline's
// loop does not cover the holes.
void RepairRun::clean_up() {
  working_ = simple_;
  if (!filtering_ && simple_->keyholes().empty())
    return;
  RepairReport& report = result_.report;
  const Soup& polygons = simple_->soup();
  std::vector<char> remove(polygons.num_faces(), 0);
  if (options_.remove_duplicate_faces) {
    for (Index f : duplicate_polygons(polygons)) {
      remove[f] = 1;
      ++report.duplicate_faces_removed;
    }
  }
  // The simple polygons of the listed input faces, not removed already, counted in `removed`.
  const auto remove_input_faces = [&](const std::vector<Index>& input_faces, std::size_t& removed) {
    std::vector<char> listed(simple_->input().num_faces(), 0);
    for (Index f : input_faces)
      listed[f] = 1;
    for (Index f = 0; f < polygons.num_faces(); ++f) {
      if (listed[simple_->face_origin(f)] && !remove[f]) {
        remove[f] = 1;
        ++removed;
      }
    }
  };
  if (options_.remove_degenerate_faces)
    remove_input_faces(report.before.degenerate_faces, report.degenerate_faces_removed);
  if (options_.remove_zero_area_faces)
    remove_input_faces(report.before.zero_area_faces, report.zero_area_faces_removed);
  // Per face of the simple soup: the keyhole whose first loop it is, +1 (0: none).
  std::vector<Index> keyhole_at(polygons.num_faces(), 0);
  for (std::size_t k = 0; k < simple_->keyholes().size(); ++k)
    keyhole_at[simple_->keyholes()[k].first_face] = static_cast<Index>(k + 1);
  const Soup& source = simple_->input();
  filtered_.positions = polygons.positions;
  for (Index f = 0; f < polygons.num_faces(); ++f) {
    if (keyhole_at[f] != 0) {
      const WorkingSoup::Keyhole& keyhole = simple_->keyholes()[keyhole_at[f] - 1];
      bool kept = true;  // a keyhole's loops are removed together (all of one input face)
      for (Index g = f; g < f + keyhole.num_loops; ++g)
        kept = kept && !remove[g];
      if (!kept) {  // removed as a degenerate face: neither cut nor its triangles added
        ++keyholes_removed_;
        keyhole_faces_not_added_ += keyhole.num_triangles - keyhole.num_loops;
      } else {
        const Index* corner = simple_->keyhole_corners().data() + keyhole.first_corner;
        for (Index i = 0; i < keyhole.num_triangles; ++i, corner += 3) {
          filtered_.add_polygon({source.corner_vertices[corner[0]],
                                 source.corner_vertices[corner[1]],
                                 source.corner_vertices[corner[2]]});
          filtered_corner_origin_.insert(filtered_corner_origin_.end(), corner, corner + 3);
          filtered_face_origin_.push_back(simple_->face_origin(f));
        }
        f += keyhole.num_loops - 1;
        continue;
      }
    }
    if (remove[f])
      continue;
    for (Index c = polygons.face_begin[f]; c < polygons.face_begin[f + 1]; ++c)
      filtered_corner_origin_.push_back(simple_->corner_origin(c));
    filtered_.add_polygon(polygons.polygon(f));
    filtered_face_origin_.push_back(simple_->face_origin(f));
  }
  filtered_working_ = std::make_unique<WorkingSoup>(filtered_);  // already simple
  grouped_ = group_sides(filtered_working_->soup());
  working_ = filtered_working_.get();
}

// The pipeline (DESIGN 4): edge bridges paired, components oriented, stitched, fans split,
// the manifold mesh emitted.
void RepairRun::pair_orient_emit() {
  PipelineOptions pipeline_options;
  pipeline_options.pairing = options_.pairing;
  pipeline_options.orient = options_.orient;
  pipeline_options.cut_nonorientable = options_.cut_nonorientable;
  pipeline_options.stitch = options_.stitch;
  pipeline_options.nested = options_.nested_shells;
  pipeline_options.keep_state = false;  // only the mesh and the counts are read below
  pipeline_ = run_pipeline(*working_, std::move(grouped_), pipeline_options);
  if (before_later_)
    result_.report.before = known_.before_later.get();
  result_.mesh = std::move(pipeline_.mesh);
}

// The output's origins, in the pipeline's soup, composed back through cleanup and gap closing
// to the input.
void RepairRun::compose_origins() {
  IndexedMesh& mesh = result_.mesh;
  if (filtered_working_) {  // cleanup or keyholes rewrote the simple soup
    for (Index& f : mesh.face_origin)
      f = filtered_face_origin_[f];
    for (Index& c : mesh.corner_origin)
      c = filtered_corner_origin_[c];
  }
  if (gaps_closed_) {
    for (Index& v : mesh.vertex_origin)
      v = v == kNoIndex ? kNoIndex : gaps_.vertex_origin[v];  // kNoIndex: a midpoint vertex
    for (Index& c : mesh.corner_origin)
      c = gaps_.corner_origin[c];
  }
}

// On the repaired mesh (manifold, consistently oriented): new triangles go after every kept
// face, so face_origin stays non-decreasing (kNoIndex is the largest index).
void RepairRun::fill_holes() {
  result_.report.holes = meshbridge::fill_holes(result_.mesh, options_.fill_holes);
}

// The report's counts from the steps; the pipeline's state is freed (about 20 bytes per side)
// before the output's detection allocates its own.
void RepairRun::count() {
  RepairReport& report = result_.report;
  const IndexedMesh& mesh = result_.mesh;
  const PipelineCounts& counts = pipeline_.counts;
  report.faces_in = input_.num_faces();
  report.vertices_in = input_.num_vertices();
  report.faces_out = mesh.soup.num_faces();
  // With remove_degenerate_faces, degenerate polygons left with < 3 corners count as removed.
  report.faces_set_aside = options_.remove_degenerate_faces ? 0 : simple_->faces_set_aside().size();
  if (options_.remove_degenerate_faces)
    report.degenerate_faces_removed += simple_->faces_set_aside().size();
  report.faces_split = simple_->faces_split();
  report.faces_added_by_split = simple_->faces_added_by_split() - keyhole_faces_not_added_;
  report.slits_set_aside = simple_->slits_set_aside();
  report.keyhole_polygons_triangulated = simple_->keyholes().size() - keyholes_removed_;
  report.vertices_out = mesh.soup.num_vertices();
  report.vertices_split = counts.vertices_split;
  report.sides_cut = counts.sides_cut;
  report.sides_cut_for_orientation = counts.sides_cut_for_orientation;
  report.sides_stitched = counts.sides_stitched;
  report.faces_flipped = counts.faces_flipped;
  report.sides_cut_to_stay_manifold = counts.sides_cut_to_stay_manifold;
  report.sides_paired_with_copies = counts.sides_paired_with_copies;
  report.edges_split_to_stay_manifold = counts.edges_split_to_stay_manifold;
  report.faces_given_midpoints = counts.faces_given_midpoints;
  report.triangles_given_midpoints = counts.triangles_given_midpoints;
  report.topology_changes = std::move(pipeline_.topology_changes);
  report.nonorientable_after_pairing = counts.nonorientable_components;
  report.ambiguous_nested_shells = counts.ambiguous_nested_shells;
  report.nested_shells = options_.nested_shells;
  balance_.open_edges_out = counts.open_sides;
  balance_.nonorientable_out = counts.nonorientable_components;
  pipeline_ = PipelineResult();
}

// report.after. The output is the input itself when nothing was split, flipped, removed or
// rewritten: its detection is then the input's. Otherwise detect again, independently of the
// pipeline.
void RepairRun::detect_output() {
  RepairReport& report = result_.report;
  const bool unchanged = !gaps_closed_ && !filtering_ && simple_->is_identity() &&
                         report.vertices_split == 0 && report.faces_flipped == 0 &&
                         report.edges_split_to_stay_manifold == 0 &&
                         report.isolated_vertices_removed == 0 && report.holes.faces_added == 0;
  if (detecting_ && detections_ == Detections::before_and_after) {
    // (The output is valid by construction: detect_defects() would check it again.)
    report.after = unchanged ? report.before : detect(WorkingSoup(result_.mesh.soup));
  }
  report.components_before = report.before.num_components;
  report.components_after = report.after.num_components;
  report.boundary_edges_before = report.before.boundary_edges.size();
  report.boundary_edges_after = report.after.boundary_edges.size();
}

void RepairRun::tell(Stage stage, double fraction) const {
  if (options_.progress)
    options_.progress(stage, fraction);
}

}  // namespace meshbridge::detail
