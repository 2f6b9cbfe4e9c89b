// SPDX-License-Identifier: GPL-3.0-or-later
// OBJ writer: the input's mtllib lines, "v x y z [r g b [a]]" (shortest exact decimals; a colour
// only where the input vertex had one; alpha only when some vertex is not opaque), the input's
// "vt" and "vn" records (and those interpolated for corners repair inserted), "f a b c ..." or
// "f a/ta/na ..." (1-based; vt or vn on a face only when all its corners have one), and the
// input's o/g/usemtl groups before the first face of each.

#include "io/formats.h"
#include "io/text_output.h"

#include <algorithm>

namespace meshbridge::detail {

void write_obj(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions&) {
  const Soup& soup = mesh.soup;
  TextOutput text(out);
  text.text("# written by MeshBridge\n");
  if (attributes != nullptr) {
    for (const std::string& library : attributes->material_libraries)
      text.text(library).ch('\n');
  }
  const bool colors = attributes != nullptr && !attributes->vertex_colors.empty();
  // Alpha only when it carries information (a vertex not opaque): "v x y z r g b a" is no
  // standard, and Open3D reads such a file as 0 points; trimesh and MeshLab read RGB.
  const bool alpha = colors && (attributes->vertex_color_channels & kAlphaChannel) != 0 &&
                     std::any_of(attributes->vertex_colors.begin(), attributes->vertex_colors.end(),
                                 [](const Rgba& c) { return c.a != 255; });
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const Point& p = soup.positions[v];
    text.text("v ").number(p[0]).ch(' ').number(p[1]).ch(' ').number(p[2]);
    const Index origin = colors ? input_vertex(mesh, v) : kNoIndex;
    if (colors && has_color(attributes->vertex_colors, attributes->vertex_color_missing, origin)) {
      const Rgba c = attributes->vertex_colors[origin];
      text.ch(' ').number(c.r / 255.0).ch(' ').number(c.g / 255.0).ch(' ').number(c.b / 255.0);
      if (alpha)
        text.ch(' ').number(c.a / 255.0);
    }
    text.ch('\n');
  }
  const CornerAttributes corners = attributes != nullptr
                                       ? carry_corner_attributes(attributes->corners, mesh)
                                       : CornerAttributes();
  const int components = std::max(corners.texture_components, 2);
  for (const std::array<double, 3>& t : corners.texture_coordinates) {
    text.text("vt ").number(t[0]).ch(' ').number(t[1]);
    if (components == 3)
      text.ch(' ').number(t[2]);
    text.ch('\n');
  }
  for (const std::array<double, 3>& n : corners.normals)
    text.text("vn ").number(n[0]).ch(' ').number(n[1]).ch(' ').number(n[2]).ch('\n');
  const auto every_corner = [&soup](const std::vector<Index>& records, std::size_t f) {
    if (records.empty())
      return false;
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      if (records[c] == kNoIndex)
        return false;
    }
    return true;
  };
  const std::vector<FaceGroup>* groups = attributes != nullptr && !attributes->face_groups.empty()
                                             ? &attributes->face_groups
                                             : nullptr;
  std::size_t current_group = static_cast<std::size_t>(-1);
  std::size_t written_end = 0;  // one past the last group line written
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (groups != nullptr) {
      // The last group starting at or before the input face (none before the first group).
      const Index origin = input_face(mesh, f);
      const auto after =
          std::upper_bound(groups->begin(), groups->end(), origin,
                           [](Index face, const FaceGroup& g) { return face < g.first_face; });
      if (after != groups->begin()) {
        // Every group line that starts at the same face applies (e.g. "g a" then "usemtl m").
        auto first = after - 1;
        while (first != groups->begin() && (first - 1)->first_face == first->first_face)
          --first;
        const std::size_t index = static_cast<std::size_t>(first - groups->begin());
        if (index != current_group) {
          for (auto g = first; g != after; ++g)
            text.text(g->name).ch('\n');
          current_group = index;
          written_end = static_cast<std::size_t>(after - groups->begin());
        }
      }
    }
    text.ch('f');
    const bool texture = every_corner(corners.corner_texture, f);
    const bool normal = every_corner(corners.corner_normal, f);
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      text.ch(' ').number(static_cast<std::uint64_t>(soup.corner_vertices[c]) + 1);
      if (texture || normal) {
        text.ch('/');
        if (texture)
          text.number(static_cast<std::uint64_t>(corners.corner_texture[c]) + 1);
        if (normal)
          text.ch('/').number(static_cast<std::uint64_t>(corners.corner_normal[c]) + 1);
      }
    }
    text.ch('\n');
  }
  // Group lines after the input's last face (a trailing "g" or "usemtl") follow the faces.
  for (std::size_t g = written_end; groups != nullptr && g < groups->size(); ++g)
    text.text((*groups)[g].name).ch('\n');
  text.flush();
}

}  // namespace meshbridge::detail
