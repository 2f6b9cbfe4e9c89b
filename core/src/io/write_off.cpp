// SPDX-License-Identifier: GPL-3.0-or-later
// OFF writer: "OFF" (or "COFF" with vertex colours), counts, "x y z [r g b [a]]" with the
// shortest exact decimals, "n i j k ... [r g b [a]]" with the colour of each face that had one
// (alpha where the input's colours have it).

#include "io/formats.h"
#include "io/text_output.h"

namespace meshbridge::detail {

namespace {

void put_color(TextOutput& text, const Rgba& c, bool alpha) {
  text.ch(' ').number(unsigned(c.r)).ch(' ').number(unsigned(c.g)).ch(' ').number(unsigned(c.b));
  if (alpha)
    text.ch(' ').number(unsigned(c.a));
}

}  // namespace

void write_off(AtomicOutput& out, const IndexedMesh& mesh, const MeshAttributes* attributes,
               const WriteOptions&) {
  const Soup& soup = mesh.soup;
  const bool vertex_colors = attributes != nullptr && !attributes->vertex_colors.empty();
  const bool face_colors = attributes != nullptr && !attributes->face_colors.empty();
  const bool vertex_alpha =
      vertex_colors && (attributes->vertex_color_channels & kAlphaChannel) != 0;
  const bool face_alpha = face_colors && (attributes->face_color_channels & kAlphaChannel) != 0;
  TextOutput text(out);
  text.text(vertex_colors ? "COFF\n" : "OFF\n");
  text.number(static_cast<std::uint64_t>(soup.num_vertices())).ch(' ');
  text.number(static_cast<std::uint64_t>(soup.num_faces())).text(" 0\n");
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const Point& p = soup.positions[v];
    text.number(p[0]).ch(' ').number(p[1]).ch(' ').number(p[2]);
    if (vertex_colors)  // COFF: every vertex has a colour (white if the input vertex had none)
      put_color(text, color_of(attributes->vertex_colors, input_vertex(mesh, v)), vertex_alpha);
    text.ch('\n');
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    text.number(static_cast<std::uint64_t>(soup.arity(f)));
    for (Index v : soup.polygon(f))
      text.ch(' ').number(static_cast<std::uint64_t>(v));
    const Index origin = face_colors ? input_face(mesh, f) : kNoIndex;
    if (face_colors && has_color(attributes->face_colors, attributes->face_color_missing, origin))
      put_color(text, attributes->face_colors[origin], face_alpha);
    text.ch('\n');
  }
  text.flush();
}

}  // namespace meshbridge::detail
