// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_actions.h"

#include "crossing_faces.h"
#include "defect_tubes.h"

#include "meshbridge/close_gaps.h"
#include "meshbridge/detect_defects.h"
#include "meshbridge/io.h"
#include "meshbridge/stl_round_trip.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/algorithms/update/selection.h>
#include <vcg/complex/algorithms/update/topology.h>

#include <cctype>
#include <sstream>
#include <string>

namespace meshbridge::meshlab {
namespace {

void require_faces(const CMeshO& mesh, const std::string& label, const char* filter) {
  if (mesh.fn > 0)
    return;
  throw FilterInputError(std::string(filter) + " needs a mesh with faces: layer '" + label +
                         "' has " + std::to_string(mesh.vn) +
                         " vertices and no faces (a point cloud or edge mesh?). Nothing was "
                         "changed.");
}

//! The core's text without its trailing newlines (MeshLab's log adds its own line breaks).
std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    text.pop_back();
  return text;
}

void refresh_selection_counts(CMeshO& mesh) {
  mesh.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(mesh));
  mesh.sfn = int(vcg::tri::UpdateSelection<CMeshO>::FaceCount(mesh));
}

FilterCount count(const char* name, std::size_t value) {
  return {name, static_cast<long long>(value), false};
}

FilterCount real(const char* name, double value) {
  FilterCount c{name, 0, false};
  c.is_real = true;
  c.real = value;
  return c;
}

//! Gap closing's counts, keys as in docs/report-schema.md's `gaps`.
void add_gap_counts(std::vector<FilterCount>& counts, const CloseGapsReport& g) {
  counts.push_back(real("gaps.tolerance", g.tolerance));
  counts.push_back(count("gaps.vertices_welded", g.vertices_welded));
  counts.push_back(real("gaps.largest_weld_distance", g.largest_weld_distance));
  counts.push_back(count("gaps.welds_refused", g.welds_refused));
  counts.push_back(count("gaps.t_junctions_closed", g.t_junctions_closed));
  counts.push_back(count("gaps.sides_split", g.sides_split));
}

//! Detect's line on what Repair's gap closing would do (the CLI's `check` says the same).
std::string would_close_gaps_text(const CloseGapsReport& g, bool automatic) {
  std::ostringstream out;
  if (!(g.tolerance > 0))
    return "gaps: not closed (weld tolerance 0)";
  out << "gaps (weld tolerance " << g.tolerance << (automatic ? ", automatic" : "")
      << "): Repair would weld " << g.vertices_welded << " vertices (largest move "
      << g.largest_weld_distance << ", " << g.welds_refused << " refused: same polygon) and close "
      << g.t_junctions_closed << " T-junction cracks (" << g.sides_split << " sides split)";
  return out.str();
}

//! The repaired layer's line on what an STL file of it reads back as.
std::string stl_reread_text(const DefectReport& reread, std::size_t vertices_split) {
  std::string text = "STL re-read: saved as STL and loaded again, this layer has singular edges " +
                     std::to_string(reread.singular_edges.size()) + ", singular vertices " +
                     std::to_string(reread.num_singular_vertices()) + ", watertight " +
                     (reread.watertight ? "yes" : "no");
  if (vertices_split != 0) {
    text += ". STL stores no shared vertices: every reader welds the " +
            std::to_string(vertices_split) + " split vertex copies together again";
  }
  return text;
}

void clear_selection(CMeshO& mesh) {
  vcg::tri::UpdateSelection<CMeshO>::FaceClear(mesh);
  vcg::tri::UpdateSelection<CMeshO>::VertexClear(mesh);
  refresh_selection_counts(mesh);
}

//! The self-intersection counts, keys as in docs/report-schema.md's `self_intersections`.
void add_crossing_counts(std::vector<FilterCount>& counts, const SelfIntersectionReport& s,
                         std::size_t violet_faces) {
  counts.push_back(count("self_intersections.face_pairs", s.face_pairs.size()));
  counts.push_back(count("self_intersections.faces", s.faces.size()));
  counts.push_back(count("self_intersections.component_pairs", s.component_pairs.size()));
  counts.push_back(count("violet_faces", violet_faces));
}

}  // namespace

bool self_intersections_by_default(std::size_t faces) {
  return faces <= kSelfIntersectionsDefaultMaxFaces;
}

