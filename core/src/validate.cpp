// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/validate.h"

#include "meshbridge/errors.h"
#include "validate_faces.h"

#include <cmath>
#include <string>

namespace meshbridge {

namespace detail {

void validate_layout(const Soup& soup) {
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
}

void throw_invalid_face(const Soup& soup, std::size_t f) {
  const Index begin = soup.face_begin[f], end = soup.face_begin[f + 1];
  if (end < begin)
    throw InvalidSoupError("face " + std::to_string(f) + " has a negative corner count");
  if (end > soup.corner_vertices.size()) {
    throw InvalidSoupError("face " + std::to_string(f) + " has corners past the end of the " +
                           "corner list (face offsets must not decrease)");
  }
  const std::size_t arity = end - begin;
  if (arity < 3) {
    throw InvalidSoupError("face " + std::to_string(f) + " has " + std::to_string(arity) +
                           " corner(s); a polygon needs at least 3");
  }
  for (std::size_t i = 0; i < arity; ++i) {
    const Index v = soup.corner_vertices[begin + i];
    if (v >= soup.num_vertices()) {
      throw InvalidSoupError("face " + std::to_string(f) + ", corner " + std::to_string(i) +
                             ": vertex index " + std::to_string(v) +
                             " is out of range (the soup has " +
                             std::to_string(soup.num_vertices()) + " vertices)");
    }
  }
  throw InvalidSoupError("face " + std::to_string(f) + " is invalid");  // not reached (\pre)
}

}  // namespace detail

void validate_soup(const Soup& soup) {
  detail::validate_layout(soup);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (!detail::is_valid_face(soup, f))
      detail::throw_invalid_face(soup, f);
  }
}

}  // namespace meshbridge
