// SPDX-License-Identifier: GPL-3.0-or-later
#include "py_results.h"

#include "numpy_soup.h"

#include "meshbridge/report_json.h"

namespace meshbridge::python {

std::string check_json(const std::string& file, const DefectReport& report, const ReadInfo* read,
                       bool elements, const SelfIntersectionReport* self_intersections) {
  ReportJsonOptions options;
  options.elements = elements;
  return check_report_json(file, report, read, options, nullptr, self_intersections);
}

std::string repair_json(const std::string& file, const RepairReport& report, const ReadInfo* read,
                        bool elements) {
  ReportJsonOptions options;
  options.elements = elements;
  return repair_report_json(file, "", report, read, options);
}

py::tuple repair_result_tuple(std::unique_ptr<RepairResult> result, const Soup& input,
                              std::string report_json) {
  auto mesh = std::make_unique<IndexedMesh>(std::move(result->mesh));
  result.reset();  // the reports' element lists are in the JSON now
  const IndexedMesh& m = *mesh;
  const py::capsule owner = owner_capsule(std::move(mesh));
  return py::make_tuple(positions_array(m.soup.positions, owner, true),
                        faces_object(m.soup, owner, true), py::str(report_json),
                        index_array(m.vertex_origin, input.num_vertices(), owner, true),
                        index_array(m.face_origin, input.num_faces(), owner, true),
                        index_array(m.corner_origin, input.num_corners(), owner, true));
}

}  // namespace meshbridge::python
