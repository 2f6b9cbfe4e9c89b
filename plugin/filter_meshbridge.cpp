// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_meshbridge.h"

#include "cmesh_adapter.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/repair.h"

#include <vcg/complex/algorithms/update/flag.h>
#include <vcg/complex/algorithms/update/selection.h>

#include <exception>
#include <string>

namespace mb = meshbridge;
namespace mbm = meshbridge::meshlab;

namespace {

// Parameter names: snake_case like the core's options (and pymeshlab's later python names).
const char* const kSelectFaces = "select_faces";
const char* const kColourFaces = "color_faces";
const char* const kPairing = "pairing";
const char* const kOrient = "orient";
const char* const kStitch = "stitch";
const char* const kCutNonorientable = "cut_nonorientable";
const char* const kRemoveDuplicateFaces = "remove_duplicate_faces";
const char* const kRemoveDegenerateFaces = "remove_degenerate_faces";
const char* const kRemoveIsolatedVertices = "remove_isolated_vertices";
const char* const kRecomputeNormals = "recompute_normals";

QString no_faces_message(const MeshModel& m, const char* what) {
  return QString(
             "%1 needs a mesh with faces: layer '%2' has %3 vertices and no faces "
             "(a point cloud or edge mesh?). Nothing was changed.")
      .arg(what)
      .arg(m.label())
      .arg(m.cm.vn);
}

//! The core's text without its trailing newlines (MeshLab's log adds its own line breaks).
std::string trimmed(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
    text.pop_back();
  return text;
}

}  // namespace

FilterMeshBridgePlugin::FilterMeshBridgePlugin() {
  typeList << FP_DETECT_SINGULAR_DEFECTS << FP_REPAIR_SINGULAR_DEFECTS;
  for (FilterIDType id : types())
    actionList << new QAction(filterName(id), this);
}

FilterMeshBridgePlugin::~FilterMeshBridgePlugin() = default;  // actions are QObject children

QString FilterMeshBridgePlugin::pluginName() const {
  return "FilterMeshBridge";
}

QString FilterMeshBridgePlugin::filterName(FilterIDType filter) const {
  switch (filter) {
    case FP_DETECT_SINGULAR_DEFECTS:
      return "Detect Singular Defects (Bridged Half-Edge)";
    case FP_REPAIR_SINGULAR_DEFECTS:
      return "Repair Singular Defects (Bridged Half-Edge)";
  }
  return "Unknown MeshBridge filter";
}

QString FilterMeshBridgePlugin::filterInfo(FilterIDType filter) const {
  switch (filter) {
    case FP_DETECT_SINGULAR_DEFECTS:
      return "Finds the defects that stop a half-edge structure from holding the mesh, without "
             "changing it: <b>singular edges</b> (more than two faces on one edge, with their "
             "number of faces), <b>singular vertices</b> (on a singular edge, or pinch vertices "
             "whose faces form more than one fan), boundary edges and holes, isolated vertices, "
             "degenerate, zero-area and duplicate faces, inconsistently oriented edges, "
             "non-orientable components, components, Euler characteristic.<br>"
             "The counts go to the log. A new layer <i>&lt;mesh&gt; defects</i> shows them as an "
             "edge mesh: singular edges <b>red</b>, boundary edges <b>green</b> (colour per "
             "vertex, quality = faces on the edge), plus one selected marker point per singular "
             "vertex (red on singular edges, magenta for pinch vertices). Optionally selects and "
             "colours the faces at the singular elements so MeshLab's selection tools can go "
             "on from there.<br>"
             "Edges are pairs of vertex indices: vertices that merely coincide are not merged "
             "(use <i>Remove Duplicate Vertices</i> first if they should be).<br>"
             "MeshBridge: edge bridges on top of OpenMesh.";
    case FP_REPAIR_SINGULAR_DEFECTS:
      return "Lossless manifold repair of the current layer, in place: every face is kept with "
             "its attributes (colour, quality, normal, wedge texture coordinates) and its place "
             "in face order; every edge ends up with at most two faces and every vertex with one "
             "fan.<br>"
             "The faces of each singular edge are paired by their angular order around the edge "
             "(faces that close a solid are paired first, a sheet between them is left over), "
             "then vertices with several fans are split; each copy carries its original's "
             "colour, quality, normal and texture coordinate. Boundary sides that can be glued "
             "back without a new singularity are stitched, and each orientable component is "
             "consistently oriented (closed ones outward). One pass is enough: the repair is "
             "idempotent.<br>"
             "Unlike <i>Repair non Manifold Edges</i> it deletes no face and does not cut every "
             "face on a singular edge loose. The repair counts go to the log.";
  }
  return "Unknown MeshBridge filter";
}

