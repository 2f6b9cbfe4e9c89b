// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ply_roles.h"

#include "io/ply_sources.h"
#include "meshbridge/errors.h"

#include <cmath>

namespace meshbridge::detail {

PlyRole ply_role(const PlyElement& e, const PlyProperty& p) {
  const std::string& n = p.name;
  if (p.is_list) {
    const bool polygons = e.name == "face" || e.name == "tristrips";
    return polygons && (n == "vertex_indices" || n == "vertex_index") ? PlyRole::indices
                                                                      : PlyRole::skip;
  }
  if (e.name == "vertex") {
    if (n == "x")
      return PlyRole::x;
    if (n == "y")
      return PlyRole::y;
    if (n == "z")
      return PlyRole::z;
  }
  if (e.name == "vertex" || e.name == "face") {
    if (n == "red" || n == "diffuse_red")
      return PlyRole::red;
    if (n == "green" || n == "diffuse_green")
      return PlyRole::green;
    if (n == "blue" || n == "diffuse_blue")
      return PlyRole::blue;
    if (n == "alpha")
      return PlyRole::alpha;
  }
  if (e.name == "edge") {
    if (n == "vertex1")
      return PlyRole::vertex1;
    if (n == "vertex2")
      return PlyRole::vertex2;
  }
  return PlyRole::skip;
}

bool is_color(PlyRole r) {
  return r == PlyRole::red || r == PlyRole::green || r == PlyRole::blue || r == PlyRole::alpha;
}

std::uint8_t ply_channel(double value, PlyScalar type) {
  if (!is_ply_integer(type))
    value *= 255.0;
  if (!(value > 0))
    return 0;
  return value >= 255 ? 255 : static_cast<std::uint8_t>(std::lround(value));
}

bool ply_channel_clamps(double value, PlyScalar type) {
  return !(value >= 0 && value <= (is_ply_integer(type) ? 255.0 : 1.0));
}

void set_color_channel(Rgba& color, PlyRole r, std::uint8_t value) {
  switch (r) {
    case PlyRole::red:
      color.r = value;
      break;
    case PlyRole::green:
      color.g = value;
      break;
    case PlyRole::blue:
      color.b = value;
      break;
    default:
      color.a = value;
      break;
  }
}

std::uint8_t ply_color_channels(const std::vector<PlyRole>& roles) {
  std::uint8_t channels = 0;
  for (PlyRole r : roles) {
    channels |= r == PlyRole::red     ? kRedChannel
                : r == PlyRole::green ? kGreenChannel
                : r == PlyRole::blue  ? kBlueChannel
                : r == PlyRole::alpha ? kAlphaChannel
                                      : 0;
  }
  return channels;
}

void check_ply_elements(const PlyHeader& header, const std::string& path) {
  const std::string where = path + ": ";
  // The vertex element first: without x, y and z nothing else matters.
  int coordinates = 0;
  std::string missing;
  for (const char* axis : {"x", "y", "z"}) {
    int found = 0;
    for (const PlyElement& e : header.elements) {
      if (e.name != "vertex")
        continue;
      for (const PlyProperty& p : e.properties)
        found += p.name == axis;
    }
    coordinates += found > 0;  // (the header refuses a property declared twice)
    if (found == 0)
      missing += std::string(missing.empty() ? "" : ", ") + "'" + axis + "'";
  }
  if (coordinates != 3) {
    throw ReadError(where + "the PLY vertex element has no " + missing +
                    " property (a vertex needs x, y and z)");
  }
  for (const PlyElement& e : header.elements) {
    if (e.count > 0 && e.properties.empty()) {
      throw ReadError(where + "PLY element '" + e.name + "' declares " + std::to_string(e.count) +
                      " items without any property");
    }
    if ((e.name != "face" && e.name != "tristrips") || e.count == 0)
      continue;
    bool has_indices = false;
    for (const PlyProperty& p : e.properties) {
      if (ply_role(e, p) != PlyRole::indices)
        continue;
      if (has_indices) {
        throw ReadError(where + "PLY element '" + e.name +
                        "' has both 'vertex_indices' and 'vertex_index'");
      }
      has_indices = true;
      if (!is_ply_integer(p.type)) {
        throw ReadError(where + "PLY " + e.name + " property '" + p.name + "' is a list of '" +
                        ply_scalar_name(p.type) + "', not of integers");
      }
    }
    if (!has_indices) {
      throw ReadError(where + "PLY element '" + e.name +
                      "' has no 'vertex_indices' (or 'vertex_index') list");
    }
  }
}

}  // namespace meshbridge::detail
