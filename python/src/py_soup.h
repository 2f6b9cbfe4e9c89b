// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file py_soup.h
//! `meshbridge._core.Soup`: a soup read from a file or built from numpy arrays, with what its
//! file declared; its arrays are views that keep the Soup alive.

#include "meshbridge/io.h"
#include "meshbridge/soup.h"

#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace meshbridge::python {

//! A soup read from a file or built from arrays, with what its file declared.
struct PySoup {
  Soup soup;
  std::string path;  //!< the file it was read from; empty when built from arrays
  ReadInfo info;
  //! What the file held that the soup does not (describe_not_held()); empty from arrays.
  std::vector<std::string> not_held;
};

//! Adds the class Soup to `m`: construction from (vertices, faces) arrays, array views, the
//! reading's counts and pickling (Dask sends soups between processes: raw bytes, exactly).
void bind_soup(pybind11::module_& m);

}  // namespace meshbridge::python
