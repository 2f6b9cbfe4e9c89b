// SPDX-License-Identifier: GPL-3.0-or-later
#include "py_file_job.h"

#include "meshbridge/batch_log.h"
#include "meshbridge/batch_warnings.h"
#include "meshbridge/file_job.h"

#include <pybind11/stl.h>

#include <string>
#include <tuple>
#include <vector>

namespace meshbridge::python {

namespace py = pybind11;

void bind_file_job(py::module_& m) {
  py::class_<FileJobOptions>(m, "FileJobOptions")
      .def(py::init<>())
      .def_readwrite("repair", &FileJobOptions::repair)
      .def_readwrite("format", &FileJobOptions::format)
      .def_readwrite("resume", &FileJobOptions::resume)
      .def_readwrite("elements", &FileJobOptions::elements)
      .def_readwrite("separate_stl_copies", &FileJobOptions::separate_stl_copies)
      .def_readwrite("print", &FileJobOptions::print)
      .def_readwrite("print_keeps_weld", &FileJobOptions::print_keeps_weld)
      .def_readwrite("print_keeps_fill_holes", &FileJobOptions::print_keeps_fill_holes)
      .def_readwrite("self_intersections", &FileJobOptions::self_intersections);

  // (jobs, unreadable): jobs as (input, output, name, output_name) sorted by name, unreadable
  // entries as (name, reason). std::invalid_argument (bad folders, format) becomes ValueError.
  m.def(
      "plan_batch",
      [](const std::string& in_dir, const std::string& out_dir, const FileJobOptions& options,
         bool in_place) {
        BatchPlan plan;
        {
          py::gil_scoped_release release;
          plan = plan_batch(in_dir, out_dir, options, in_place);
        }
        std::vector<std::tuple<std::string, std::string, std::string, std::string>> jobs;
        jobs.reserve(plan.jobs.size());
        for (FileJob& job : plan.jobs) {
          jobs.emplace_back(std::move(job.input), std::move(job.output), std::move(job.name),
                            std::move(job.output_name));
        }
        std::vector<std::pair<std::string, std::string>> unreadable;
        for (BatchPlan::Unreadable& entry : plan.unreadable)
          unreadable.emplace_back(std::move(entry.name), std::move(entry.reason));
        return std::make_pair(std::move(jobs), std::move(unreadable));
      },
      py::arg("in_dir"), py::arg("out_dir"), py::arg("options"), py::arg("in_place") = false);

  // (status, reason, record, warnings): never raises for a bad file (its record says `failed`);
  // warnings as batch_warning_lines.
  m.def(
      "run_file_job",
      [](const std::string& input, const std::string& output, const std::string& name,
         const std::string& output_name, const FileJobOptions& options) {
        FileJobResult result;
        {
          py::gil_scoped_release release;
          result = run_file_job(FileJob{input, output, name, output_name}, options);
        }
        std::string warnings =
            batch_warning_lines(result, FileJob{input, output, name, output_name});
        return std::make_tuple(std::string(to_string(result.status)), std::move(result.reason),
                               std::move(result.record), std::move(warnings));
      },
      py::arg("input"), py::arg("output"), py::arg("name"), py::arg("output_name"),
      py::arg("options"));

  m.def(
      "skipped_record",
      [](const std::string& name, const std::string& reason) {
        return skipped_record(BatchPlan::Unreadable{name, reason});
      },
      py::arg("name"), py::arg("reason"));

  // The batch log (batch_log.h): a job as (input, output, name, output_name).
  using JobTuple = std::tuple<std::string, std::string, std::string, std::string>;
  const auto to_job = [](const JobTuple& t) {
    return FileJob{std::get<0>(t), std::get<1>(t), std::get<2>(t), std::get<3>(t)};
  };
  m.def(
      "batch_log_line",
      [to_job](const std::string& record, const JobTuple& job, const FileJobOptions& options) {
        return batch_log_line(record, to_job(job), options);
      },
      py::arg("record"), py::arg("job"), py::arg("options"));
  m.def("record_of_log_line", &record_of_log_line, py::arg("line"));
  m.def("batch_options_text", &batch_options_text, py::arg("options"));
  // (done, why): whether a rerun may skip the job, else what changed.
  m.def(
      "is_done_in_log",
      [to_job](const std::string& line, const JobTuple& job, const FileJobOptions& options) {
        std::string why;
        const bool done = is_done_in_log(line, to_job(job), options, &why);
        return std::make_pair(done, why);
      },
      py::arg("line"), py::arg("job"), py::arg("options"));
  m.def("write_batch_log", &write_batch_log, py::arg("path"), py::arg("lines"));
  m.def("harmless_warning_kind", &harmless_warning_kind, py::arg("line"));

  // The `failed` record of a job that ended without a result of its own (its worker died).
  m.def(
      "failed_record",
      [](const std::string& name, const std::string& output_name, const std::string& reason) {
        return batch_record_json(name, output_name, to_string(FileStatus::failed), reason, nullptr);
      },
      py::arg("name"), py::arg("output_name"), py::arg("reason"));
}

}  // namespace meshbridge::python
