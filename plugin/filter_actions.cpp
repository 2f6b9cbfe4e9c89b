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
#include <initializer_list>
#include <sstream>
#include <string>
#include <utility>

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

//! Appends the filter's own counts (what it drew, selected and wrote back), none of a report.
void add_counts(ReportCounts& counts,
                std::initializer_list<std::pair<const char*, std::size_t>> values) {
  for (const auto& [name, value] : values)
    counts.push_back({name, static_cast<long long>(value)});
}

//! Sets the count `name` that append_counts() gave to `value`.
void set_count(ReportCounts& counts, const char* name, std::size_t value) {
  find_count(counts, name)->value = static_cast<long long>(value);
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

}  // namespace

void DocumentHost::update_box_and_normals(CMeshO& mesh) {
  vcg::tri::UpdateBounding<CMeshO>::Box(mesh);
  if (mesh.fn > 0) {
    vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(mesh);
    vcg::tri::UpdateNormal<CMeshO>::PerVertexAngleWeighted(mesh);
  }
}

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
  if (options.color_faces)
    host.enable_face_color();
  out.selection = select_defect_faces(soup, out.report, options.select_faces, options.color_faces);
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
  if (options.select_faces || options.color_faces) {
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

  append_counts(out.counts, out.report);
  add_counts(out.counts, {{"red_edges", out.drawn.singular_edges},
                          {"green_edges", out.drawn.boundary_edges},
                          {"singular_vertex_markers", out.drawn.singular_vertex_markers},
                          {"selected_faces", options.select_faces ? out.selection.faces : 0},
                          {"selected_vertices", options.select_faces ? out.selection.vertices : 0},
                          {"colored_faces", options.color_faces ? out.selection.faces : 0}});
  append_counts(out.counts, out.gaps);
  if (out.crossings) {
    append_counts(out.counts, *out.crossings);
    add_counts(out.counts, {{"violet_faces", out.violet_faces}});
  }
  return out;
}

RepairOutcome repair_singular_defects(CMeshO& mesh, const std::string& label,
                                      const RepairFilterOptions& options, DocumentHost& host) {
  require_faces(mesh, label, "Repair Singular Defects");
  RepairOutcome out;
  const CMeshSoup soup = soup_from_cmesh(mesh);
  RepairResult result = repair(soup.soup, options.core);
  WriteBackOptions write_options;
  write_options.keep_set_aside_faces = !options.core.remove_degenerate_faces;
  write_options.recompute_normals = options.recompute_normals;
  // STL keeps no shared vertices: what a save of this layer as STL reads back as, checked on the
  // soup the write-back makes of the layer.
  write_options.keep_soup = is_stl_file_name(host.file_name()) || result.report.vertices_split != 0;
  // Throws before touching the mesh if the result does not fit.
  out.written =
      write_repaired(mesh, soup, result.mesh, result.report.before.faces_set_aside, write_options);
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
  if (options.recompute_normals) {
    host.update_box_and_normals(mesh);
  } else {
    vcg::tri::UpdateBounding<CMeshO>::Box(mesh);
  }
  refresh_selection_counts(mesh);
  // The defects Detect showed are gone: its layer and its selection would only mislead.
  out.defect_layers_removed = host.remove_layers(defect_layer_label(label));
  if (out.defect_layers_removed != 0)
    clear_selection(mesh);
  if (out.written.soup) {
    out.reread = detect_defects(stl_round_trip(*out.written.soup));
    out.written.soup.reset();
  }

  const WriteBackReport& w = out.written;
  out.log = "MeshBridge repair of '" + label + "':\n";
  out.log += trimmed(to_text(out.report));
  out.log += "\nLayer now: " + std::to_string(mesh.vn) + " vertices, " + std::to_string(mesh.fn) +
             " faces (was " + std::to_string(w.vertices_in) + " vertices, " +
             std::to_string(w.faces_in) + " faces)";
  if (w.degenerate_faces_kept != 0) {
    out.log += "\nKept " + std::to_string(w.degenerate_faces_kept) +
               " degenerate faces unchanged (they repeat a vertex and cannot be manifold; "
               "'Remove degenerate faces' drops them)";
  }
  if (w.polygons_triangulated != 0) {
    out.log += "\nTriangulated " + std::to_string(w.polygons_triangulated) + " polygons (" +
               std::to_string(w.triangles_added_by_triangulation) + " extra triangles)";
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

  append_counts(out.counts, out.report);
  // Where the layer's number differs from the core's under the same key: vertices and faces of
  // the layer (triangles, degenerate faces kept).
  set_count(out.counts, "vertices_out", w.vertices_out);
  set_count(out.counts, "faces_out", w.faces_out);
  add_counts(out.counts, {{"degenerate_faces_kept", w.degenerate_faces_kept},
                          {"polygons_triangulated", w.polygons_triangulated}});
  if (out.reread)
    append_counts(out.counts, *out.reread, "reread.");
  return out;
}

}  // namespace meshbridge::meshlab