bool is_stl_file_name(const std::string& file_name) {
  return mesh_format(file_name) == MeshFormat::stl;
}

std::string defect_layer_label(const std::string& mesh_label) {
  std::string name = mesh_label;
  const std::size_t dot = name.find_last_of('.');
  if (dot != std::string::npos && dot > 0) {
    const std::string ext = name.substr(dot + 1);
    const bool is_extension =
        !ext.empty() && ext.size() <= 5 && ext.find_first_of(" /\\()") == std::string::npos;
    if (is_extension)
      name.erase(dot);
  }
  for (char& c : name) {
    if (c == '.')
      c = '_';
  }
  return name + " - defects";
}

std::vector<std::string> html_log_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::string line;
  auto flush = [&] {
    while (!line.empty() && (line.back() == ' ' || line.back() == '\r'))
      line.pop_back();
    lines.push_back(line);
    line.clear();
  };
  for (char c : text) {
    switch (c) {
      case '&':
        line += "&amp;";
        break;
      case '<':
        line += "&lt;";
        break;
      case '>':
        line += "&gt;";
        break;
      case '\n':
        flush();
        break;
      default:
        line += c;
    }
  }
  if (!line.empty())
    flush();
  // MeshLab's log adds its own breaks: no empty entries at the end.
  while (!lines.empty() && lines.back().empty())
    lines.pop_back();
  return lines;
}

DetectOutcome detect_singular_defects(CMeshO& mesh, const std::string& label,
                                      const DetectOptions& options, DocumentHost& host) {
  require_faces(mesh, label, "Detect Singular Defects");
  DetectOutcome out;
  CMeshSoup soup = soup_from_cmesh(mesh);
  out.report = detect_defects(soup.soup);
  out.gaps = preview_close_gaps(soup.soup, options.close_gaps);
  const bool find_crossings = options.self_intersections && self_intersections_available();
  if (find_crossings)
    out.crossings = find_self_intersections(soup.soup);

  // Nothing has changed so far; from here on only the selection, face colours and a new layer.
  if (options.colour_faces)
    host.enable_face_colour();
  out.selection = select_defect_faces(soup, out.report, options.select_faces, options.colour_faces);
  if (options.select_faces)
    refresh_selection_counts(mesh);

  // The defect layer stays behind the current one, so the next filter of a script still works
  // on the mesh itself; it replaces the layer a previous Detect of this mesh made.
  out.label = defect_layer_label(label);
  const bool tubes = options.layer_form == DefectLayerForm::tubes;
  CMeshO& layer = host.add_defect_layer(out.label, tubes);
  out.drawn = tubes ? build_defect_tubes(soup, out.report, layer)
                    : build_defect_layer(soup, out.report, layer);
  if (tubes && out.crossings)
    out.violet_faces = add_crossing_faces(soup, *out.crossings, layer);
  layer.Tr = mesh.Tr;
  vcg::tri::UpdateBounding<CMeshO>::Box(layer);
  layer.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(layer));

  out.log = "MeshBridge defects of '" + label + "':\n";
  out.log += trimmed(to_text(out.report));
  out.log += "\n" + would_close_gaps_text(out.gaps, options.close_gaps.tolerance < 0);
  if (out.crossings) {
    out.log += "\n" + trimmed(to_text(*out.crossings));
  } else {
    out.log += options.self_intersections
                   ? "\nself-intersections: not searched (this build has no CGAL)"
                   : "\nself-intersections: not searched (turn on 'Find self-intersections')";
  }
  if (options.select_faces || options.colour_faces) {
    out.log += "\n" + std::string(options.select_faces ? "Selected " : "Coloured ") +
               std::to_string(out.selection.faces) + " faces at singular edges/vertices";
    if (options.select_faces)
      out.log += " and " + std::to_string(out.selection.vertices) + " singular vertices";
  }
  out.log += "\nDefect layer '" + out.label + "': " + std::to_string(out.drawn.singular_edges) +
             " red (singular) edges, " + std::to_string(out.drawn.boundary_edges) +
             " green (boundary) edges, " + std::to_string(out.drawn.singular_vertex_markers) +
             " singular vertex markers";
  if (out.crossings && tubes) {
    out.log += ", " + std::to_string(out.violet_faces) + " violet (self-intersecting) faces";
  } else if (out.crossings) {
    out.log += "; the " + std::to_string(out.crossings->faces.size()) +
               " self-intersecting faces are not drawn in an Edges layer";
  }

  const DefectReport& r = out.report;
  std::size_t contenders = 0;
  for (const SingularEdge& e : r.singular_edges)
    contenders += e.contenders;
  out.counts = {
      count("vertices", r.num_vertices),
      count("faces", r.num_faces),
      count("edges", r.num_edges),
      count("singular_edges", r.singular_edges.size()),
      count("singular_edge_contenders", contenders),
      count("singular_vertices", r.num_singular_vertices()),
      count("singular_edge_vertices", r.singular_edge_vertices.size()),
      count("pinch_vertices", r.pinch_vertices.size()),
      count("boundary_edges", r.boundary_edges.size()),
      count("boundary_loops", r.num_boundary_loops),
      count("isolated_vertices", r.isolated_vertices.size()),
      count("degenerate_faces", r.degenerate_faces.size()),
      count("faces_set_aside", r.excluded_faces.size()),
      count("zero_area_faces", r.zero_area_faces.size()),
      count("duplicate_faces", r.duplicate_faces.size()),
      count("inconsistent_edges", r.inconsistent_edges.size()),
      count("nonorientable_components", r.num_nonorientable_components),
      count("components", r.num_components),
      {"euler_characteristic", r.euler_characteristic, false},
      {"watertight", r.watertight ? 1 : 0, true},
      count("red_edges", out.drawn.singular_edges),
      count("green_edges", out.drawn.boundary_edges),
      count("singular_vertex_markers", out.drawn.singular_vertex_markers),
      count("selected_faces", options.select_faces ? out.selection.faces : 0),
      count("selected_vertices", options.select_faces ? out.selection.vertices : 0),
      count("coloured_faces", options.colour_faces ? out.selection.faces : 0),
  };
  add_gap_counts(out.counts, out.gaps);
  if (out.crossings)
    add_crossing_counts(out.counts, *out.crossings, out.violet_faces);
  return out;
}

