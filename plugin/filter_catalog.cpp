// SPDX-License-Identifier: GPL-3.0-or-later
#include "filter_catalog.h"

#include <stdexcept>
#include <string>
#include <utility>

namespace meshbridge::meshlab {
namespace {

const FilterText kDetect = {
    "Detect Singular Defects (Bridged Half-Edge)",
    "compute_singular_defects_bridged",
    "Finds the defects that stop a half-edge structure from holding the mesh, without changing "
    "it: <b>singular edges</b> (more than two faces on one edge, with their number of faces), "
    "<b>singular vertices</b> (on a singular edge, or pinch vertices whose faces form more than "
    "one fan), boundary edges and holes, isolated vertices, degenerate, zero-area and duplicate "
    "faces, inconsistently oriented edges, non-orientable components, components, Euler "
    "characteristic.<br>"
    "The counts go to the log (MeshLab 2022 and later also return them as the filter's result, "
    "a dictionary in pymeshlab), ending with one summary line. A new layer <i>&lt;mesh&gt; - "
    "defects</i> shows them: by default a thin tube along each singular edge (<b>red</b>) and "
    "each boundary edge (<b>green</b>), and a small marker at each singular vertex (red on "
    "singular edges, magenta for pinch vertices), sized from the bounding box and visible "
    "without changing any render setting; or, for scripts, the raw edges as an edge mesh "
    "(colour per vertex, quality = faces on the edge, one selected marker point per singular "
    "vertex). A second Detect replaces the layer; Repair removes it. The mesh's own colours "
    "are left alone. Optionally selects and colours the faces at the singular elements so "
    "MeshLab's selection tools can go on from there.<br>"
    "Edges are pairs of vertex indices: vertices that merely coincide are not merged (use "
    "<i>Remove Duplicate Vertices</i> first if they should be). The log also says what Repair's "
    "gap closing would weld and close with the given <i>Weld tolerance</i> (cracks that "
    "rounding left between sides that should meet), without moving anything.<br>"
    "MeshBridge: edge bridges on top of OpenMesh.",
};

const FilterText kRepair = {
    "Repair Singular Defects (Bridged Half-Edge)",
    "meshing_repair_singular_defects_bridged",
    "Lossless manifold repair of the current layer, in place: every face is kept with its "
    "attributes (colour, quality, normal, wedge texture coordinates) and its place in face "
    "order; every edge ends up with at most two faces and every vertex with one fan.<br>"
    "First, cracks are closed: boundary vertices closer than the <i>Weld tolerance</i> are "
    "welded (never two corners of one face) and a boundary vertex lying on another boundary "
    "side splits it (T-junction cracks); the log says how many and the largest move.<br>"
    "The faces of each singular edge are paired by their angular order around the edge (faces "
    "that close a solid are paired first, a sheet between them is left over), then vertices "
    "with several fans are split; each copy carries its original's colour, quality, normal and "
    "texture coordinate. Boundary sides that can be glued back without a new singularity are "
    "stitched, and each orientable component is consistently oriented (closed ones outward). "
    "One pass is enough: the repair is idempotent.<br>"
    "Unlike <i>Repair non Manifold Edges</i> it deletes no face and does not cut every face on "
    "a singular edge loose. The repair counts go to the log (MeshLab 2022 and later also "
    "return them as the filter's result, a dictionary in pymeshlab). When the layer came from "
    "STL or vertices were split, the log also says what an STL file of the result reads back "
    "as: STL stores no shared vertices, so its readers weld split copies together again.",
};

ParameterSpec spec(ParameterSpec::Kind kind, const char* name, const char* label,
                   std::string tooltip) {
  ParameterSpec p;
  p.kind = kind;
  p.name = name;
  p.label = label;
  p.tooltip = std::move(tooltip);
  return p;
}

ParameterSpec boolean(const char* name, bool default_value, const char* label,
                      std::string tooltip) {
  return boolean_parameter(name, default_value, label, std::move(tooltip));
}

//! The gap closing parameters, the same in both filters but for what their tooltips say.
std::vector<ParameterSpec> gap_parameters(const std::string& tolerance_tooltip,
                                          const std::string& t_junction_tooltip) {
  const CloseGapsOptions defaults;
  return {
      length_parameter(parameter::weld_tolerance, defaults.tolerance,
                       "Weld tolerance (negative = automatic, 0 = off)", tolerance_tooltip),
      boolean(parameter::close_t_junctions, defaults.close_t_junctions, "Close T-junction cracks",
              t_junction_tooltip),
  };
}

//! What both filters' weld tooltips say about the tolerance's values and rules.
const std::string kWeldRules =
    "Negative (the default, -1): automatic, 2^-21 times the largest absolute coordinate (4 to 8 "
    "float32 rounding steps there: 7.2e-5 at 150 mm), the size of the rounding differences CAD "
    "exports leave between copies of one vertex. 0: off, no welding and no T-junction "
    "splitting. Only boundary vertices weld, never two corners of one face, never two vertices "
    "at exactly the same position (a repaired mesh's split copies stay apart). Python: "
    "weld_tolerance=pymeshlab.PureValue(0.01), PureValue(0) (off) or PureValue(-1) (automatic).";

std::vector<ParameterSpec> make_detect_parameters() {
  const DetectOptions defaults;
  ParameterSpec layer_form;
  layer_form.kind = ParameterSpec::Kind::enumeration;
  layer_form.name = parameter::defect_layer;
  layer_form.enum_default = defaults.layer_form == DefectLayerForm::edges ? 1 : 0;
  layer_form.enum_values = {"Tubes", "Edges"};
  layer_form.label = "Defect layer";
  layer_form.tooltip =
      "Tubes (0): thin tubes along the defect edges and markers at singular vertices, a "
      "triangle mesh MeshLab shows in colour by default. Edges (1): the raw edges as an edge "
      "mesh (PLY/OBJ export keeps them), for scripts.";
  std::vector<ParameterSpec> specs = {
      boolean(parameter::select_faces, defaults.select_faces,
              "Select faces at singular edges and vertices",
              "Replace the current selection by the faces that have a side on a singular edge or "
              "a corner at a pinch vertex, and by the singular vertices, so that MeshLab's "
              "selection filters can work on them next."),
      boolean(parameter::color_faces, defaults.color_faces,
              "Colour faces at singular edges and vertices",
              "Paint those faces: red at singular edges, orange at pinch vertices. Turns on "
              "per-face colour for the layer and overwrites the colour of those faces."),
      layer_form,
      boolean(
          parameter::self_intersections, defaults.self_intersections,
          "Find self-intersections (violet)",
          "Also find the faces that cross or overlap another face (shells of an assembly that "
          "cross, a fold, coplanar overlap), with exact predicates: faces that only touch along "
          "a shared edge or at a shared vertex do not count, nor do the touching copies Repair "
          "makes. They are shown in the defect layer in violet (Tubes only), counted in the log "
          "and returned (self_intersections.face_pairs, .faces, .component_pairs). On by "
          "default for meshes of at most " +
              std::to_string(kSelfIntersectionsDefaultMaxFaces) +
              " faces, off above (it costs about as much again as the rest of Detect); tick it "
              "to search a larger mesh. Python: self_intersections=True. The CLI: check "
              "--self-intersections."),
  };
  const std::vector<ParameterSpec> gaps = gap_parameters(
      "Also report what Repair's gap closing would do (Detect moves no vertex): how many "
      "vertices it would weld because they lie closer than this distance (in the mesh's units), "
      "and how many T-junction cracks it would close. " +
          kWeldRules,
      "Also report how many boundary vertices lie on another boundary side (within the weld "
      "tolerance), which Repair would insert into that side so the seam stitches.");
  specs.insert(specs.end(), gaps.begin(), gaps.end());
  return specs;
}

std::vector<ParameterSpec> make_repair_parameters() {
  const RepairFilterOptions defaults;
  ParameterSpec pairing;
  pairing.kind = ParameterSpec::Kind::enumeration;
  pairing.name = parameter::pairing;
  pairing.enum_default = defaults.core.pairing == PairingPolicy::combinatorial ? 1 : 0;
  // Short labels: pymeshlab takes an enum by its label (pairing='Combinatorial') or its index.
  pairing.enum_values = {"Geometric", "Combinatorial"};
  pairing.label = "Pairing of faces on singular edges";
  pairing.tooltip =
      "How the faces on an edge with more than two faces are paired. Geometric (0): sort them by "
      "angle around the edge and pair neighbours that enclose the same solid; a sheet between "
      "two solids is left over; faces without a usable normal fall back to combinatorial. "
      "Combinatorial (1): faces that run the edge in opposite directions first, in face order, "
      "then "
      "the rest in face order.";
  std::vector<ParameterSpec> specs = {
      pairing,
      boolean(parameter::orient, defaults.core.orient, "Orient components consistently",
              "Flip faces so that every orientable component is consistently oriented, closed "
              "ones outward (positive volume). Off: every face keeps its vertex order."),
      boolean(parameter::stitch, defaults.core.stitch, "Stitch boundary sides back",
              "Glue sides left unpaired on the same edge back together where the result stays "
              "manifold, so repair opens no hole that was not there."),
      boolean(parameter::cut_nonorientable, defaults.core.cut_nonorientable,
              "Orient non-orientable components too",
              "Also orient components that cannot be oriented (Moebius strips): their faces "
              "follow a breadth-first spanning tree and the edges that disagree with it are cut "
              "(not necessarily the fewest). Off: such components keep their faces' directions "
              "and each edge whose two faces run the same way is cut (not necessarily the "
              "fewest either)."),
      boolean(parameter::remove_duplicate_faces, defaults.core.remove_duplicate_faces,
              "Remove duplicate faces",
              "Delete faces whose vertex set an earlier face has (counted in the log). Off: "
              "every face is kept."),
      boolean(parameter::remove_degenerate_faces, defaults.core.remove_degenerate_faces,
              "Remove degenerate faces",
              "Delete faces that repeat a vertex (counted in the log). Off: they are kept "
              "unchanged in their place; such a face cannot be part of a manifold, so it is "
              "left as it was."),
      boolean(parameter::remove_isolated_vertices, defaults.core.remove_isolated_vertices,
              "Remove isolated vertices", "Delete vertices that no face uses. Off: they are kept."),
      boolean(parameter::recompute_normals, defaults.recompute_normals, "Recompute normals",
              "Recompute face and vertex normals afterwards, as MeshLab's own cleaning filters "
              "do. Off: vertex normals are copied to split vertices and face normals of flipped "
              "faces are negated, so normals loaded from a file survive."),
  };
  const std::vector<ParameterSpec> gaps = gap_parameters(
      "Before pairing, weld boundary vertices that lie closer than this distance (in the mesh's "
      "units): cracks between sides that should meet close, and the log says how many vertices "
      "were welded and the largest distance one moved. " +
          kWeldRules,
      "Before pairing, a boundary vertex that lies on another boundary side (within the weld "
      "tolerance) splits that side, so both sides of a seam with an extra vertex on one side "
      "stitch (counted in the log). Off: only welding.");
  specs.insert(specs.end(), gaps.begin(), gaps.end());
  specs.push_back(integer_parameter(
      parameter::fill_holes, int(defaults.core.fill_holes.max_edges),
      "Fill holes of at most N edges (0 = off)",
      "After the repair, close every boundary loop of at most this many edges with new "
      "triangles between its own vertices (CGAL's hole triangulation, Liepa 2003), oriented "
      "like the faces around it; longer loops stay open. The log counts holes filled, faces "
      "added and holes left; the new faces come after every original face, in the default "
      "colour. 0 (the default): off, no face is added. " +
          std::to_string(kDefaultFillHolesMaxEdges) +
          " (the CLI's bare --fill-holes) closes what a broken export leaves and keeps the rims "
          "of a model that is open on purpose."));
  return specs;
}

}  // namespace

ParameterSpec boolean_parameter(const char* name, bool default_value, const char* label,
                                std::string tooltip) {
  ParameterSpec p = spec(ParameterSpec::Kind::boolean, name, label, std::move(tooltip));
  p.bool_default = default_value;
  return p;
}

ParameterSpec integer_parameter(const char* name, int default_value, const char* label,
                                std::string tooltip) {
  ParameterSpec p = spec(ParameterSpec::Kind::integer, name, label, std::move(tooltip));
  p.int_default = default_value;
  return p;
}

ParameterSpec length_parameter(const char* name, double default_value, const char* label,
                               std::string tooltip) {
  ParameterSpec p = spec(ParameterSpec::Kind::length, name, label, std::move(tooltip));
  p.length_default = default_value;
  return p;
}

CloseGapsOptions close_gaps_options(double weld_tolerance, bool close_t_junctions) {
  CloseGapsOptions options;
  options.tolerance = weld_tolerance < 0 ? kAutoWeldTolerance : weld_tolerance;
  options.float_coordinates = true;  // CMeshO holds floats
  options.close_t_junctions = close_t_junctions;
  return options;
}

std::size_t fill_holes_max_edges(int fill_holes) {
  return fill_holes > 0 ? std::size_t(fill_holes) : 0;
}

const std::vector<FilterId>& all_filters() {
  static const std::vector<FilterId> filters = {FilterId::detect, FilterId::repair};
  return filters;
}

const FilterText& filter_text(FilterId id) {
  switch (id) {
    case FilterId::detect:
      return kDetect;
    case FilterId::repair:
      return kRepair;
  }
  throw std::invalid_argument("unknown MeshBridge filter id " + std::to_string(int(id)));
}

const std::vector<ParameterSpec>& parameters(FilterId id) {
  static const std::vector<ParameterSpec> detect = make_detect_parameters();
  static const std::vector<ParameterSpec> repair = make_repair_parameters();
  switch (id) {
    case FilterId::detect:
      return detect;
    case FilterId::repair:
      return repair;
  }
  throw std::invalid_argument("unknown MeshBridge filter id " + std::to_string(int(id)));
}

std::vector<ParameterSpec> parameters(FilterId id, std::size_t faces) {
  std::vector<ParameterSpec> specs = parameters(id);
  for (ParameterSpec& p : specs) {
    if (id == FilterId::detect && std::string(p.name) == parameter::self_intersections)
      p.bool_default = self_intersections_by_default(faces);
  }
  return specs;
}

}  // namespace meshbridge::meshlab
