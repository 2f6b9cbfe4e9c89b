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
#include "meshbridge/report_counts.h"
#include "meshbridge/self_intersections.h"

#include <optional>
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

//! One number a filter hands back (pymeshlab returns them as a dict): the core's flattened
//! report entry (report_counts.h), key e.g. "singular_edges" or "before.components".
using FilterCount = ReportCount;

// ---- detect ----------------------------------------------------------------------------------

//! How the defect layer shows the defects.
enum class DefectLayerForm {
  //! Triangles: a thin tube along each defect edge and a marker at each singular vertex, in
  //! per-vertex and per-face colour (defect_tubes.h). MeshLab shows them in colour by default.
  tubes,
  //! The raw edges: an edge mesh, two vertices and one edge per defect edge, coloured per
  //! vertex, plus one isolated marker vertex per singular vertex. For scripts; MeshLab draws
  //! edges as thin lines in a user colour unless told otherwise.
  edges,
};

//! Options of the detect filter.
struct DetectOptions {
  //! Replace the face and vertex selection by the faces with a side on a singular edge or a
  //! corner at a pinch vertex, and by the singular vertices. Default: on.
  bool select_faces = true;
  //! Paint those faces: red at singular edges, orange at pinch vertices (per-face colour is
  //! turned on through DocumentHost::enable_face_colour()). Default: off.
  bool color_faces = false;
  //! What the defect layer holds. Default: tubes.
  DefectLayerForm layer_form = DefectLayerForm::tubes;
  //! Detect reports what Repair's gap closing would weld and close with these options (it
  //! changes nothing itself). Default: the core's (automatic tolerance, T-junctions closed).
  CloseGapsOptions close_gaps;
  //! Also find the faces that cross or overlap another face (find_self_intersections(), exact
  //! predicates, both cores), count them, and show them in the tube layer in violet
  //! (crossing_faces.h). It costs about as much again as the rest of Detect (meshlabserver on a
  //! torus, two cores: +0.9 s on 0.6 s at 1M faces, +2.8 s on 3.5 s at 2M), so the parameter
  //! defaults to it only up to kSelfIntersectionsDefaultMaxFaces faces
  //! (self_intersections_by_default()). Default here: on.
  bool self_intersections = true;
};

//! The largest mesh (in faces, MeshLab's triangles) for which Detect's "Find self-intersections"
//! is on by default: 2,000,000 (Detect then takes about 3 s more on two cores).
inline constexpr std::size_t kSelfIntersectionsDefaultMaxFaces = 2000000;

//! Whether Detect finds self-intersections by default on a mesh of `faces` faces: up to
//! kSelfIntersectionsDefaultMaxFaces.
bool self_intersections_by_default(std::size_t faces);

//! What the filters need from MeshLab's document; each adapter implements it with its API's
//! MeshModel/MeshDocument calls.
class DocumentHost {
 public:
  virtual ~DocumentHost() = default;
  //! Turns on per-face colour of the current layer (called only with `colour_faces`).
  virtual void enable_face_color() = 0;
  //! Removes every layer labelled `label` other than the current one, then appends a layer
  //! labelled `label`, with per-vertex colour and quality (and per-face colour if
  //! `face_colour`), behind the current one (the current layer stays current); returns its mesh.
  //! Called once, after detection succeeded.
  virtual CMeshO& add_defect_layer(const std::string& label, bool face_color) = 0;
  //! Removes every layer labelled `label` other than the current one; returns how many.
  virtual std::size_t remove_layers(const std::string& label) = 0;
  //! True if this MeshLab can save 3MF files (an exporter for it is loaded).
  virtual bool can_save_3mf() const = 0;
  //! The file the current layer was loaded from (MeshModel::fullName()); empty if none.
  virtual std::string file_name() const = 0;
  //! Recomputes the bounding box and the face and vertex normals of `mesh`, the current layer's
  //! mesh, after a change: MeshModel::UpdateBoxAndNormals(), as MeshLab's own filters call it.
  //! The default makes the vcglib calls that function makes, for hosts without a MeshModel.
  virtual void update_box_and_normals(CMeshO& mesh);
};

//! True if `file_name` ends with ".stl" (any case).
bool is_stl_file_name(const std::string& file_name);

//! The label of the defect layer of a mesh labelled `mesh_label`: its name without the file
//! extension, then " - defects" ("t_junction_rib.off" -> "t_junction_rib - defects"). Dots
//! left in the name become '_' (MeshLab's layer list shows a label up to its last dot).
std::string defect_layer_label(const std::string& mesh_label);

//! `text` as lines for MeshLab's log, which is rich text: one entry per line of `text`, with
//! '&', '<' and '>' escaped, so that every line arrives and nothing is read as a tag.
std::vector<std::string> html_log_lines(const std::string& text);