RepairOutcome repair_singular_defects(CMeshO& mesh, const std::string& label,
                                      const RepairFilterOptions& options, DocumentHost& host) {
  require_faces(mesh, label, "Repair Singular Defects");
  WriteBackOptions write_options;
  write_options.keep_set_aside_faces = !options.core.remove_degenerate_faces;
  write_options.recompute_normals = options.recompute_normals;

  RepairOutcome out;
  const CMeshSoup soup = soup_from_cmesh(mesh);
  RepairResult result = repair(soup.soup, options.core);
  // Throws before touching the mesh if the result does not fit.
  out.written =
      write_repaired(mesh, soup, result.mesh, result.report.before.excluded_faces, write_options);
  out.report = std::move(result.report);

  // What MeshLab's own cleaning filters do after changing the mesh: adjacency that was in use is
  // rebuilt (MeshModel::updateDataMask does the same for FF/VF), border flags, bounding box and
  // normals are recomputed (MeshModel::UpdateBoxAndNormals), selection counts refreshed.
  const bool has_ff = mesh.face.IsFFAdjacencyEnabled();
  if (has_ff)
    vcg::tri::UpdateTopology<CMeshO>::FaceFace(mesh);
  if (mesh.vert.IsVFAdjacencyEnabled() && mesh.face.IsVFAdjacencyEnabled())
    vcg::tri::UpdateTopology<CMeshO>::VertexFace(mesh);
  if (has_ff) {
    vcg::tri::UpdateFlags<CMeshO>::FaceBorderFromFF(mesh);
  } else {
    vcg::tri::UpdateFlags<CMeshO>::FaceBorderFromNone(mesh);
  }
  vcg::tri::UpdateFlags<CMeshO>::VertexBorderFromFaceBorder(mesh);
  vcg::tri::UpdateBounding<CMeshO>::Box(mesh);
  if (options.recompute_normals && mesh.fn > 0) {
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(mesh);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexAngleWeighted(mesh);
  }
  refresh_selection_counts(mesh);
  // The defects Detect showed are gone: its layer and its selection would only mislead.
  out.defect_layers_removed = host.remove_layers(defect_layer_label(label));
  if (out.defect_layers_removed != 0)
    clear_selection(mesh);
  // STL keeps no shared vertices: what a save of this layer as STL reads back as.
  if (is_stl_file_name(host.file_name()) || out.report.vertices_split != 0)
    out.reread = detect_defects(stl_round_trip(soup_from_cmesh(mesh).soup));

  const WriteBackReport& w = out.written;
  out.log = "MeshBridge repair of '" + label + "':\n";
  out.log += trimmed(to_text(out.report));
  out.log += "\nLayer now: " + std::to_string(mesh.vn) + " vertices, " + std::to_string(mesh.fn) +
             " faces (was " + std::to_string(w.vertices_in) + " vertices, " +
             std::to_string(w.faces_in) + " faces)";
  if (w.set_aside_faces_kept != 0) {
    out.log += "\nKept " + std::to_string(w.set_aside_faces_kept) +
               " degenerate faces unchanged (they repeat a vertex and cannot be manifold; "
               "'Remove degenerate faces' drops them)";
  }
  if (w.polygons_fanned != 0) {
    out.log += "\nTriangulated " + std::to_string(w.polygons_fanned) + " polygons (" +
               std::to_string(w.triangles_from_fans) + " extra triangles)";
  }
  if (out.defect_layers_removed != 0) {
    out.log += "\nRemoved the defect layer '" + defect_layer_label(label) +
               "' and cleared the selection Detect made (run Detect again to check the result)";
  }
  if (out.reread)
    out.log += "\n" + stl_reread_text(*out.reread, out.report.vertices_split);
  if (out.report.vertices_split != 0) {
    out.log += "\nTo keep the repair, save as PLY, OBJ or OFF";
    out.log += host.can_save_3mf() ? " (or 3MF)" : "";
    out.log += ": they keep the " + std::to_string(out.report.vertices_split) +
               " split vertex copies apart";
  }

  const RepairReport& r = out.report;
  out.counts = {
      count("vertices_in", w.vertices_in),
      count("vertices_out", std::size_t(mesh.vn)),
      count("faces_in", w.faces_in),
      count("faces_out", std::size_t(mesh.fn)),
      count("vertices_split", r.vertices_split),
      count("faces_flipped", r.faces_flipped),
      count("sides_cut", r.sides_cut),
      count("sides_cut_for_orientation", r.sides_cut_for_orientation),
      count("sides_stitched", r.sides_stitched),
      count("faces_split", r.faces_split),
      count("faces_added_by_split", r.faces_added_by_split),
      count("faces_set_aside", r.faces_set_aside),
      count("duplicate_faces_removed", r.duplicate_faces_removed),
      count("degenerate_faces_removed", r.degenerate_faces_removed),
      count("isolated_vertices_removed", r.isolated_vertices_removed),
      // Keys of docs/report-schema.md, flattened with dots (JSON `before.components`).
      count("before.components", r.components_before),
      count("after.components", r.components_after),
      count("before.boundary_edges", r.boundary_edges_before),
      count("after.boundary_edges", r.boundary_edges_after),
      count("before.nonorientable_components", r.nonorientable_components),
      count("before.singular_edges", r.before.singular_edges.size()),
      count("before.singular_vertices", r.before.num_singular_vertices()),
      count("after.singular_edges", r.after.singular_edges.size()),
      count("after.singular_vertices", r.after.num_singular_vertices()),
      {"after.watertight", r.after.watertight ? 1 : 0, true},
      count("degenerate_faces_kept", w.set_aside_faces_kept),
      count("polygons_triangulated", w.polygons_fanned),
  };
  add_gap_counts(out.counts, r.gaps);
  out.counts.push_back(count("holes.max_edges", r.holes.max_edges));
  out.counts.push_back(count("holes.holes_filled", r.holes.holes_filled));
  out.counts.push_back(count("holes.faces_added", r.holes.faces_added));
  out.counts.push_back(count("holes.holes_left", r.holes.holes_left));
  out.counts.push_back(count("holes.patches_refused", r.holes.patches_refused));
  if (out.reread) {
    const DefectReport& again = *out.reread;
    out.counts.push_back(count("reread.singular_edges", again.singular_edges.size()));
    out.counts.push_back(count("reread.singular_vertices", again.num_singular_vertices()));
    out.counts.push_back(count("reread.boundary_edges", again.boundary_edges.size()));
    out.counts.push_back({"reread.watertight", again.watertight ? 1 : 0, true});
  }
  return out;
}

}  // namespace meshbridge::meshlab