MeshFilterInterface::FilterClass FilterMeshBridgePlugin::getClass(QAction*) {
  return MeshFilterInterface::Cleaning;
}

int FilterMeshBridgePlugin::getRequirements(QAction*) {
  return MeshModel::MM_NONE;
}

int FilterMeshBridgePlugin::getPreConditions(QAction*) const {
  return MeshModel::MM_FACENUMBER;
}

int FilterMeshBridgePlugin::postCondition(QAction* action) const {
  switch (ID(action)) {
    case FP_DETECT_SINGULAR_DEFECTS:
      return MeshModel::MM_VERTFLAGSELECT | MeshModel::MM_FACEFLAGSELECT | MeshModel::MM_FACECOLOR;
    case FP_REPAIR_SINGULAR_DEFECTS:
      // Topology and vertex count change; copies of split vertices bring their colour/quality.
      return MeshModel::MM_GEOMETRY_AND_TOPOLOGY_CHANGE | MeshModel::MM_VERTCOLOR |
             MeshModel::MM_VERTQUALITY | MeshModel::MM_FACECOLOR | MeshModel::MM_FACEQUALITY |
             MeshModel::MM_WEDGTEXCOORD | MeshModel::MM_VERTTEXCOORD;
  }
  return MeshModel::MM_ALL;
}

MeshFilterInterface::FILTER_ARITY FilterMeshBridgePlugin::filterArity(QAction*) const {
  return SINGLE_MESH;
}

void FilterMeshBridgePlugin::initParameterSet(QAction* action, MeshModel&,
                                              RichParameterList& params) {
  switch (ID(action)) {
    case FP_DETECT_SINGULAR_DEFECTS:
      params.addParam(RichBool(
          kSelectFaces, true, "Select faces at singular edges and vertices",
          "Replace the current selection by the faces that have a side on a singular edge or a "
          "corner at a pinch vertex, and by the singular vertices, so that MeshLab's selection "
          "filters can work on them next."));
      params.addParam(RichBool(
          kColourFaces, false, "Colour faces at singular edges and vertices",
          "Paint those faces: red at singular edges, orange at pinch vertices. Turns on per-face "
          "colour for the layer and overwrites the colour of those faces."));
      break;
    case FP_REPAIR_SINGULAR_DEFECTS: {
      params.addParam(RichEnum(
          kPairing, 0,
          QStringList() << "Geometric (angular order around the edge)"
                        << "Combinatorial (opposite directions, in face order)",
          "Pairing of faces on singular edges",
          "How the faces on an edge with more than two faces are paired. Geometric: sort them by "
          "angle around the edge and pair neighbours that enclose the same solid; a sheet "
          "between two solids is left over; faces without a usable normal fall back to "
          "combinatorial. Combinatorial: faces that run the edge in opposite directions first, "
          "in face order, then the rest in face order."));
      params.addParam(RichBool(
          kOrient, true, "Orient components consistently",
          "Flip faces so that every orientable component is consistently oriented, closed ones "
          "outward (positive volume). Off: every face keeps its vertex order."));
      params.addParam(
          RichBool(kStitch, true, "Stitch boundary sides back",
                   "Glue sides left unpaired on the same edge back together where the result stays "
                   "manifold, so repair opens no hole that was not there."));
      params.addParam(RichBool(
          kCutNonorientable, false, "Orient non-orientable components too",
          "Also orient components that cannot be oriented (Moebius strips), cutting the fewest "
          "conflicting edges a spanning tree finds. Off: such components keep their faces' "
          "directions and each of their inconsistent edges is cut."));
      params.addParam(RichBool(
          kRemoveDuplicateFaces, false, "Remove duplicate faces",
          "Delete faces whose vertex set an earlier face has (counted in the log). Off: every "
          "face is kept."));
      params.addParam(RichBool(
          kRemoveDegenerateFaces, false, "Remove degenerate faces",
          "Delete faces that repeat a vertex (counted in the log). Off: they are kept unchanged "
          "in their place; such a face cannot be part of a manifold, so it is left as it was."));
      params.addParam(RichBool(kRemoveIsolatedVertices, false, "Remove isolated vertices",
                               "Delete vertices that no face uses. Off: they are kept."));
      params.addParam(RichBool(
          kRecomputeNormals, true, "Recompute normals",
          "Recompute face and vertex normals afterwards, as MeshLab's own cleaning filters do. "
          "Off: vertex normals are copied to split vertices and face normals of flipped faces "
          "are negated, so normals loaded from a file survive."));
      break;
    }
    default:
      break;
  }
}

