// SPDX-License-Identifier: GPL-3.0-or-later
//! \file module.cpp
//! `meshbridge._core`: the compiled half of the Python package. The public, documented API is the
//! pure-Python layer in python/meshbridge/__init__.py; this module is its thin adapter to the
//! core. Every call that reads, repairs, checks or writes releases the GIL.

#include "numpy_soup.h"
#include "py_file_job.h"
#include "py_results.h"
#include "py_soup.h"

#include "meshbridge/detect_defects.h"
#include "meshbridge/errors.h"
#include "meshbridge/io.h"
#include "meshbridge/preview_repair.h"
#include "meshbridge/read_accounting.h"
#include "meshbridge/repair.h"
#include "meshbridge/self_intersections.h"
#include "meshbridge/stl_round_trip.h"
#include "meshbridge/validate.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cctype>
#include <chrono>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <tuple>

namespace py = pybind11;
using namespace meshbridge;
using namespace meshbridge::python;

namespace {

PyObject* new_exception(py::module_& m, const char* name, py::handle base1, py::handle base2,
                        const char* doc) {
  const std::string qualified = std::string("meshbridge.") + name;
  py::tuple bases = py::make_tuple(base1, base2);
  PyObject* type = PyErr_NewExceptionWithDoc(qualified.c_str(), doc, bases.ptr(), nullptr);
  if (type == nullptr)
    throw py::error_already_set();
  m.add_object(name, py::handle(type));
  return type;
}

//! Adds Error and its subclasses InvalidMeshError (also a ValueError), ReadError and WriteError
//! (also OSErrors), and translates the core's exceptions into them.
void bind_errors(py::module_& m) {
  // Exceptions: every message names the offending file, face, corner or vertex.
  PyObject* base = PyErr_NewExceptionWithDoc(
      "meshbridge.Error", "Base class of MeshBridge's errors.", PyExc_Exception, nullptr);
  m.add_object("Error", py::handle(base));
  static PyObject* invalid =
      new_exception(m, "InvalidMeshError", base, PyExc_ValueError,
                    "Vertices or faces that violate a precondition: a wrong shape or dtype, an "
                    "index out of range or negative, a polygon with fewer than 3 corners, a "
                    "non-finite coordinate. The message names the face, corner or vertex.");
  static PyObject* read_error = new_exception(
      m, "ReadError", base, PyExc_OSError,
      "A mesh file that cannot be read: missing, unreadable, empty, unknown format, malformed.");
  static PyObject* write_error =
      new_exception(m, "WriteError", base, PyExc_OSError,
                    "A mesh file that cannot be written; the previous file is left untouched.");
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p)
        std::rethrow_exception(p);
    } catch (const InvalidSoupError& e) {
      PyErr_SetString(invalid, e.what());
    } catch (const ReadError& e) {
      PyErr_SetString(read_error, e.what());
    } catch (const WriteError& e) {
      PyErr_SetString(write_error, e.what());
    }
  });
}

//! Adds PairingPolicy, AmbiguousNesting, RepairOptions (gap closing and hole filling flattened
//! into it) and the constants AUTO_WELD_TOLERANCE, DEFAULT_FILL_HOLES_MAX_EDGES, HAS_HOLE_FILLING.
void bind_repair_options(py::module_& m) {
  py::enum_<PairingPolicy>(m, "PairingPolicy")
      .value("geometric", PairingPolicy::geometric)
      .value("combinatorial", PairingPolicy::combinatorial);

  py::enum_<AmbiguousNesting>(m, "AmbiguousNesting")
      .value("material", AmbiguousNesting::material)
      .value("cavity", AmbiguousNesting::cavity);

  py::class_<RepairOptions>(m, "RepairOptions")
      .def(py::init<>())
      .def_readwrite("pairing", &RepairOptions::pairing)
      .def_readwrite("orient", &RepairOptions::orient)
      .def_readwrite("cut_nonorientable", &RepairOptions::cut_nonorientable)
      .def_readwrite("stitch", &RepairOptions::stitch)
      .def_readwrite("remove_duplicate_faces", &RepairOptions::remove_duplicate_faces)
      .def_readwrite("remove_degenerate_faces", &RepairOptions::remove_degenerate_faces)
      .def_readwrite("remove_zero_area_faces", &RepairOptions::remove_zero_area_faces)
      .def_readwrite("remove_isolated_vertices", &RepairOptions::remove_isolated_vertices)
      .def_readwrite("detect_before_after", &RepairOptions::detect_before_after)
      .def_readwrite("nested_shells", &RepairOptions::nested_shells)
      // FillHolesOptions::max_edges, flattened: 0 = off.
      .def_property(
          "fill_holes", [](const RepairOptions& o) { return o.fill_holes.max_edges; },
          [](RepairOptions& o, std::size_t max_edges) { o.fill_holes.max_edges = max_edges; })
      // CloseGapsOptions, flattened: the tolerance (kAutoWeldTolerance = automatic, 0 = off).
      .def_property(
          "weld", [](const RepairOptions& o) { return o.close_gaps.tolerance; },
          [](RepairOptions& o, double tolerance) { o.close_gaps.tolerance = tolerance; })
      .def_property(
          "close_t_junctions",
          [](const RepairOptions& o) { return o.close_gaps.close_t_junctions; },
          [](RepairOptions& o, bool close) { o.close_gaps.close_t_junctions = close; });
  m.attr("AUTO_WELD_TOLERANCE") = kAutoWeldTolerance;
  m.attr("DEFAULT_FILL_HOLES_MAX_EDGES") = kDefaultFillHolesMaxEdges;
  m.attr("HAS_HOLE_FILLING") = has_hole_filling();
}

