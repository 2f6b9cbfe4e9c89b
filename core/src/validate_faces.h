// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// validate_soup() in its two steps, for a caller that walks the faces anyway (the readers'
// accounting): it checks each face on its way instead of in a second pass over the corners.

#include "meshbridge/soup.h"

#include <cstddef>

namespace meshbridge::detail {

//! The face offsets cover the corner list, the counts fit an Index, every coordinate is finite.
//! \throw InvalidSoupError as validate_soup()
void validate_layout(const Soup& soup);

//! Face f has at least 3 corners, within the corner list, each naming a vertex of the soup.
//! \pre validate_layout(soup) passed; f < soup.num_faces()
inline bool is_valid_face(const Soup& soup, std::size_t f) {
  const Index begin = soup.face_begin[f], end = soup.face_begin[f + 1];
  if (end < begin || end - begin < 3 || end > soup.corner_vertices.size())
    return false;
  const std::size_t vertices = soup.num_vertices();
  for (Index c = begin; c < end; ++c) {
    if (soup.corner_vertices[c] >= vertices)
      return false;
  }
  return true;
}

//! Throws the InvalidSoupError that names what is wrong with face f.
//! \pre validate_layout(soup) passed; !is_valid_face(soup, f)
[[noreturn]] void throw_invalid_face(const Soup& soup, std::size_t f);

}  // namespace meshbridge::detail
