// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/io.h"

#include <algorithm>

namespace meshbridge {

MeshAttributes carry_attributes(const MeshAttributes& input, const IndexedMesh& mesh) {
  MeshAttributes out;
  out.double_precision = input.double_precision;
  if (!input.vertex_colors.empty()) {
    out.vertex_colors.reserve(mesh.vertex_origin.size());
    for (Index origin : mesh.vertex_origin)
      out.vertex_colors.push_back(origin < input.vertex_colors.size() ? input.vertex_colors[origin]
                                                                      : Rgba{});
  }
  if (!input.face_colors.empty()) {
    out.face_colors.reserve(mesh.face_origin.size());
    for (Index origin : mesh.face_origin)
      out.face_colors.push_back(origin < input.face_colors.size() ? input.face_colors[origin]
                                                                  : Rgba{});
  }
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
