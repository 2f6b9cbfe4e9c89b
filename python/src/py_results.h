// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file py_results.h
//! Reports as Python dicts (built from the core's report tree: the keys and order of the CLI's
//! JSON, one source of truth, with no text in between) and repair results as numpy arrays that
//! own the repaired mesh (no copy).

#include "meshbridge/defect_report.h"
#include "meshbridge/io.h"
#include "meshbridge/preview_repair.h"
#include "meshbridge/repair.h"
#include "meshbridge/report_tree.h"
#include "meshbridge/self_intersections.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

namespace meshbridge::python {

namespace py = pybind11;

//! The check report of `meshbridge check --json` (report_json.h) for `report`; `file` empty for
//! arrays, `read` null when the soup did not come from a file. Element lists only with
//! `elements`; `self_intersections`, `gaps`, `orientation` and `preview` add their objects when
//! not null (`gaps`, `orientation`, `repair`). Needs no GIL.
ReportTree check_tree(const std::string& file, const DefectReport& report, const ReadInfo* read,
                      bool elements, const SelfIntersectionReport* self_intersections = nullptr,
                      const CloseGapsReport* gaps = nullptr,
                      const OrientationPreview* orientation = nullptr,
                      const RepairPreview* preview = nullptr);

//! The repair report of `meshbridge repair --report`, same conventions as check_tree; with
//! `self_intersections` (those of the result) its `self_intersections` object.
ReportTree repair_tree(const std::string& file, const RepairReport& report, const ReadInfo* read,
                       bool elements, const SelfIntersectionReport* self_intersections = nullptr);

//! `tree` as Python values: objects as dicts (keys in the JSON's order), arrays as lists, counts
//! as ints, strings as str; equal to json.loads() of its text. Needs the GIL.
py::dict to_dict(const ReportTree& tree);

//! `(vertices, faces, report, vertex_origin, face_origin, corner_origin)`: the arrays view the
//! result's mesh, which they keep alive; `input` gives the bounds of the origin indices; `report`
//! is to_dict(`report`).
py::tuple repair_result_tuple(std::unique_ptr<RepairResult> result, const Soup& input,
                              const ReportTree& report);

}  // namespace meshbridge::python
