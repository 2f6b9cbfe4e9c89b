// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file report_json.h
//! The one JSON form of MeshBridge's reports (schema in docs/report-schema.md and
//! docs/report-schema.json). `check --json`, `repair --report`, `batch --json`, the Python
//! module and the MeshLab plugin's result maps all use these keys.
//!
//! Every object starts with `schema_version` and `kind`, then `file`. Counts come by default;
//! element lists (vertex indices, vertex pairs) only on request, under `elements`. The JSON is
//! written by nlohmann-json inside the core; nothing of it is in this header.
//!
//! Strings (paths, error messages) are bytes on Linux and need not be UTF-8. Valid UTF-8 passes
//! through unchanged; every byte that is not part of a valid UTF-8 sequence becomes U+FFFD (the
//! replacement character), so the output is always valid JSON in UTF-8.

#include "meshbridge/defect_report.h"
#include "meshbridge/io.h"
#include "meshbridge/preview_repair.h"
#include "meshbridge/repair.h"
#include "meshbridge/self_intersections.h"
#include "meshbridge/stock_build.h"

#include <cstddef>
#include <string>
#include <vector>

namespace meshbridge {

//! Version of the report schema; raised whenever a key is renamed, removed or changes meaning.
constexpr int kReportSchemaVersion = 3;

//! How a report is written.
struct ReportJsonOptions {
  //! Add the element lists under `elements` (default false: counts only). On a 5M-triangle
  //! model with many defects the lists are ~100 MB; the counts are under 2 kB.
  bool elements = false;
  //! Spaces per indentation level; negative (default -1) writes one line (JSON Lines).
  int indent = -1;
};

//! `{"schema_version":1,"kind":"check","file":...,"read":{...},<counts>[,"gaps":{...}]
//! [,"elements":{...}]}`. `file` is written as given. `read` (the read accounting of ReadInfo)
//! is left out when `read` is null; `gaps` (what repair's gap closing would do, the keys of a
//! repair report's `gaps`) when `gaps` is null; `self_intersections` (the counts of
//! find_self_intersections(), its lists under its own `elements` on request) when that is null;
//! `orientation` (a watertight file's OrientationPreview) when it is null or not computed;
//! `repair` (what repair would do: `changes`, `ran_repair`, the counts of a repair report
//! without `gaps` and `before`, and `after`) when `preview` is null.
std::string check_report_json(const std::string& file, const DefectReport& report,
                              const ReadInfo* read = nullptr, const ReportJsonOptions& options = {},
                              const CloseGapsReport* gaps = nullptr,
                              const SelfIntersectionReport* self_intersections = nullptr,
                              const OrientationPreview* orientation = nullptr,
                              const RepairPreview* preview = nullptr);

//! `{"schema_version":1,"kind":"check","file":...,"status":"failed","reason":...}`: what
//! `check --json` prints instead of the report when FILE cannot be checked (`reason`: the error
//! message, as on stderr; `status` and `reason` as in a failed batch record).
std::string check_failed_json(const std::string& file, const std::string& reason,
                              const ReportJsonOptions& options = {});

//! `{"schema_version":1,"kind":"repair","file":...,"output":...,"read":{...},<repair counts>,
//! "gaps":{<gap closing counts>},"before":{<check counts>},"after":{<check counts>}
//! [,"reread":{<check counts>}]
//! [,"written":{"triangles":N,"polygons_triangulated":N,"left_out":[...]}]}`; with
//! `options.elements` the `before`, `after` (and `reread`) objects carry their `elements`. `output`
//! is left out when empty, `read` when null. `reread` (the written file as a reader gets it back:
//! STL welds split vertex copies by position) is written exactly when `reread` is not null,
//! `written` exactly when `written` is not null; `self_intersections` (those of the repaired mesh
//! as written, the object of check_report_json()) exactly when it is not null.
std::string repair_report_json(const std::string& file, const std::string& output,
                               const RepairReport& report, const ReadInfo* read = nullptr,
                               const ReportJsonOptions& options = {},
                               const DefectReport* reread = nullptr,
                               const WrittenOutput* written = nullptr,
                               const SelfIntersectionReport* self_intersections = nullptr);

//! What one way of building an OpenMesh mesh from a soup kept (for `compare`).
struct BuildFigures {
  std::size_t vertices = 0;        //!< vertices of the built mesh
  std::size_t faces_kept = 0;      //!< faces present in it
  std::size_t faces_detached = 0;  //!< faces re-added on duplicated vertices
  std::size_t faces_lost = 0;      //!< faces not in it at all
  std::size_t boundary_edges = 0;  //!< edges of the built mesh with one face
  std::size_t components = 0;      //!< connected through shared edges of the built mesh
};

//! `{"schema_version":1,"kind":"compare","file":...,"vertices":N,"faces":N,
//! "stock":{<BuildFigures>},"bridged":{<BuildFigures>}}` where vertices and faces are the soup's.
std::string compare_report_json(const std::string& file, std::size_t soup_vertices,
                                std::size_t soup_faces, const BuildFigures& stock,
                                const BuildFigures& bridged, const ReportJsonOptions& options = {});

//! One line of `batch --json`: `{"schema_version":1,"kind":"batch","file":...,"output":...,
//! "status":"clean"|"repaired"|"failed"|"skipped"[,"reason":...][,"read":{...}]
//! [,<repair
//! counts>,"gaps":{...},"before":{...},"after":{...}[,"reread":{...}][,"written":{...}]
//! [,"self_intersections":{...}]]}`. The repair counts, `gaps` and `before`/`after` are those of
//! repair_report_json() and are present exactly when `report` is not null (`reread`, `written`
//! and `self_intersections`, the object of check_report_json() for the output as written, when
//! they are not null too); `reason` (why it failed or was skipped) exactly when it is not empty;
//! `output` when not empty.
std::string batch_record_json(const std::string& file, const std::string& output,
                              const char* status, const std::string& reason,
                              const RepairReport* report, const ReadInfo* read = nullptr,
                              const ReportJsonOptions& options = {},
                              const DefectReport* reread = nullptr,
                              const WrittenOutput* written = nullptr,
                              const SelfIntersectionReport* self_intersections = nullptr);

//! Converts a string of bytes to valid UTF-8 as described above (U+FFFD per invalid byte).
std::string to_valid_utf8(const std::string& bytes);

}  // namespace meshbridge
