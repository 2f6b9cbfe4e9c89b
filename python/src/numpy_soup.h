// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file numpy_soup.h
//! numpy arrays and Python sequences <-> meshbridge::Soup, in one pass, without intermediate
//! copies of the caller's arrays.
//!
//! Index convention on the Python side: vertex and face indices come out as int32 (int64 when a
//! mesh has 2^31 vertices or more), and "no element" (kNoIndex in the core) is -1.

#include "meshbridge/indexed_mesh.h"
#include "meshbridge/soup.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <memory>

namespace meshbridge::python {

namespace py = pybind11;

//! Builds a soup from `vertices` and `faces`. Called with the GIL held.
//!
//! `vertices`: (n, 3) array of float64 or float32 (any strides, read in place; other real dtypes
//! and nested sequences are converted once). `faces`: (m, k) integer array, k >= 3, of any integer
//! dtype and strides (read in place), or a sequence of index sequences (polygons of any arity).
//! \throw InvalidSoupError for a wrong shape or dtype, or a negative index, naming the face and
//! corner; range and finiteness are checked by the core (InvalidSoupError) when the soup is used.
Soup soup_from_python(py::handle vertices, py::handle faces);

//! A numpy view of a vector that `owner` keeps alive (no copy). `T` is the element type; a
//! vector of OpenMesh points becomes an (n, 3) float64 array.
py::array positions_array(const std::vector<Point>& positions, py::handle owner, bool writeable);

//! An index vector whose values are below `bound` or kNoIndex, as an int32 view when `bound` <=
//! 2^31 (an int64 copy otherwise); kNoIndex becomes -1 either way. Shape (n,) or, with `columns`
//! > 0, (n / columns, columns).
py::array index_array(const std::vector<Index>& indices, std::size_t bound, py::handle owner,
                      bool writeable, std::size_t columns = 0);

//! The soup's polygons: an (m, k) index view when every polygon has k corners (m > 0), otherwise
//! a list of m lists of ints. An empty soup gives a (0, 3) array.
py::object faces_object(const Soup& soup, py::handle owner, bool writeable);

//! Keeps a C++ object alive for as long as numpy arrays viewing it exist.
template <class T>
py::capsule owner_capsule(std::unique_ptr<T> object) {
  return py::capsule(object.release(), [](void* p) { delete static_cast<T*>(p); });
}

}  // namespace meshbridge::python