//! Writes `soup` to `path` (meshbridge.write): see the docstring bound below. Returns (singular
//! edges, singular vertices) of the file as an STL reader gets it back, vertices moved apart and
//! the distance. \throws std::invalid_argument for a `vertex_origin` of the wrong shape or size
std::tuple<std::size_t, std::size_t, std::size_t, double> write_soup(const std::string& path,
                                                                     const PySoup& soup,
                                                                     py::object vertex_origin) {
  std::tuple<std::size_t, std::size_t, std::size_t, double> written{0, 0, 0, 0.0};
  std::optional<std::vector<Index>> origins;
  if (!vertex_origin.is_none()) {  // -1 (an added vertex) becomes kNoIndex
    const auto array = py::array_t<std::int64_t, py::array::forcecast>::ensure(vertex_origin);
    if (!array || array.ndim() != 1)
      throw std::invalid_argument("write: vertex_origin must be a 1-D array of integers");
    origins.emplace(static_cast<std::size_t>(array.size()));
    const auto values = array.unchecked<1>();
    for (py::ssize_t i = 0; i < array.size(); ++i)
      (*origins)[i] = values(i) < 0 ? kNoIndex : static_cast<Index>(values(i));
  }
  {
    py::gil_scoped_release release;
    IndexedMesh mesh;
    mesh.soup = soup.soup;
    const bool stl = mesh_format(path) == MeshFormat::stl;
    if (stl && origins) {  // a repair result: its split vertex copies moved apart
      if (origins->size() != mesh.soup.num_vertices()) {
        throw std::invalid_argument("write: vertex_origin has " + std::to_string(origins->size()) +
                                    " entries for " + std::to_string(mesh.soup.num_vertices()) +
                                    " vertices");
      }
      mesh.vertex_origin = std::move(*origins);
      const StlSeparation separated = separate_copies_for_stl(mesh);
      std::get<2>(written) = separated.vertices_moved;
      std::get<3>(written) = separated.distance;
    }
    write_mesh(path, mesh);
    if (stl) {
      // What every STL reader gets back: positions welded, split copies merged again.
      const DefectReport again = detect_defects(stl_round_trip(mesh.soup));
      std::get<0>(written) = again.singular_edges.size();
      std::get<1>(written) = again.num_singular_vertices();
    }
  }
  return written;
}

