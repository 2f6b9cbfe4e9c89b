// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/validate.h"

#include "meshbridge/errors.h"

#include <cmath>
#include <string>

namespace meshbridge {

void validate_soup(const Soup& soup) {
  if (soup.face_begin.empty() || soup.face_begin.front() != 0 ||
      soup.face_begin.back() != soup.corner_vertices.size()) {
    throw InvalidSoupError("soup: face offsets do not cover the corner list");
  }
  if (soup.num_vertices() >= kNoIndex || soup.num_corners() >= kNoIndex) {
    throw InvalidSoupError("soup: more than 2^32-2 vertices or corners");
  }
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const Point& p = soup.positions[v];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      throw InvalidSoupError("vertex " + std::to_string(v) + " has a non-finite coordinate (" +
                             std::to_string(p[0]) + ", " + std::to_string(p[1]) + ", " +
                             std::to_string(p[2]) + ")");
    }
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (soup.face_begin[f + 1] < soup.face_begin[f]) {
      throw InvalidSoupError("face " + std::to_string(f) + " has a negative corner count");
    }
    const std::size_t arity = soup.arity(f);
    if (arity < 3) {
      throw InvalidSoupError("face " + std::to_string(f) + " has " + std::to_string(arity) +
                             " corner(s); a polygon needs at least 3");
    }
    const PolygonView polygon = soup.polygon(f);
    for (std::size_t i = 0; i < arity; ++i) {
      if (polygon[i] >= soup.num_vertices()) {
        throw InvalidSoupError("face " + std::to_string(f) + ", corner " + std::to_string(i) +
                               ": vertex index " + std::to_string(polygon[i]) +
                               " is out of range (the soup has " +
                               std::to_string(soup.num_vertices()) + " vertices)");
      }
    }
  }
}

}  // namespace meshbridge