bool FilterMeshBridgePlugin::applyFilter(QAction* action, MeshDocument& md,
                                         const RichParameterList& params, vcg::CallBackPos* cb) {
  if (md.mm() == nullptr) {
    errorMessage = "No current layer: open a mesh first.";
    return false;
  }
  errorMessage.clear();
  bool ok = false;
  try {
    switch (ID(action)) {
      case FP_DETECT_SINGULAR_DEFECTS:
        ok = detect(md, params, cb);
        break;
      case FP_REPAIR_SINGULAR_DEFECTS:
        ok = repair(md, params, cb);
        break;
      default:
        errorMessage = "Unknown MeshBridge filter";
        break;
    }
  } catch (const std::exception& e) {
    errorMessage = QString("%1 failed: %2").arg(filterName(action)).arg(e.what());
    ok = false;
  }
  // meshlabserver prints the log but not errorMessage: put the reason in both.
  if (!ok)
    Log(GLLogStream::WARNING, errorMessage.toStdString());
  return ok;
}

bool FilterMeshBridgePlugin::detect(MeshDocument& md, const RichParameterList& params,
                                    vcg::CallBackPos* /*cb*/) {
  MeshModel& m = *md.mm();
  if (m.cm.fn == 0) {
    errorMessage = no_faces_message(m, "Detect Singular Defects");
    return false;
  }
  mbm::CMeshSoup soup = mbm::soup_from_cmesh(m.cm);
  const mb::DefectReport report = mb::detect_defects(soup.soup);

  const bool select = params.getBool(kSelectFaces);
  const bool colour = params.getBool(kColourFaces);
  if (colour)
    m.updateDataMask(MeshModel::MM_FACECOLOR);
  const mbm::DefectSelection selection = mbm::select_defect_faces(soup, report, select, colour);
  if (select) {
    m.cm.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(m.cm));
    m.cm.sfn = int(vcg::tri::UpdateSelection<CMeshO>::FaceCount(m.cm));
  }

  // The defect layer stays behind the current one, so the next filter of a script still works
  // on the mesh itself (meshlabserver: save it with `-o file.obj -l x -m vc`).
  MeshModel* layer = md.addNewMesh("", m.label() + " defects", false);
  const mbm::DefectLayerCounts drawn = mbm::build_defect_layer(soup, report, layer->cm);
  layer->updateDataMask(MeshModel::MM_VERTCOLOR | MeshModel::MM_VERTQUALITY);
  layer->cm.Tr = m.cm.Tr;
  vcg::tri::UpdateBounding<CMeshO>::Box(layer->cm);
  layer->cm.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(layer->cm));

  std::string text = "MeshBridge defects of '" + m.label().toStdString() + "':\n";
  text += trimmed(mb::to_text(report));
  text += "\nDefect layer '" + layer->label().toStdString() +
          "': " + std::to_string(drawn.singular_edges) + " red (singular) edges, " +
          std::to_string(drawn.boundary_edges) + " green (boundary) edges, " +
          std::to_string(drawn.singular_vertex_markers) + " singular vertex markers";
  if (select || colour) {
    text += "\n" + std::string(select ? "Selected " : "Coloured ") +
            std::to_string(selection.faces) + " faces at singular edges/vertices";
    if (select)
      text += " and " + std::to_string(selection.vertices) + " singular vertices";
  }
  Log(text);
  return true;
}

