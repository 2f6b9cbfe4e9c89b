// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/io.h"

#include "io/formats.h"

#include <algorithm>

namespace meshbridge {

namespace {

//! The colours of the output elements (and their missing flags) from their input elements.
void carry_colors(const std::vector<Rgba>& colors, const std::vector<bool>& missing,
                  const std::vector<Index>& origins, std::vector<Rgba>& out_colors,
                  std::vector<bool>& out_missing) {
  if (colors.empty())
    return;
  out_colors.reserve(origins.size());
  bool any_missing = false;
  for (Index origin : origins) {
    out_colors.push_back(origin < colors.size() ? colors[origin] : Rgba{});
    any_missing = any_missing || !MeshAttributes::has_color(colors, missing, origin);
  }
  if (!any_missing)
    return;
  out_missing.reserve(origins.size());
  for (Index origin : origins)
    out_missing.push_back(!MeshAttributes::has_color(colors, missing, origin));
}

}  // namespace

namespace detail {

std::vector<FaceObject> output_face_objects(const Soup& soup, const std::vector<Index>& face_origin,
                                            const std::vector<FaceObject>& input) {
  std::vector<FaceObject> kinds;
  if (input.empty())
    return kinds;
  const auto origin_of = [&](std::size_t f) {
    return face_origin.empty() ? static_cast<Index>(f) : face_origin[f];
  };
  kinds.resize(soup.num_faces());
  bool added = false, other = false;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const Index origin = origin_of(f);
    added = added || origin >= input.size();
    kinds[f] = origin < input.size() ? input[origin] : FaceObject{};
    other = other || !kinds[f].is_printed_model();
  }
  if (added && other) {
    // The kind at each vertex: of the first face with an input that uses it.
    std::vector<FaceObject> at_vertex(soup.num_vertices());
    std::vector<bool> known(soup.num_vertices(), false);
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      if (origin_of(f) >= input.size())
        continue;
      for (Index v : soup.polygon(f)) {
        if (v < known.size() && !known[v]) {
          known[v] = true;
          at_vertex[v] = kinds[f];
        }
      }
    }
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      const PolygonView polygon = soup.polygon(f);
      if (origin_of(f) >= input.size() && polygon.size() > 0 && polygon[0] < known.size() &&
          known[polygon[0]])
        kinds[f] = at_vertex[polygon[0]];
    }
  }
  if (!other)
    kinds.clear();
  return kinds;
}

}  // namespace detail

MeshAttributes carry_attributes(const MeshAttributes& input, const IndexedMesh& mesh) {
  MeshAttributes out;
  out.double_precision = input.double_precision;
  out.length_unit = input.length_unit;
  out.vertex_color_channels = input.vertex_color_channels;
  out.face_color_channels = input.face_color_channels;
  out.material_libraries = input.material_libraries;
  out.texture_coordinates = input.texture_coordinates;
  out.normals = input.normals;
  out.not_kept = input.not_kept;
  out.corners = detail::carry_corner_attributes(input.corners, mesh);
  out.metadata = input.metadata;
  // The 3MF object of each output face (an added face: of the faces around it).
  out.face_objects = detail::output_face_objects(mesh.soup, mesh.face_origin, input.face_objects);
  carry_colors(input.vertex_colors, input.vertex_color_missing, mesh.vertex_origin,
               out.vertex_colors, out.vertex_color_missing);
  carry_colors(input.face_colors, input.face_color_missing, mesh.face_origin, out.face_colors,
               out.face_color_missing);
  // face_origin is non-decreasing (repair keeps the face order), so a group starts at the first
  // output face that comes from its first input face or a later one; empty groups are dropped.
  for (const FaceGroup& group : input.face_groups) {
    const auto first =
        std::lower_bound(mesh.face_origin.begin(), mesh.face_origin.end(), group.first_face);
    const auto index = static_cast<Index>(first - mesh.face_origin.begin());
    if (!out.face_groups.empty() && out.face_groups.back().first_face == index)
      out.face_groups.back() = {group.name, index};
    else
      out.face_groups.push_back({group.name, index});
  }
  return out;
}

}  // namespace meshbridge
