// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file filter_actions.h
//! What the two MeshBridge filters do, on CMeshO and plain options: run the core's detection or
//! repair, build the defect layer, select and colour faces, update what vcglib keeps beside the
//! mesh (adjacency, border flags, normals, bounding box, selection counts), and return the counts
//! and the log text.
//!
//! Shared by every MeshLab adapter (2020.09's MeshFilterInterface, 2022+'s FilterPlugin); the
//! adapters only translate parameters, data masks, layers, logging and errors of their API.

#include "cmesh_adapter.h"

#include "meshbridge/defect_report.h"
#include "meshbridge/repair.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace meshbridge::meshlab {

//! A filter was given a layer it cannot work on (no faces). Thrown before anything changes; the
//! message names the layer and says why.
class FilterInputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

//! One number a filter hands back (pymeshlab returns them as a dict).
struct FilterCount {
  std::string name;  //!< snake_case key, e.g. "singular_edges"
  long long value = 0;
  bool is_flag = false;  //!< a yes/no value (0 or 1), e.g. "watertight"
};

// ---- detect ----------------------------------------------------------------------------------

//! Options of the detect filter.
struct DetectOptions {
  //! Replace the face and vertex selection by the faces with a side on a singular edge or a
  //! corner at a pinch vertex, and by the singular vertices. Default: on.
  bool select_faces = true;
  //! Paint those faces: red at singular edges, orange at pinch vertices (per-face colour is
  //! turned on through DetectHost::enable_face_colour()). Default: off.
  bool colour_faces = false;
};

//! What the detect filter needs from MeshLab's document; each adapter implements it with its
//! API's MeshModel/MeshDocument calls.
class DetectHost {
 public:
  virtual ~DetectHost() = default;
  //! Turns on per-face colour of the current layer (called only with `colour_faces`).
  virtual void enable_face_colour() = 0;
  //! Appends a layer labelled `label`, with per-vertex colour and quality, behind the current
  //! one (the current layer stays current); returns its mesh. Called once, after detection
  //! succeeded.
  virtual CMeshO& add_defect_layer(const std::string& label) = 0;
};

//! What detect_singular_defects() found and did.
struct DetectOutcome {
  DefectReport report;        //!< the core's detection on the layer's live faces
  DefectLayerCounts drawn;    //!< what the defect layer shows
  DefectSelection selection;  //!< faces and vertices selected (or coloured)
  std::string log;            //!< one readable block: report, defect layer, selection
  //! The numbers, in this order: vertices, faces (triangles), edges, singular_edges,
  //! singular_edge_contenders (sides on singular edges, summed), singular_vertices,
  //! singular_edge_vertices, pinch_vertices, boundary_edges, boundary_loops, isolated_vertices,
  //! degenerate_faces, zero_area_faces, duplicate_faces, inconsistent_edges,
  //! nonorientable_components, components, euler_characteristic, watertight (flag); the defect
  //! layer's red_edges, green_edges, singular_vertex_markers; selected_faces and
  //! selected_vertices (0 unless `select_faces`), coloured_faces (0 unless `colour_faces`).
  std::vector<FilterCount> counts;
};

//! Detects the singular defects of `mesh` (labelled `label`) without changing its geometry;
//! then selects/colours faces as `options` say and fills a new defect layer from `host`.
//! \throw FilterInputError if `mesh` has no faces (nothing changed, no layer added)
//! \throw std::exception from the core (before anything changed)
DetectOutcome detect_singular_defects(CMeshO& mesh, const std::string& label,
                                      const DetectOptions& options, DetectHost& host);

// ---- repair ----------------------------------------------------------------------------------

//! Options of the repair filter.
struct RepairFilterOptions {
  RepairOptions core;  //!< the core's options, with the core's defaults
  //! Recompute face and vertex normals afterwards (as MeshLab's own cleaning filters do).
  //! Off: vertex normals are copied to split vertices and face normals of flipped faces are
  //! negated, so normals loaded from a file survive. Default: on.
  bool recompute_normals = true;
};

//! What repair_singular_defects() did.
struct RepairOutcome {
  RepairReport report;      //!< the core's repair report (detection before and after included)
  WriteBackReport written;  //!< what the write-back into CMeshO did
  std::string log;          //!< one readable block of counts
  //! The numbers, in this order: vertices_in, vertices_out, faces_in, faces_out (the layer's,
  //! faces in triangles); the core's vertices_split, faces_flipped, sides_cut,
  //! sides_cut_for_orientation, sides_stitched, faces_detached, faces_split,
  //! faces_added_by_split, faces_set_aside, duplicate_faces_removed, degenerate_faces_removed,
  //! isolated_vertices_removed, components_before, components_after, boundary_edges_before,
  //! boundary_edges_after, nonorientable_components, singular_edges_before,
  //! singular_vertices_before, singular_edges_after, singular_vertices_after; the write-back's
  //! degenerate_faces_kept and polygons_triangulated.
  std::vector<FilterCount> counts;
};

//! Repairs `mesh` (labelled `label`) in place, losslessly: every face is kept with its
//! attributes and its place in face order. Afterwards face-face and vertex-face adjacency are
//! rebuilt if they were enabled, border flags, bounding box and selection counts are
//! recomputed, and normals too if `options.recompute_normals`. The adapter still tells MeshLab
//! what changed (data masks, "modified").
//! \throw FilterInputError if `mesh` has no faces (nothing changed)
//! \throw std::exception from the core or the write-back (then `mesh` is unchanged)
RepairOutcome repair_singular_defects(CMeshO& mesh, const std::string& label,
                                      const RepairFilterOptions& options);

}  // namespace meshbridge::meshlab