bool FilterMeshBridgePlugin::repair(MeshDocument& md, const RichParameterList& params,
                                    vcg::CallBackPos* /*cb*/) {
  MeshModel& m = *md.mm();
  if (m.cm.fn == 0) {
    errorMessage = no_faces_message(m, "Repair Singular Defects");
    return false;
  }
  mb::RepairOptions options;
  options.pairing = params.getEnum(kPairing) == 1 ? mb::PairingPolicy::combinatorial
                                                  : mb::PairingPolicy::geometric;
  options.orient = params.getBool(kOrient);
  options.stitch = params.getBool(kStitch);
  options.cut_nonorientable = params.getBool(kCutNonorientable);
  options.remove_duplicate_faces = params.getBool(kRemoveDuplicateFaces);
  options.remove_degenerate_faces = params.getBool(kRemoveDegenerateFaces);
  options.remove_isolated_vertices = params.getBool(kRemoveIsolatedVertices);
  mbm::WriteBackOptions write_options;
  write_options.keep_set_aside_faces = !options.remove_degenerate_faces;
  write_options.recompute_normals = params.getBool(kRecomputeNormals);

  const mbm::CMeshSoup soup = mbm::soup_from_cmesh(m.cm);
  const mb::RepairResult result = mb::repair(soup.soup, options);
  // Throws before touching the mesh if the result does not fit; the catch in applyFilter reports
  // it.
  const mbm::WriteBackReport written = mbm::write_repaired(
      m.cm, soup, result.mesh, result.report.before.excluded_faces, write_options);

  // What MeshLab's own cleaning filters do after changing the mesh: adjacency that was in use is
  // rebuilt, border flags, bounding box and normals are recomputed, selection counts refreshed.
  const int topology = m.dataMask() & (MeshModel::MM_FACEFACETOPO | MeshModel::MM_VERTFACETOPO);
  if (topology != 0)
    m.updateDataMask(topology);
  if (m.hasDataMask(MeshModel::MM_FACEFACETOPO)) {
    vcg::tri::UpdateFlags<CMeshO>::FaceBorderFromFF(m.cm);
  } else {
    vcg::tri::UpdateFlags<CMeshO>::FaceBorderFromNone(m.cm);
  }
  vcg::tri::UpdateFlags<CMeshO>::VertexBorderFromFaceBorder(m.cm);
  if (write_options.recompute_normals) {
    m.UpdateBoxAndNormals();
  } else {
    vcg::tri::UpdateBounding<CMeshO>::Box(m.cm);
  }
  m.cm.svn = int(vcg::tri::UpdateSelection<CMeshO>::VertexCount(m.cm));
  m.cm.sfn = int(vcg::tri::UpdateSelection<CMeshO>::FaceCount(m.cm));
  m.setMeshModified(true);

  std::string text = "MeshBridge repair of '" + m.label().toStdString() + "':\n";
  text += trimmed(mb::to_text(result.report));
  text += "\nLayer now: " + std::to_string(m.cm.vn) + " vertices, " + std::to_string(m.cm.fn) +
          " faces (was " + std::to_string(written.vertices_in) + " vertices, " +
          std::to_string(written.faces_in) + " faces)";
  if (written.set_aside_faces_kept != 0) {
    text += "\nKept " + std::to_string(written.set_aside_faces_kept) +
            " degenerate faces unchanged (they repeat a vertex and cannot be manifold; "
            "'Remove degenerate faces' drops them)";
  }
  if (written.polygons_fanned != 0) {
    text += "\nTriangulated " + std::to_string(written.polygons_fanned) + " polygons (" +
            std::to_string(written.triangles_from_fans) + " extra triangles)";
  }
  Log(text);
  return true;
}
