// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file model_builders.h
//! Small building blocks shared by the model generators (internal to models/).

#include "meshbridge/soup.h"

#include <stdexcept>
#include <string>

namespace meshbridge::models::detail {

inline constexpr double kPi = 3.14159265358979323846;

//! Appends quad (a, b, c, d) as the triangles (a, b, c), (a, c, d).
inline void add_split_quad(Soup& soup, Index a, Index b, Index c, Index d) {
  soup.add_polygon({a, b, c});
  soup.add_polygon({a, c, d});
}

//! \throw std::invalid_argument with `message` unless `ok`
inline void check_argument(bool ok, const std::string& message) {
  if (!ok)
    throw std::invalid_argument(message);
}

}  // namespace meshbridge::models::detail