//! Adds read, write, check, repair and _repair_seconds: the calls on a Soup (GIL released).
void bind_soup_calls(py::module_& m) {
  m.def(
      "read",
      [](const std::string& path) {
        auto soup = std::make_shared<PySoup>();
        {
          py::gil_scoped_release release;
          MeshAttributes attributes;
          soup->soup = read_soup(path, &soup->info, &attributes);
          soup->path = path;
          soup->not_held = describe_not_held(attributes);
        }
        return soup;
      },
      py::arg("path"));

  m.def(
      "write", &write_soup, py::arg("path"), py::arg("soup"), py::arg("vertex_origin") = py::none(),
      "Writes `soup` (positions and polygons only: a Soup holds no colours, groups or texture "
      "coordinates, so a file read and written back this way loses them; meshbridge.batch and the "
      "CLI carry them). For STL with `vertex_origin` (a repair's, one input vertex per vertex, "
      "-1 for added ones) the copies of split vertices are moved apart first "
      "(separate_copies_for_stl). Returns (singular edges, singular vertices) of the file as an "
      "STL reader gets it back ((0, 0) for other formats), vertices moved and their distance.");

  // With `forecast` (repair options: their weld and nested_shells, as check's --weld and
  // --nested-shells) also `gaps`, `orientation` and `repair`, as `meshbridge check --json`.
  m.def(
      "check",
      [](const PySoup& soup, bool elements, bool self_intersections,
         std::optional<RepairOptions> forecast) {
        std::optional<ReportTree> tree;
        {
          py::gil_scoped_release release;
          validate_soup(soup.soup);
          const ReadInfo* read = soup.path.empty() ? nullptr : &soup.info;
          OrientationPreview orientation;
          DefectReport report;
          std::optional<RepairPreview> preview;
          if (forecast) {  // detection and forecast in one pass, as `meshbridge check`
            forecast->close_gaps.float_coordinates = soup.info.float_coordinates;
            SoupCheck checked = check_soup(soup.soup, *forecast);
            report = std::move(checked.report);
            orientation = checked.orientation;
            preview = std::move(checked.preview);
          } else {
            report = detect_defects(soup.soup);
          }
          if (read != nullptr)
            count_records_without_corners(soup.info, report);
          CloseGapsReport gaps;
          if (forecast) {
            gaps = preview->ran_repair
                       ? preview->report.gaps
                       : preview_close_gaps(soup.soup, forecast->close_gaps, &report);
          }
          std::unique_ptr<SelfIntersectionReport> crossings;
          if (self_intersections)
            crossings =
                std::make_unique<SelfIntersectionReport>(find_self_intersections(soup.soup));
          tree.emplace(check_tree(soup.path, report, read, elements, crossings.get(),
                                  forecast ? &gaps : nullptr, forecast ? &orientation : nullptr,
                                  preview ? &*preview : nullptr));
        }
        return to_dict(*tree);
      },
      py::arg("soup"), py::arg("elements") = false, py::arg("self_intersections") = false,
      py::arg("forecast") = py::none());

  m.def(
      "repair",
      [](const PySoup& soup, const RepairOptions& options, bool elements, bool self_intersections) {
        std::unique_ptr<RepairResult> result;
        std::optional<ReportTree> tree;
        {
          py::gil_scoped_release release;
          RepairOptions file_options = options;
          file_options.close_gaps.float_coordinates = soup.info.float_coordinates;
          result = std::make_unique<RepairResult>(repair(soup.soup, file_options));
          if (!soup.path.empty())
            count_records_without_corners(soup.info, result->report);
          std::unique_ptr<SelfIntersectionReport> crossings;  // of the result, as the CLI's
          if (self_intersections) {
            crossings = std::make_unique<SelfIntersectionReport>(
                find_self_intersections(result->mesh.soup));
          }
          tree.emplace(repair_tree(soup.path, result->report,
                                   soup.path.empty() ? nullptr : &soup.info, elements,
                                   crossings.get()));
        }
        return repair_result_tuple(std::move(result), soup.soup, *tree);
      },
      py::arg("soup"), py::arg("options"), py::arg("elements") = false,
      py::arg("self_intersections") = false);

  // For python/bench/call_overhead.py: the C++ repair alone, timed in C++ (no conversion, no
  // report JSON), to set the Python call's total against.
  m.def(
      "_repair_seconds",
      [](const PySoup& soup, const RepairOptions& options) {
        py::gil_scoped_release release;
        const auto start = std::chrono::steady_clock::now();
        const RepairResult result = repair(soup.soup, options);
        const auto stop = std::chrono::steady_clock::now();
        return std::chrono::duration<double>(stop - start).count();
      },
      py::arg("soup"), py::arg("options"));
}

}  // namespace

PYBIND11_MODULE(_core, m) {
  m.doc() = "Compiled core of meshbridge (use the functions of the meshbridge package).";
  bind_errors(m);
  bind_repair_options(m);
  bind_soup(m);
  bind_soup_calls(m);
  bind_file_job(m);
}
