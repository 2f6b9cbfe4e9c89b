// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file report_counts.h
//! The numbers of MeshBridge's reports as one flat list of (key, value) pairs: the keys of
//! docs/report-schema.md in its order, nested objects joined with dots (`before.singular_edges`,
//! `gaps.vertices_welded`). For front ends that hand back a flat dictionary, such as the MeshLab
//! plugin's result map (pymeshlab's return value). Text (`gaps.refused_reason`) and element
//! lists are not numbers and are not in it.

#include "meshbridge/close_gaps.h"
#include "meshbridge/defect_report.h"
#include "meshbridge/fill_holes.h"
#include "meshbridge/repair.h"
#include "meshbridge/self_intersections.h"

#include <string>
#include <vector>

namespace meshbridge {

//! One number of a report.
struct ReportCount {
  enum class Kind {
    count,    //!< a count (>= 0) in `value`
    integer,  //!< a signed number in `value` (euler_characteristic)
    flag,     //!< yes (1) or no (0) in `value` (watertight)
    real,     //!< a real number in `real`, `value` unused (gaps.tolerance)
  };
  std::string name;  //!< the schema's key, nested ones joined with dots
  long long value = 0;
  Kind kind = Kind::count;
  double real = 0;
};

using ReportCounts = std::vector<ReportCount>;

//! Appends the counts of a check (docs/report-schema.md's check object, without `elements`):
//! vertices, faces, edges, components, euler_characteristic (integer), watertight (flag),
//! has_defects (flag), singular_edges, singular_edge_contenders, singular_vertices,
//! singular_edge_vertices, pinch_vertices, boundary_edges, boundary_loops, inconsistent_edges,
//! nonorientable_components, isolated_vertices, degenerate_faces, faces_set_aside,
//! zero_area_faces, duplicate_faces; each key preceded by `prefix` (e.g. "before.").
void append_counts(ReportCounts& out, const DefectReport& report, const std::string& prefix = "");

//! Appends gap closing's numbers (the schema's `gaps`): tolerance (real), vertices_welded,
//! largest_weld_distance (real), automatic (flag), welds_refused, welds_too_long,
//! t_junctions_closed, t_junctions_too_wide, sides_split, welds_undone, t_junctions_undone.
void append_counts(ReportCounts& out, const CloseGapsReport& gaps,
                   const std::string& prefix = "gaps.");

//! Appends hole filling's counts (the schema's `holes`): max_edges, holes_filled, faces_added,
//! holes_left, patches_refused.
void append_counts(ReportCounts& out, const FillHolesReport& holes,
                   const std::string& prefix = "holes.");

//! Appends the counts of find_self_intersections() (the schema's `self_intersections`):
//! face_pairs, faces, component_pairs, degenerate_triangles.
void append_counts(ReportCounts& out, const SelfIntersectionReport& crossings,
                   const std::string& prefix = "self_intersections.");

//! Appends a repair's counts (the schema's repair object): faces_in, faces_out, faces_set_aside,
//! faces_split, faces_added_by_split, slits_set_aside, keyhole_polygons_triangulated,
//! faces_flipped, duplicate_faces_removed, degenerate_faces_removed, zero_area_faces_removed,
//! vertices_in, vertices_out, vertices_split, isolated_vertices_removed, sides_cut,
//! sides_cut_for_orientation, sides_cut_to_stay_manifold, sides_paired_with_copies,
//! edges_split_to_stay_manifold, faces_given_midpoints, triangles_given_midpoints,
//! sides_stitched, nonorientable_after_pairing, ambiguous_nested_shells,
//! components_topology_changed, components_topology_changed_by_cuts_for_orientation,
//! components_topology_changed_by_pairing_stacked_copies; then gaps.*, holes.*
//! (always, 0 when filling was off), before.* and after.* (the check counts of `before` and
//! `after`).
void append_counts(ReportCounts& out, const RepairReport& report);

//! The entry named `name` in `counts`, or null.
ReportCount* find_count(ReportCounts& counts, const std::string& name);

}  // namespace meshbridge
