// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/report_counts.h"

#include <utility>

namespace meshbridge {
namespace {

//! Appends entries under one prefix.
class Appender {
 public:
  Appender(ReportCounts& out, std::string prefix) : out_(out), prefix_(std::move(prefix)) {}
  void count(const char* name, std::size_t value) {
    add(name, static_cast<long long>(value), ReportCount::Kind::count);
  }
  void integer(const char* name, long long value) { add(name, value, ReportCount::Kind::integer); }
  void flag(const char* name, bool value) { add(name, value ? 1 : 0, ReportCount::Kind::flag); }
  void real(const char* name, double value) {
    add(name, 0, ReportCount::Kind::real);
    out_.back().real = value;
  }

 private:
  void add(const char* name, long long value, ReportCount::Kind kind) {
    out_.push_back({prefix_ + name, value, kind, 0.0});
  }
  ReportCounts& out_;
  std::string prefix_;
};

}  // namespace

void append_counts(ReportCounts& out, const DefectReport& r, const std::string& prefix) {
  Appender a(out, prefix);
  std::size_t contenders = 0;
  for (const SingularEdge& e : r.singular_edges)
    contenders += e.contenders;
  a.count("vertices", r.num_vertices);
  a.count("faces", r.num_faces_of_file());
  a.count("edges", r.num_edges);
  a.count("components", r.num_components);
  a.integer("euler_characteristic", r.euler_characteristic);
  a.flag("watertight", r.watertight);
  a.flag("has_defects", r.has_defects());
  a.count("singular_edges", r.singular_edges.size());
  a.count("singular_edge_contenders", contenders);
  a.count("singular_vertices", r.num_singular_vertices());
  a.count("singular_edge_vertices", r.singular_edge_vertices.size());
  a.count("pinch_vertices", r.pinch_vertices.size());
  a.count("boundary_edges", r.boundary_edges.size());
  a.count("boundary_loops", r.num_boundary_loops);
  a.count("inconsistent_edges", r.inconsistent_edges.size());
  a.count("nonorientable_components", r.num_nonorientable_components);
  a.count("isolated_vertices", r.isolated_vertices.size());
  a.count("degenerate_faces", r.degenerate_faces.size());
  a.count("keyhole_polygons", r.keyhole_polygons_triangulated);
  a.count("faces_set_aside", r.num_faces_set_aside());
  a.count("zero_area_faces", r.zero_area_faces.size());
  a.count("duplicate_faces", r.duplicate_faces.size());
}

void append_counts(ReportCounts& out, const CloseGapsReport& g, const std::string& prefix) {
  Appender a(out, prefix);
  a.real("tolerance", g.tolerance);
  a.count("vertices_welded", g.vertices_welded);
  a.real("largest_weld_distance", g.largest_weld_distance);
  a.flag("automatic", g.automatic);
  a.count("welds_refused", g.welds_refused);
  a.count("welds_too_long", g.welds_too_long);
  a.count("t_junctions_closed", g.t_junctions_closed);
  a.count("t_junctions_too_wide", g.t_junctions_too_wide);
  a.count("sides_split", g.sides_split);
  a.count("welds_undone", g.welds_undone);
  a.count("t_junctions_undone", g.t_junctions_undone);
}

void append_counts(ReportCounts& out, const FillHolesReport& h, const std::string& prefix) {
  Appender a(out, prefix);
  a.count("max_edges", h.max_edges);
  a.count("holes_filled", h.holes_filled);
  a.count("faces_added", h.faces_added);
  a.count("holes_left", h.holes_left);
  a.count("patches_refused", h.patches_refused);
}

void append_counts(ReportCounts& out, const SelfIntersectionReport& s, const std::string& prefix) {
  Appender a(out, prefix);
  a.count("face_pairs", s.face_pairs.size());
  a.count("faces", s.faces.size());
  a.count("component_pairs", s.component_pairs.size());
  a.count("degenerate_triangles", s.degenerate_triangles);
}

void append_counts(ReportCounts& out, const RepairReport& r) {
  Appender a(out, "");
  a.count("faces_in", r.faces_in);
  a.count("faces_out", r.faces_out);
  a.count("faces_set_aside", r.faces_set_aside);
  a.count("faces_split", r.faces_split);
  a.count("faces_added_by_split", r.faces_added_by_split);
  a.count("slits_set_aside", r.slits_set_aside);
  a.count("keyhole_polygons_triangulated", r.keyhole_polygons_triangulated);
  a.count("faces_flipped", r.faces_flipped);
  a.count("duplicate_faces_removed", r.duplicate_faces_removed);
  a.count("degenerate_faces_removed", r.degenerate_faces_removed);
  a.count("zero_area_faces_removed", r.zero_area_faces_removed);
  a.count("vertices_in", r.vertices_in);
  a.count("vertices_out", r.vertices_out);
  a.count("vertices_split", r.vertices_split);
  a.count("isolated_vertices_removed", r.isolated_vertices_removed);
  a.count("sides_cut", r.sides_cut);
  a.count("sides_cut_for_orientation", r.sides_cut_for_orientation);
  a.count("sides_cut_to_stay_manifold", r.sides_cut_to_stay_manifold);
  a.count("sides_paired_with_copies", r.sides_paired_with_copies);
  a.count("edges_split_to_stay_manifold", r.edges_split_to_stay_manifold);
  a.count("faces_given_midpoints", r.faces_given_midpoints);
  a.count("triangles_given_midpoints", r.triangles_given_midpoints);
  a.count("sides_stitched", r.sides_stitched);
  a.count("nonorientable_after_pairing", r.nonorientable_after_pairing);
  a.count("ambiguous_nested_shells", r.ambiguous_nested_shells);
  a.count("components_topology_changed", r.topology_changes.size());
  a.count("components_topology_changed_by_cuts_for_orientation",
          components_topology_changed_by_cuts_for_orientation(r));
  a.count("components_topology_changed_by_pairing_stacked_copies",
          components_topology_changed_by_pairing_stacked_copies(r));
  append_counts(out, r.gaps);
  append_counts(out, r.holes);
  append_counts(out, r.before, "before.");
  append_counts(out, r.after, "after.");
}

ReportCount* find_count(ReportCounts& counts, const std::string& name) {
  for (ReportCount& c : counts) {
    if (c.name == name)
      return &c;
  }
  return nullptr;
}

}  // namespace meshbridge
