// SPDX-License-Identifier: GPL-3.0-or-later
// The report schema (docs/report-schema.md), written with nlohmann-json. Key order is fixed by
// nlohmann::ordered_json, so equal reports give equal bytes.
#include "meshbridge/report_json.h"
#include "meshbridge/report_tree.h"

#include "meshbridge/self_intersections.h"

#include <nlohmann/json.hpp>

namespace meshbridge {

namespace {

using Json = nlohmann::ordered_json;

Json pair_list(const std::vector<VertexPair>& pairs) {
  Json list = Json::array();
  for (const VertexPair& p : pairs)
    list.push_back({p.v0, p.v1});
  return list;
}

Json read_json(const ReadInfo& info) {
  return Json{{"declared_vertices", info.declared_vertices},
              {"declared_faces", info.declared_faces},
              {"faces_kept", info.faces_kept},
              {"faces_split", info.faces_split},
              {"keyhole_polygons", info.keyhole_polygons},
              {"faces_set_aside", info.faces_set_aside},
              {"dangling_edges", info.dangling_edges},
              {"lone_points", info.lone_points},
              {"strip_joins", info.strip_joins},
              {"unknown_records", info.unknown_records},
              {"empty_records", info.empty_records},
              {"trailing_bytes", info.trailing_bytes},
              {"color_map_indices", info.color_map_indices},
              {"vertices_welded_by_position", info.vertices_welded_by_position}};
}

//! What writing the output made of the mesh (repair and batch records), when given.
void add_written(Json& out, const WrittenOutput* written) {
  if (written == nullptr)
    return;
  out["written"] = Json{{"triangles", written->triangles},
                        {"polygons_triangulated", written->polygons_triangulated},
                        {"left_out", written->left_out},
                        {"copies_moved", written->copies_moved},
                        {"separation", written->separation}};
}

Json face_pair_list(const std::vector<FacePair>& pairs) {
  Json list = Json::array();
  for (const FacePair& p : pairs)
    list.push_back({p.f0, p.f1});
  return list;
}

//! `self_intersections`: the counts of find_self_intersections(), its lists on request.
Json self_intersections_json(const SelfIntersectionReport& r, bool elements) {
  Json out{{"face_pairs", r.face_pairs.size()},
           {"faces", r.faces.size()},
           {"component_pairs", r.component_pairs.size()},
           {"degenerate_triangles", r.degenerate_triangles}};
  if (elements) {
    out["elements"] = Json{{"face_pairs", face_pair_list(r.face_pairs)},
                           {"faces", r.faces},
                           {"component_pairs", face_pair_list(r.component_pairs)}};
  }
  return out;
}

//! The counts of a detection report, then its element lists on request.
void add_defects(Json& out, const DefectReport& r, bool elements) {
  out["vertices"] = r.num_vertices;
  out["faces"] = r.num_faces_of_file();
  out["edges"] = r.num_edges;
  out["components"] = r.num_components;
  out["euler_characteristic"] = r.euler_characteristic;
  out["watertight"] = r.watertight;
  out["has_defects"] = r.has_defects();
  out["singular_edges"] = r.singular_edges.size();
  std::size_t contenders = 0;
  for (const SingularEdge& e : r.singular_edges)
    contenders += e.contenders;
  out["singular_edge_contenders"] = contenders;
  out["singular_vertices"] = r.num_singular_vertices();
  out["singular_edge_vertices"] = r.singular_edge_vertices.size();
  out["pinch_vertices"] = r.pinch_vertices.size();
  out["boundary_edges"] = r.boundary_edges.size();
  out["boundary_loops"] = r.num_boundary_loops;
  out["inconsistent_edges"] = r.inconsistent_edges.size();
  out["nonorientable_components"] = r.num_nonorientable_components;
  out["isolated_vertices"] = r.isolated_vertices.size();
  out["degenerate_faces"] = r.degenerate_faces.size();
  out["keyhole_polygons"] = r.keyhole_polygons_triangulated;
  out["faces_set_aside"] = r.num_faces_set_aside();
  out["zero_area_faces"] = r.zero_area_faces.size();
  out["duplicate_faces"] = r.duplicate_faces.size();
  if (!elements)
    return;
  Json singular = Json::array();
  for (const SingularEdge& e : r.singular_edges)
    singular.push_back(
        {{"vertices", {e.vertices.v0, e.vertices.v1}}, {"contenders", e.contenders}});
  out["elements"] = Json{{"singular_edges", std::move(singular)},
                         {"singular_edge_vertices", r.singular_edge_vertices},
                         {"pinch_vertices", r.pinch_vertices},
                         {"boundary_edges", pair_list(r.boundary_edges)},
                         {"inconsistent_edges", pair_list(r.inconsistent_edges)},
                         {"isolated_vertices", r.isolated_vertices},
                         {"degenerate_faces", r.degenerate_faces},
                         {"faces_set_aside", r.faces_set_aside},
                         {"zero_area_faces", r.zero_area_faces},
                         {"duplicate_faces", r.duplicate_faces}};
}

Json gaps_json(const CloseGapsReport& g) {
  return Json{{"tolerance", g.tolerance},
              {"vertices_welded", g.vertices_welded},
              {"largest_weld_distance", g.largest_weld_distance},
              {"automatic", g.automatic},
              {"welds_refused", g.welds_refused},
              {"welds_too_long", g.welds_too_long},
              {"t_junctions_closed", g.t_junctions_closed},
              {"t_junctions_too_wide", g.t_junctions_too_wide},
              {"sides_split", g.sides_split},
              {"welds_undone", g.welds_undone},
              {"t_junctions_undone", g.t_junctions_undone},
              {"refused_reason", g.refused_reason}};
}

Json holes_json(const FillHolesReport& h) {
  return Json{{"max_edges", h.max_edges},
              {"holes_filled", h.holes_filled},
              {"faces_added", h.faces_added},
              {"holes_left", h.holes_left},
              {"patches_refused", h.patches_refused}};
}

void add_repair(Json& out, const RepairReport& r, bool elements, const DefectReport* reread) {
  out["faces_in"] = r.faces_in;
  out["faces_out"] = r.faces_out;
  out["faces_set_aside"] = r.faces_set_aside;
  out["faces_split"] = r.faces_split;
  out["faces_added_by_split"] = r.faces_added_by_split;
  out["slits_set_aside"] = r.slits_set_aside;
  out["keyhole_polygons_triangulated"] = r.keyhole_polygons_triangulated;
  out["faces_flipped"] = r.faces_flipped;
  out["duplicate_faces_removed"] = r.duplicate_faces_removed;
  out["degenerate_faces_removed"] = r.degenerate_faces_removed;
  out["zero_area_faces_removed"] = r.zero_area_faces_removed;
  out["vertices_in"] = r.vertices_in;
  out["vertices_out"] = r.vertices_out;
  out["vertices_split"] = r.vertices_split;
  out["isolated_vertices_removed"] = r.isolated_vertices_removed;
  out["sides_cut"] = r.sides_cut;
  out["sides_cut_for_orientation"] = r.sides_cut_for_orientation;
  out["sides_cut_to_stay_manifold"] = r.sides_cut_to_stay_manifold;
  out["sides_paired_with_copies"] = r.sides_paired_with_copies;
  out["edges_split_to_stay_manifold"] = r.edges_split_to_stay_manifold;
  out["faces_given_midpoints"] = r.faces_given_midpoints;
  out["triangles_given_midpoints"] = r.triangles_given_midpoints;
  out["sides_stitched"] = r.sides_stitched;
  out["nonorientable_after_pairing"] = r.nonorientable_after_pairing;
  out["ambiguous_nested_shells"] = r.ambiguous_nested_shells;
  out["components_topology_changed"] = r.topology_changes.size();
  out["components_topology_changed_by_cuts_for_orientation"] =
      components_topology_changed_by_cuts_for_orientation(r);
  out["components_topology_changed_by_pairing_stacked_copies"] =
      components_topology_changed_by_pairing_stacked_copies(r);
  out["gaps"] = gaps_json(r.gaps);
  if (r.holes.max_edges > 0)  // only when asked for: reports of a default repair stay as they were
    out["holes"] = holes_json(r.holes);
  Json before = Json::object(), after = Json::object();
  add_defects(before, r.before, elements);
  add_defects(after, r.after, elements);
  out["before"] = std::move(before);
  out["after"] = std::move(after);
  if (reread) {
    Json again = Json::object();
    add_defects(again, *reread, elements);
    out["reread"] = std::move(again);
  }
}

Json header(const char* kind, const std::string& file) {
  return Json{{"schema_version", kReportSchemaVersion}, {"kind", kind}, {"file", file}};
}

std::string dump(const Json& json, int indent) {
  return json.dump(indent < 0 ? -1 : indent, ' ', false, Json::error_handler_t::replace);
}

Json figures(const BuildFigures& f) {
  return Json{{"vertices", f.vertices},
              {"faces_kept", f.faces_kept},
              {"faces_detached", f.faces_detached},
              {"faces_lost", f.faces_lost},
              {"boundary_edges", f.boundary_edges},
              {"components", f.components}};
}

//! Walks `json` into `visitor` (ReportVisitor's order).
void visit_json(const Json& json, ReportVisitor& visitor) {
  switch (json.type()) {
    case Json::value_t::object:
      visitor.begin_object();
      for (const auto& [name, value] : json.items()) {
        visitor.key(name);
        visit_json(value, visitor);
      }
      visitor.end_object();
      break;
    case Json::value_t::array:
      visitor.begin_array();
      for (const Json& value : json)
        visit_json(value, visitor);
      visitor.end_array();
      break;
    case Json::value_t::string:
      visitor.string(to_valid_utf8(json.get_ref<const std::string&>()));
      break;
    case Json::value_t::boolean:
      visitor.boolean(json.get<bool>());
      break;
    case Json::value_t::number_integer:
      visitor.integer(json.get<std::int64_t>());
      break;
    case Json::value_t::number_unsigned:
      visitor.unsigned_integer(json.get<std::uint64_t>());
      break;
    case Json::value_t::number_float:
      visitor.real(json.get<double>());
      break;
    default:  // null, and the binary and discarded kinds no report holds
      visitor.null_value();
      break;
  }
}

}  // namespace

struct ReportTree::Values {
  Json json;
};

ReportTree::ReportTree(std::unique_ptr<Values> values) : values_(std::move(values)) {}
ReportTree::ReportTree(ReportTree&&) noexcept = default;
ReportTree& ReportTree::operator=(ReportTree&&) noexcept = default;
ReportTree::~ReportTree() = default;

void ReportTree::visit(ReportVisitor& visitor) const {
  visit_json(values_->json, visitor);
}

std::string ReportTree::text(int indent) const {
  return dump(values_->json, indent);
}

namespace {

ReportTree tree_of(Json json) {
  return ReportTree(std::make_unique<ReportTree::Values>(ReportTree::Values{std::move(json)}));
}

}  // namespace

ReportTree check_report_tree(const std::string& file, const DefectReport& report,
                             const ReadInfo* read, const ReportJsonOptions& options,
                             const CloseGapsReport* gaps,
                             const SelfIntersectionReport* self_intersections,
                             const OrientationPreview* orientation, const RepairPreview* preview) {
  Json out = header("check", file);
  if (read)
    out["read"] = read_json(*read);
  add_defects(out, report, options.elements);
  if (gaps)
    out["gaps"] = gaps_json(*gaps);
  if (orientation != nullptr && orientation->computed) {
    out["orientation"] = Json{{"faces_flipped", orientation->faces_flipped},
                              {"ambiguous_nested_shells", orientation->ambiguous_nested_shells}};
  }
  if (preview != nullptr) {
    Json would = Json::object();
    would["changes"] = preview->changes;
    would["ran_repair"] = preview->ran_repair;
    std::string text = to_text(*preview);  // the line check prints, without its newline
    if (!text.empty() && text.back() == '\n')
      text.pop_back();
    would["text"] = std::move(text);
    add_repair(would, preview->report, false, nullptr);
    // Not what repair would change: the check's own `gaps` and counts (the input's), and the
    // result's detection, which preview_repair() does not make.
    for (const char* key : {"gaps", "before", "after", "components_before", "components_after",
                            "boundary_edges_before", "boundary_edges_after"})
      would.erase(key);
    out["repair"] = std::move(would);
  }
  if (self_intersections)
    out["self_intersections"] = self_intersections_json(*self_intersections, options.elements);
  return tree_of(std::move(out));
}

std::string check_report_json(const std::string& file, const DefectReport& report,
                              const ReadInfo* read, const ReportJsonOptions& options,
                              const CloseGapsReport* gaps,
                              const SelfIntersectionReport* self_intersections,
                              const OrientationPreview* orientation, const RepairPreview* preview) {
  return check_report_tree(file, report, read, options, gaps, self_intersections, orientation,
                           preview)
      .text(options.indent);
}

std::string check_failed_json(const std::string& file, const std::string& reason,
                              const ReportJsonOptions& options) {
  Json out = header("check", file);
  out["status"] = "failed";
  out["reason"] = reason;
  return dump(out, options.indent);
}

ReportTree repair_report_tree(const std::string& file, const std::string& output,
                              const RepairReport& report, const ReadInfo* read,
                              const ReportJsonOptions& options, const DefectReport* reread,
                              const WrittenOutput* written,
                              const SelfIntersectionReport* self_intersections) {
  Json out = header("repair", file);
  if (!output.empty())
    out["output"] = output;
  if (read)
    out["read"] = read_json(*read);
  add_repair(out, report, options.elements, reread);
  add_written(out, written);
  if (self_intersections)
    out["self_intersections"] = self_intersections_json(*self_intersections, options.elements);
  return tree_of(std::move(out));
}

std::string repair_report_json(const std::string& file, const std::string& output,
                               const RepairReport& report, const ReadInfo* read,
                               const ReportJsonOptions& options, const DefectReport* reread,
                               const WrittenOutput* written,
                               const SelfIntersectionReport* self_intersections) {
  return repair_report_tree(file, output, report, read, options, reread, written,
                            self_intersections)
      .text(options.indent);
}

std::string compare_report_json(const std::string& file, std::size_t soup_vertices,
                                std::size_t soup_faces, const BuildFigures& stock,
                                const BuildFigures& bridged, const ReportJsonOptions& options) {
  Json out = header("compare", file);
  out["vertices"] = soup_vertices;
  out["faces"] = soup_faces;
  out["stock"] = figures(stock);
  out["bridged"] = figures(bridged);
  return dump(out, options.indent);
}

std::string batch_record_json(const std::string& file, const std::string& output,
                              const char* status, const std::string& reason,
                              const RepairReport* report, const ReadInfo* read,
                              const ReportJsonOptions& options, const DefectReport* reread,
                              const WrittenOutput* written,
                              const SelfIntersectionReport* self_intersections) {
  Json out = header("batch", file);
  if (!output.empty())
    out["output"] = output;
  out["status"] = status;
  if (!reason.empty())
    out["reason"] = reason;
  if (read)
    out["read"] = read_json(*read);
  if (report) {
    add_repair(out, *report, options.elements, reread);
    add_written(out, written);
    if (self_intersections)
      out["self_intersections"] = self_intersections_json(*self_intersections, options.elements);
  }
  return dump(out, options.indent);
}

std::string to_valid_utf8(const std::string& bytes) {
  // A JSON string dumped with replacement is quoted and escaped; parse it back to get the bytes.
  return Json::parse(Json(bytes).dump(-1, ' ', false, Json::error_handler_t::replace))
      .get<std::string>();
}

}  // namespace meshbridge
