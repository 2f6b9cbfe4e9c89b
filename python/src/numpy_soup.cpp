// SPDX-License-Identifier: GPL-3.0-or-later
#include "numpy_soup.h"

#include "meshbridge/errors.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>

namespace meshbridge::python {

namespace {

static_assert(sizeof(Point) == 3 * sizeof(double), "OpenMesh::Vec3d must be 3 packed doubles");

std::string shape_text(const py::array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d)
    text += (d ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

std::string type_name(py::handle h) {
  return py::str(py::type::handle_of(h).attr("__name__"));
}

template <class T>
void read_positions(const py::array& array, Soup& soup) {
  const auto v = array.unchecked<T, 2>();
  soup.positions.resize(static_cast<std::size_t>(v.shape(0)));
  for (py::ssize_t i = 0; i < v.shape(0); ++i) {
    soup.positions[static_cast<std::size_t>(i)] = Point(
        static_cast<double>(v(i, 0)), static_cast<double>(v(i, 1)), static_cast<double>(v(i, 2)));
  }
}

void read_vertices(py::handle vertices, Soup& soup) {
  py::array array;
  if (py::isinstance<py::array_t<double>>(vertices) ||
      py::isinstance<py::array_t<float>>(vertices)) {
    array = py::reinterpret_borrow<py::array>(vertices);
  } else {
    if (py::isinstance<py::array>(vertices)) {
      const char kind = py::reinterpret_borrow<py::array>(vertices).dtype().kind();
      if (kind != 'f' && kind != 'i' && kind != 'u') {
        throw InvalidSoupError("vertices: expected an (n, 3) array of numbers, got dtype " +
                               std::string(py::str(vertices.attr("dtype"))));
      }
    }
    try {  // lists, integer coordinates, other float widths: converted once
      array = py::array_t<double, py::array::forcecast>::ensure(vertices);
    } catch (const py::error_already_set&) {
    }
    if (!array) {
      PyErr_Clear();
      throw InvalidSoupError("vertices: expected an (n, 3) array of numbers, got " +
                             type_name(vertices));
    }
  }
  if (array.ndim() != 2 || array.shape(1) != 3) {
    throw InvalidSoupError("vertices must have shape (n, 3), got shape " + shape_text(array));
  }
  if (py::isinstance<py::array_t<float>>(array))
    read_positions<float>(array, soup);
  else
    read_positions<double>(array, soup);
}

[[noreturn]] void index_error(std::size_t face, std::size_t corner, const std::string& value,
                              const char* what) {
  throw InvalidSoupError("face " + std::to_string(face) + ", corner " + std::to_string(corner) +
                         ": vertex index " + value + " " + what);
}

//! Checks one index from Python and narrows it to the core's 32 bits.
template <class T>
Index checked_index(T value, std::size_t face, std::size_t corner) {
  if constexpr (std::is_signed_v<T>) {
    if (value < 0)
      index_error(face, corner, std::to_string(value), "is negative");
  }
  if (static_cast<unsigned long long>(value) >= kNoIndex) {
    index_error(face, corner, std::to_string(value),  // in its own type: 2^63 stays positive
                "is out of range (MeshBridge indices are below 2^32 - 1)");
  }
  return static_cast<Index>(value);
}

//! C-contiguous fast path: one vectorisable pass for the range, one for the copy. False (nothing
//! written) if some index is negative or too large, so the caller finds it element by element.
template <class T>
bool copy_contiguous_indices(const T* data, std::size_t n, Index* corners) {
  T low = 0, high = 0;
  for (std::size_t i = 0; i < n; ++i) {
    low = std::min(low, data[i]);
    high = std::max(high, data[i]);
  }
  if (low < 0 || static_cast<unsigned long long>(high) >= kNoIndex)
    return false;
  for (std::size_t i = 0; i < n; ++i)
    corners[i] = static_cast<Index>(data[i]);
  return true;
}

template <class T>
bool read_face_array(const py::array& array, Soup& soup) {
  if (!py::isinstance<py::array_t<T>>(array))
    return false;
  const auto f = array.unchecked<T, 2>();
  const auto m = static_cast<std::size_t>(f.shape(0));
  const auto k = static_cast<std::size_t>(f.shape(1));
  soup.corner_vertices.resize(m * k);
  soup.face_begin.resize(m + 1);
  for (std::size_t i = 0; i <= m; ++i)
    soup.face_begin[i] = static_cast<Index>(i * k);
  Index* corners = soup.corner_vertices.data();
  if ((array.flags() & py::array::c_style) != 0 && m * k > 0 &&
      copy_contiguous_indices(static_cast<const T*>(array.data()), m * k, corners)) {
    return true;
  }
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = 0; j < k; ++j) {
      corners[i * k + j] =
          checked_index(f(static_cast<py::ssize_t>(i), static_cast<py::ssize_t>(j)), i, j);
    }
  }
  return true;
}

void read_face_sequences(py::handle faces, Soup& soup) {
  if (!py::isinstance<py::sequence>(faces) || py::isinstance<py::str>(faces)) {
    throw InvalidSoupError(
        "faces: expected an (m, k) integer array or a sequence of index sequences, got " +
        type_name(faces));
  }
  const auto sequence = py::reinterpret_borrow<py::sequence>(faces);
  const std::size_t m = sequence.size();
  soup.face_begin.reserve(m + 1);
  soup.corner_vertices.reserve(3 * m);
  for (std::size_t i = 0; i < m; ++i) {
    const py::object polygon = sequence[i];
    if (!py::isinstance<py::sequence>(polygon) || py::isinstance<py::str>(polygon)) {
      throw InvalidSoupError("face " + std::to_string(i) +
                             ": expected a sequence of vertex indices, got " + type_name(polygon));
    }
    const auto corners = py::reinterpret_borrow<py::sequence>(polygon);
    const std::size_t k = corners.size();
    for (std::size_t j = 0; j < k; ++j) {
      const py::object item = corners[j];
      PyObject* index = PyNumber_Index(item.ptr());  // ints and numpy integers, not floats
      if (index == nullptr) {
        PyErr_Clear();
        throw InvalidSoupError("face " + std::to_string(i) + ", corner " + std::to_string(j) +
                               ": expected an integer vertex index, got " + type_name(item));
      }
      int overflow = 0;
      const long long value = PyLong_AsLongLongAndOverflow(index, &overflow);
      Py_DECREF(index);
      if (overflow != 0) {
        index_error(i, j, py::str(item).cast<std::string>(),
                    overflow < 0 ? "is negative" : "is out of range");
      }
      soup.corner_vertices.push_back(checked_index(value, i, j));
    }
    soup.face_begin.push_back(static_cast<Index>(soup.corner_vertices.size()));
  }
}

void read_faces(py::handle faces, Soup& soup) {
  if (py::isinstance<py::array>(faces)) {
    const auto array = py::reinterpret_borrow<py::array>(faces);
    const char kind = array.dtype().kind();
    if (kind == 'O') {
      read_face_sequences(faces, soup);
      return;
    }
    if (kind != 'i' && kind != 'u') {
      throw InvalidSoupError("faces: expected integer vertex indices, got dtype " +
                             std::string(py::str(array.dtype())));
    }
    if (array.ndim() != 2 || array.shape(1) < 3) {
      throw InvalidSoupError(
          "faces must have shape (m, k) with k >= 3 (or be a sequence of index sequences), got "
          "shape " +
          shape_text(array));
    }
    if (static_cast<unsigned long long>(array.size()) >= kNoIndex)
      throw InvalidSoupError("faces: more than 2^32 - 2 corners");
    soup.face_begin.clear();
    if (read_face_array<std::int32_t>(array, soup) || read_face_array<std::int64_t>(array, soup) ||
        read_face_array<std::uint32_t>(array, soup) ||
        read_face_array<std::uint64_t>(array, soup) || read_face_array<std::int16_t>(array, soup) ||
        read_face_array<std::uint16_t>(array, soup) || read_face_array<std::int8_t>(array, soup) ||
        read_face_array<std::uint8_t>(array, soup)) {
      return;
    }
    // Another byte order: converted once.
    const auto native = py::array_t<std::int64_t, py::array::forcecast>::ensure(faces);
    read_face_array<std::int64_t>(native, soup);
    return;
  }
  read_face_sequences(faces, soup);
}

}  // namespace

