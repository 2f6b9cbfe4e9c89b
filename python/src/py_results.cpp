// SPDX-License-Identifier: GPL-3.0-or-later
#include "py_results.h"

#include "numpy_soup.h"

#include <utility>
#include <vector>

namespace meshbridge::python {

namespace {

//! Builds Python values from a report tree: a stack of the open dicts and lists, and the key
//! the next value of the innermost dict goes under.
class DictBuilder final : public ReportVisitor {
 public:
  void begin_object() override { open(py::dict()); }
  void end_object() override { close(); }
  void begin_array() override { open(py::list()); }
  void end_array() override { close(); }
  void key(std::string_view name) override { key_ = py::str(name.data(), name.size()); }
  void null_value() override { add(py::none()); }
  void boolean(bool value) override { add(py::bool_(value)); }
  void integer(std::int64_t value) override { add(py::int_(value)); }
  void unsigned_integer(std::uint64_t value) override { add(py::int_(value)); }
  void real(double value) override { add(py::float_(value)); }
  void string(std::string_view value) override { add(py::str(value.data(), value.size())); }

  //! The finished top-level object.
  py::dict result() const { return py::reinterpret_borrow<py::dict>(root_); }

 private:
  void open(py::object container) {
    add(container);
    open_.push_back(std::move(container));
  }
  void close() { open_.pop_back(); }
  void add(const py::object& value) {
    if (open_.empty()) {
      root_ = value;
    } else if (py::isinstance<py::list>(open_.back())) {
      py::reinterpret_borrow<py::list>(open_.back()).append(value);
    } else {
      open_.back()[key_] = value;
    }
  }

  std::vector<py::object> open_;
  py::object root_;
  py::str key_;
};

}  // namespace

ReportTree check_tree(const std::string& file, const DefectReport& report, const ReadInfo* read,
                      bool elements, const SelfIntersectionReport* self_intersections,
                      const CloseGapsReport* gaps, const OrientationPreview* orientation,
                      const RepairPreview* preview) {
  ReportJsonOptions options;
  options.elements = elements;
  return check_report_tree(file, report, read, options, gaps, self_intersections, orientation,
                           preview);
}

ReportTree repair_tree(const std::string& file, const RepairReport& report, const ReadInfo* read,
                       bool elements, const SelfIntersectionReport* self_intersections) {
  ReportJsonOptions options;
  options.elements = elements;
  return repair_report_tree(file, "", report, read, options, nullptr, nullptr, self_intersections);
}

py::dict to_dict(const ReportTree& tree) {
  DictBuilder builder;
  tree.visit(builder);
  return builder.result();
}

py::tuple repair_result_tuple(std::unique_ptr<RepairResult> result, const Soup& input,
                              const ReportTree& report) {
  auto mesh = std::make_unique<IndexedMesh>(std::move(result->mesh));
  result.reset();  // the reports' element lists are in the tree now
  const IndexedMesh& m = *mesh;
  const py::capsule owner = owner_capsule(std::move(mesh));
  return py::make_tuple(positions_array(m.soup.positions, owner, true),
                        faces_object(m.soup, owner, true), to_dict(report),
                        index_array(m.vertex_origin, input.num_vertices(), owner, true),
                        index_array(m.face_origin, input.num_faces(), owner, true),
                        index_array(m.corner_origin, input.num_corners(), owner, true));
}

}  // namespace meshbridge::python