//! What detect_singular_defects() found and did.
struct DetectOutcome {
  DefectReport report;        //!< the core's detection on the layer's live faces
  DefectLayerCounts drawn;    //!< what the defect layer shows
  DefectSelection selection;  //!< faces and vertices selected (or coloured)
  std::string label;          //!< the defect layer's label (defect_layer_label())
  //! What Repair's gap closing would do with `options.close_gaps` (close_gaps() on the layer;
  //! the layer itself is not changed).
  CloseGapsReport gaps;
  //! With `options.self_intersections`: the faces (the layer's live faces, in storage order)
  //! that cross or overlap. Absent otherwise.
  std::optional<SelfIntersectionReport> crossings;
  //! Faces shown in violet in the tube layer (crossing faces of nonzero area; 0 for edges).
  std::size_t violet_faces = 0;
  //! Plain text, one line per line: the report, what gap closing would do ("gaps (weld
  //! tolerance T[, automatic]): Repair would weld N vertices ..."), the self-intersections
  //! (to_text() of `crossings`, or "self-intersections: not searched ..."), the selection, then
  //! as its last line the summary "Defect layer '<label>': N red (singular) edges, M green
  //! (boundary) edges, K singular vertex markers" (with `crossings` followed by ", F violet
  //! (self-intersecting) faces", or for an Edges layer by "; the F self-intersecting faces are
  //! not drawn in an Edges layer"). Pass it through html_log_lines() for MeshLab's log.
  std::string log;
  //! The numbers, in this order: the report's (append_counts() of report_counts.h: the keys of
  //! docs/report-schema.md's check object, `faces` in triangles); the defect layer's red_edges,
  //! green_edges, singular_vertex_markers; selected_faces and selected_vertices (0 unless
  //! `select_faces`), colored_faces (0 unless `color_faces`); what gap closing would do
  //! (gaps.*, the schema's `gaps`); with `crossings` only, self_intersections.* (the schema's
  //! `self_intersections`) and the layer's violet_faces.
  std::vector<FilterCount> counts;
};

//! Detects the singular defects of `mesh` (labelled `label`) without changing its geometry, and
//! its self-intersections if `options.self_intersections`; then selects/colours faces as
//! `options` say (self-intersecting faces are neither selected nor coloured) (colours and the
//! colour mask of `mesh` are left alone unless `colour_faces`) and fills a new defect layer from
//! `host`, replacing the one a previous Detect made. \throw FilterInputError if `mesh` has no faces
//! (nothing changed, no layer added) \throw std::exception from the core (before anything changed)
DetectOutcome detect_singular_defects(CMeshO& mesh, const std::string& label,
                                      const DetectOptions& options, DocumentHost& host);

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
  //! Defect layers of this mesh that were removed (they showed the defects before repair).
  std::size_t defect_layers_removed = 0;
  //! The repaired layer as an STL file of it reads back (detect_defects(stl_round_trip()) of
  //! the layer's faces): computed when the layer was loaded from an STL file or vertices were
  //! split, absent otherwise.
  std::optional<DefectReport> reread;
  //! Plain text, one line per line: the counts (the core's, gap closing first), then with
  //! `reread` what an STL save reads back as ("STL re-read: saved as STL and loaded again, this
  //! layer has singular edges S, singular vertices V, watertight yes|no", and why when vertices
  //! were split), and (when vertices were split) which formats keep the repair. Pass it through
  //! html_log_lines() for MeshLab's log.
  std::string log;
  //! The numbers, in this order: the repair report's (append_counts() of report_counts.h: the
  //! keys of docs/report-schema.md's repair object with gaps.*, holes.*, before.* and after.*
  //! flattened with dots), except that vertices_out and faces_out are the layer's (faces in
  //! triangles, degenerate faces kept included);
  //! then the write-back's degenerate_faces_kept and polygons_triangulated; with `reread` only,
  //! reread.* (the check counts of `reread`).
  std::vector<FilterCount> counts;
};

//! Repairs `mesh` (labelled `label`) in place, losslessly: every face is kept with its
//! attributes and its place in face order. Afterwards face-face and vertex-face adjacency are
//! rebuilt if they were enabled, border flags, bounding box and selection counts are
//! recomputed, and normals too if `options.recompute_normals`. The defect layer of `mesh` (see
//! defect_layer_label()) is removed through `host`, and if there was one, the face and vertex
//! selection of `mesh` (made by that Detect) is cleared, so what is on screen after Repair is
//! the repaired mesh. When the layer came from an STL file (host.file_name()) or vertices were
//! split, the log says what an STL save of the result reads back as (`reread`). The adapter
//! still tells MeshLab what changed (data masks, "modified").
//! \throw FilterInputError if `mesh` has no faces (nothing changed)
//! \throw std::exception from the core or the write-back (then `mesh` is unchanged)
RepairOutcome repair_singular_defects(CMeshO& mesh, const std::string& label,
                                      const RepairFilterOptions& options, DocumentHost& host);

}  // namespace meshbridge::meshlab
