// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/io.h"

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
  out.metadata = input.metadata;
  // The 3MF object of each output face; an added face (kNoIndex) is of the model.
  if (!input.face_objects.empty()) {
    out.face_objects.reserve(mesh.face_origin.size());
    for (Index origin : mesh.face_origin) {
      out.face_objects.push_back(origin < input.face_objects.size() ? input.face_objects[origin]
                                                                    : FaceObject{});
    }
  }
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
