// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file py_results.h
//! Reports as JSON text (the CLI's schema, one source of truth) and repair results as numpy
//! arrays that own the repaired mesh (no copy).

#include "meshbridge/defect_report.h"
#include "meshbridge/io.h"
#include "meshbridge/repair.h"
#include "meshbridge/self_intersections.h"

#include <pybind11/pybind11.h>

#include <memory>
#include <string>

namespace meshbridge::python {

namespace py = pybind11;

//! The check report of `meshbridge check --json` (report_json.h, one line) for `report`; `file`
//! empty for arrays, `read` null when the soup did not come from a file. Element lists only with
//! `elements`; `self_intersections` adds its object when not null.
std::string check_json(const std::string& file, const DefectReport& report, const ReadInfo* read,
                       bool elements, const SelfIntersectionReport* self_intersections = nullptr);

//! The repair report of `meshbridge repair --report`, same conventions as check_json.
std::string repair_json(const std::string& file, const RepairReport& report, const ReadInfo* read,
                        bool elements);

//! `(vertices, faces, report_json, vertex_origin, face_origin, corner_origin)`: the arrays view
//! the result's mesh, which they keep alive; `input` gives the bounds of the origin indices.
py::tuple repair_result_tuple(std::unique_ptr<RepairResult> result, const Soup& input,
                              std::string report_json);

}  // namespace meshbridge::python
