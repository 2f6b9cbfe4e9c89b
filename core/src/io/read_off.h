// SPDX-License-Identifier: GPL-3.0-or-later
// What the OFF reader's two bodies share: the header's flags, colour scaling, faces from corner
// lists. ASCII OFF is read in read_off.cpp, binary OFF in read_off_binary.cpp.

#pragma once

#include "io/mapped_file.h"
#include "meshbridge/io.h"
#include "meshbridge/soup.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace meshbridge::detail {

//! The flags of an OFF header `[ST][C][N][n]OFF [BINARY]`.
struct OffHeader {
  bool texcoords = false, colors = false, normals = false, binary = false;
};

//! A colour channel as a byte, from 0..1 (`unit_range`) or 0..255, clamped; 0 if not finite.
inline std::uint8_t off_color_byte(double value, bool unit_range) {
  if (!std::isfinite(value))
    return 0;
  const double scaled = unit_range ? value * 255.0 : value;
  return static_cast<std::uint8_t>(std::lround(std::clamp(scaled, 0.0, 255.0)));
}

//! True if a colour channel lies outside 0..1 (`unit_range`) or 0..255, or is not finite:
//! off_color_byte() clamps it.
inline bool off_color_clamped(double value, bool unit_range) {
  return !(value >= 0 && value <= (unit_range ? 1.0 : 255.0));
}

//! Appends an OFF face from its corners (formats.h: 1 or 2 corners repeat the last one up to a
//! triangle; none is counted in `info.faces_without_corners`, not appended). May grow `corners`.
void add_off_face(std::vector<Index>& corners, Soup& soup, ReadInfo& info);

//! What reading a binary OFF body counts for the reader's NotKept entries.
struct OffBinaryNotes {
  std::size_t face_colors = 0;            //!< Geomview-layout faces with a colour (not kept)
  std::size_t vertex_colors_clamped = 0;  //!< vertices with a channel outside 0..1
};

//! Reads the binary body of an OFF file (from `body`, just after the header line `h`) into `soup`
//! (and vertex colours into `attributes`, if given and `h.colors`): OpenMesh's layout or
//! Geomview's, whichever accounts for every byte. \throw ReadError naming what does not fit
OffBinaryNotes read_off_binary(const MappedFile& file, const char* body, const OffHeader& h,
                               Soup& soup, ReadInfo& info, MeshAttributes* attributes);

}  // namespace meshbridge::detail
