// SPDX-License-Identifier: GPL-3.0-or-later
//! \file py_soup.cpp
//! The Soup class of meshbridge._core (see py_soup.h).

#include "py_soup.h"

#include "numpy_soup.h"

#include "meshbridge/errors.h"
#include "meshbridge/validate.h"

#include <pybind11/stl.h>

#include <cstring>
#include <memory>

namespace py = pybind11;

namespace meshbridge::python {
namespace {

//! The keys of the reports' "read" object (report_json.h), or None for a soup from arrays.
py::object read_info_dict(const PySoup& s) {
  if (s.path.empty())
    return py::none();
  py::dict info;
  info["declared_vertices"] = s.info.declared_vertices;
  info["declared_faces"] = s.info.declared_faces;
  info["faces_kept"] = s.info.faces_kept;
  info["faces_split"] = s.info.faces_split;
  info["keyhole_polygons"] = s.info.keyhole_polygons;
  info["faces_set_aside"] = s.info.faces_set_aside;
  info["dangling_edges"] = s.info.dangling_edges;
  info["lone_points"] = s.info.lone_points;
  info["strip_joins"] = s.info.strip_joins;
  info["unknown_records"] = s.info.unknown_records;
  info["empty_records"] = s.info.empty_records;
  info["trailing_bytes"] = s.info.trailing_bytes;
  info["color_map_indices"] = s.info.color_map_indices;
  info["vertices_welded_by_position"] = s.info.vertices_welded_by_position;
  return std::move(info);
}

template <class T>
py::bytes raw_bytes(const std::vector<T>& values) {
  return py::bytes(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

//! (positions, corner_vertices, face_begin as raw bytes, path, the 16 values of ReadInfo,
//! not_held). Every ReadInfo value counts: check and repair read faces_without_corners, and repair
//! takes float_coordinates for the weld tolerance.
py::tuple pickle_state(const PySoup& s) {
  const ReadInfo& i = s.info;
  return py::make_tuple(
      raw_bytes(s.soup.positions), raw_bytes(s.soup.corner_vertices), raw_bytes(s.soup.face_begin),
      s.path,
      py::make_tuple(i.declared_vertices, i.declared_faces, i.faces_kept, i.faces_split,
                     i.faces_set_aside, i.dangling_edges, i.lone_points, i.strip_joins,
                     i.unknown_records, i.color_map_indices, i.empty_records, i.trailing_bytes,
                     i.faces_without_corners, i.vertices_welded_by_position,
                     std::size_t(i.float_coordinates ? 1 : 0), i.keyhole_polygons),
      s.not_held);
}

template <class T>
void unpack_bytes(const py::handle& item, std::vector<T>& values) {
  const std::string bytes = item.cast<std::string>();
  if (bytes.size() % sizeof(T) != 0)
    throw InvalidSoupError("Soup: bad pickle state");
  values.resize(bytes.size() / sizeof(T));
  std::memcpy(static_cast<void*>(values.data()), bytes.data(), bytes.size());
}

//! The inverse of pickle_state() (also of older states: 5 items from before not_held was pickled,
//! 12 and 15 ReadInfo values from before the last three and the last one); the soup is validated.
//! \throws InvalidSoupError on a state of another shape
std::shared_ptr<PySoup> unpickle(const py::tuple& state) {
  if (state.size() != 5 && state.size() != 6)
    throw InvalidSoupError("Soup: bad pickle state");
  auto soup = std::make_shared<PySoup>();
  unpack_bytes(state[0], soup->soup.positions);
  unpack_bytes(state[1], soup->soup.corner_vertices);
  unpack_bytes(state[2], soup->soup.face_begin);
  soup->path = state[3].cast<std::string>();
  const auto i = state[4].cast<std::vector<std::size_t>>();
  if (i.size() != 12 && i.size() != 15 && i.size() != 16)
    throw InvalidSoupError("Soup: bad pickle state");
  ReadInfo& info = soup->info;
  info.declared_vertices = i[0], info.declared_faces = i[1];
  info.faces_kept = i[2], info.faces_split = i[3], info.faces_set_aside = i[4];
  info.dangling_edges = i[5], info.lone_points = i[6], info.strip_joins = i[7];
  info.unknown_records = i[8], info.color_map_indices = i[9], info.empty_records = i[10];
  info.trailing_bytes = i[11];
  if (i.size() >= 15) {
    info.faces_without_corners = i[12], info.vertices_welded_by_position = i[13];
    info.float_coordinates = i[14] != 0;
  }
  if (i.size() == 16)
    info.keyhole_polygons = i[15];
  if (state.size() == 6)
    soup->not_held = state[5].cast<std::vector<std::string>>();
  validate_soup(soup->soup);
  return soup;
}

}  // namespace

void bind_soup(py::module_& m) {
  py::class_<PySoup, std::shared_ptr<PySoup>>(m, "Soup")
      .def(py::init([](py::handle vertices, py::handle faces) {
             auto soup = std::make_shared<PySoup>();
             soup->soup = soup_from_python(vertices, faces);
             return soup;
           }),
           py::arg("vertices"), py::arg("faces"))
      .def_property_readonly("vertices",
                             [](py::object self) {
                               return positions_array(self.cast<PySoup&>().soup.positions, self,
                                                      false);
                             })
      .def_property_readonly(
          "faces",
          [](py::object self) { return faces_object(self.cast<PySoup&>().soup, self, false); })
      .def_property_readonly("corner_vertices",
                             [](py::object self) {
                               const Soup& s = self.cast<PySoup&>().soup;
                               return index_array(s.corner_vertices, s.num_vertices(), self, false);
                             })
      .def_property_readonly("face_begin",
                             [](py::object self) {
                               const Soup& s = self.cast<PySoup&>().soup;
                               return index_array(s.face_begin, s.num_corners() + 1, self, false);
                             })
      .def_property_readonly("num_vertices", [](const PySoup& s) { return s.soup.num_vertices(); })
      .def_property_readonly("num_faces", [](const PySoup& s) { return s.soup.num_faces(); })
      .def_property_readonly("path",
                             [](const PySoup& s) -> py::object {
                               return s.path.empty() ? py::object(py::none())
                                                     : py::object(py::str(s.path));
                             })
      .def_property_readonly(
          "reading",
          [](const PySoup& s) -> py::object {
            if (s.path.empty() || !s.info.changed_anything())
              return py::none();
            return py::str(describe_reading(s.info));
          },
          "What the reader did not keep as it was (describe_reading(), as the CLI warns), or None")
      .def_property_readonly(
          "not_held", [](const PySoup& s) { return s.not_held; },
          "What the file holds besides positions and polygons, which a Soup does not "
          "(describe_not_held()): one phrase per kind, empty when none or built from arrays")
      .def_property_readonly("read_info", &read_info_dict,
                             "The keys of the reports' \"read\" object, or None from arrays")
      .def("__repr__",
           [](const PySoup& s) {
             return "<meshbridge.Soup: " + std::to_string(s.soup.num_vertices()) + " vertices, " +
                    std::to_string(s.soup.num_faces()) + " faces" +
                    (s.path.empty() ? std::string() : " from " + s.path) + ">";
           })
      // Pickling (Dask sends soups between processes): the arrays as raw bytes, exactly.
      .def(py::pickle(&pickle_state, &unpickle));
}

}  // namespace meshbridge::python
