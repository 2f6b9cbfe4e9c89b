// SPDX-License-Identifier: GPL-3.0-or-later
// What each PLY property means to MeshBridge (a coordinate, a colour channel, the corner list,
// an edge's end, or nothing it keeps), colour channels as bytes, and the header checks that
// need those meanings.

#pragma once

#include "io/ply_header.h"
#include "meshbridge/io.h"

#include <cstdint>
#include <string>
#include <vector>

namespace meshbridge::detail {

//! The meaning of a PLY property: see ply_role().
enum class PlyRole : std::uint8_t {
  skip,
  x,
  y,
  z,
  red,
  green,
  blue,
  alpha,
  indices,
  vertex1,
  vertex2
};

//! The role of property `p` of element `e`: x/y/z of `vertex`; red/green/blue/alpha (or
//! diffuse_*) of `vertex` and `face`; the `vertex_indices` (or `vertex_index`) list of `face` and
//! `tristrips`; vertex1/vertex2 of `edge`; skip for everything else.
PlyRole ply_role(const PlyElement& e, const PlyProperty& p);

bool is_color(PlyRole r);

//! A colour channel as 0..255: integer types as they are (clamped), reals in [0, 1] scaled.
std::uint8_t ply_channel(double value, PlyScalar type);

//! True if ply_channel() clamps `value`: outside 0..255 (integer types) or 0..1 (reals), or nan.
bool ply_channel_clamps(double value, PlyScalar type);

//! Sets the channel of `color` that `r` (a colour role) names.
void set_color_channel(Rgba& color, PlyRole r, std::uint8_t value);

//! The colour channels among an element's properties (ColorChannel bits).
std::uint8_t ply_color_channels(const std::vector<PlyRole>& roles);

//! Refuses a header MeshBridge cannot read a mesh from: a vertex element without x, y or z, an
//! element with items but no property, a face or tristrips element without one integer corner
//! list. \throw ReadError starting with `path`
void check_ply_elements(const PlyHeader& header, const std::string& path);

}  // namespace meshbridge::detail