Soup soup_from_python(py::handle vertices, py::handle faces) {
  Soup soup;
  read_vertices(vertices, soup);
  read_faces(faces, soup);
  return soup;
}

py::array positions_array(const std::vector<Point>& positions, py::handle owner, bool writeable) {
  const auto n = static_cast<py::ssize_t>(positions.size());
  py::array_t<double> array(
      {n, py::ssize_t{3}},
      {static_cast<py::ssize_t>(sizeof(Point)), static_cast<py::ssize_t>(sizeof(double))},
      positions.empty() ? nullptr : positions.front().data(), owner);
  if (!writeable)
    array.attr("flags").attr("writeable") = false;
  return std::move(array);
}

py::array index_array(const std::vector<Index>& indices, std::size_t bound, py::handle owner,
                      bool writeable, std::size_t columns) {
  const auto n = static_cast<py::ssize_t>(indices.size());
  std::vector<py::ssize_t> shape{n};
  if (columns > 0)
    shape = {n / static_cast<py::ssize_t>(columns), static_cast<py::ssize_t>(columns)};
  if (bound <= (std::size_t{1} << 31)) {
    // Values below 2^31 read the same as int32, and kNoIndex (2^32 - 1) reads as -1.
    py::array_t<std::int32_t> array(
        shape, indices.empty() ? nullptr : reinterpret_cast<const std::int32_t*>(indices.data()),
        owner);
    if (!writeable)
      array.attr("flags").attr("writeable") = false;
    return std::move(array);
  }
  py::array_t<std::int64_t> array(shape);
  std::int64_t* out = array.mutable_data();
  for (std::size_t i = 0; i < indices.size(); ++i)
    out[i] = indices[i] == kNoIndex ? -1 : static_cast<std::int64_t>(indices[i]);
  return std::move(array);
}

py::object faces_object(const Soup& soup, py::handle owner, bool writeable) {
  const std::size_t m = soup.num_faces();
  if (m == 0)
    return py::array_t<std::int32_t>(std::vector<py::ssize_t>{0, 3});
  const std::size_t k = soup.arity(0);
  bool uniform = true;
  for (std::size_t f = 1; f < m && uniform; ++f)
    uniform = soup.arity(f) == k;
  if (uniform && k > 0)
    return index_array(soup.corner_vertices, soup.num_vertices(), owner, writeable, k);
  py::list polygons(m);
  for (std::size_t f = 0; f < m; ++f) {
    py::list polygon(soup.arity(f));
    std::size_t i = 0;
    for (Index v : soup.polygon(f))
      polygon[i++] = py::int_(v);
    polygons[f] = std::move(polygon);
  }
  return std::move(polygons);
}

}  // namespace meshbridge::python
