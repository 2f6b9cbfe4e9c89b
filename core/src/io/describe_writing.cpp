// SPDX-License-Identifier: GPL-3.0-or-later
// What a write leaves out of what the reader kept: the output format's limits, named so that no
// attribute is lost without a word.

#include "geometry/triangulate.h"
#include "io/formats.h"
#ifdef MESHBRIDGE_WITH_3MF
#include "io/objects_3mf.h"
#endif
#include "meshbridge/counted.h"
#include "meshbridge/io.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <utility>
#include <vector>

namespace meshbridge {

namespace {

const char* name_of(detail::Format format) {
  switch (format) {
    case detail::Format::obj:
      return "OBJ";
    case detail::Format::off:
      return "OFF";
    case detail::Format::ply:
      return "PLY";
    case detail::Format::stl:
      return "STL";
    case detail::Format::threemf:
      return "3MF";
    case detail::Format::unknown:
      break;
  }
  return "this format";
}

//! The red, green and blue channels missing from `channels` (ColorChannel bits), e.g. "green
//! and blue"; empty when all three are there.
std::string missing_rgb(std::uint8_t channels) {
  std::vector<const char*> names;
  if ((channels & kRedChannel) == 0)
    names.push_back("red");
  if ((channels & kGreenChannel) == 0)
    names.push_back("green");
  if ((channels & kBlueChannel) == 0)
    names.push_back("blue");
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k)
    text += std::string(k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return text;
}

//! A length as text, to a float's precision ("1.52587891e-05" as "1.5258789e-05").
std::string shortest(double length) {
  char digits[32];
  const auto end = std::to_chars(digits, digits + sizeof digits, static_cast<float>(length)).ptr;
  return std::string(digits, end);
}

//! The plural of a 3MF unit name: "inches", "feet", "microns".
std::string units(const std::string& unit) {
  if (unit == "inch")
    return "inches";
  if (unit == "foot")
    return "feet";
  return unit + "s";
}

std::size_t missing_count(const std::vector<bool>& missing) {
  return static_cast<std::size_t>(std::count(missing.begin(), missing.end(), true));
}

//! The names of `metadata`, e.g. "Title, Designer".
std::string metadata_names(const std::vector<Metadata>& metadata) {
  std::string text;
  for (const Metadata& entry : metadata)
    text += (text.empty() ? "" : ", ") + entry.name;
  return text;
}

}  // namespace

std::string describe_face_objects(const std::vector<FaceObject>& face_objects) {
  std::vector<std::pair<FaceObject, std::size_t>> kinds;
  for (const FaceObject& kind : face_objects) {
    if (kind.is_printed_model())
      continue;
    const auto known =
        std::find_if(kinds.begin(), kinds.end(), [&](const auto& k) { return k.first == kind; });
    if (known == kinds.end())
      kinds.emplace_back(kind, 1);
    else
      ++known->second;
  }
  std::string text;
  for (const auto& [kind, count] : kinds) {
    text += (text.empty() ? "" : ", ") + counted(count, "face");
    if (kind.type != ObjectType::model)
      text += std::string(" of type ") + object_type_name(kind.type);
    if (!kind.in_build)
      text +=
          kind.type != ObjectType::model ? " in no build item" : " of an object in no build item";
  }
  return text;
}

const char* object_type_name(ObjectType type) {
  switch (type) {
    case ObjectType::model:
      return "model";
    case ObjectType::support:
      return "support";
    case ObjectType::solidsupport:
      return "solidsupport";
    case ObjectType::surface:
      return "surface";
    case ObjectType::other:
      break;
  }
  return "other";
}

std::vector<std::string> describe_unwritten(const std::string& path,
                                            const MeshAttributes& attributes) {
  using detail::Format;
  const Format format = mesh_format(path);
  const std::string name = name_of(format);
  std::vector<std::string> lost;
  // OBJ writes the records it kept (CornerAttributes); the other formats hold none per corner.
  const CornerAttributes& corners = attributes.corners;
  const bool corners_kept = corners.texture_coordinates.size() == attributes.texture_coordinates &&
                            corners.normals.size() == attributes.normals;
  if (attributes.texture_coordinates + attributes.normals > 0 &&
      !(format == Format::obj && corners_kept)) {
    std::string what;
    if (attributes.texture_coordinates > 0)
      what = counted(attributes.texture_coordinates, "texture coordinate") + " (vt)";
    if (attributes.texture_coordinates > 0 && attributes.normals > 0)
      what += " and ";
    if (attributes.normals > 0)
      what += counted(attributes.normals, "normal") + " (vn)";
    lost.push_back(what + " not written: " +
                   (format == Format::obj
                        ? std::string("they were not kept (read without them)")
                        : name + " holds none per corner (write OBJ to keep them)"));
  }
  const bool writes_vertex_colors =
      format == Format::obj || format == Format::off || format == Format::ply;
  const bool writes_face_colors = format == Format::off || format == Format::ply;
  for (const NotKept& n : attributes.not_kept) {
    // Clamped colours that the output holds none of: the colours are named below as not written.
    if (n.clamped && !(n.noun == "face" ? writes_face_colors : writes_vertex_colors))
      continue;
    lost.push_back(
        n.what + ", on " + counted(n.count, n.noun) +
        (n.clamped ? ": written clamped" : ": not written (MeshBridge reads past them)"));
  }
  const bool vertex_colors = !attributes.vertex_colors.empty();
  const bool face_colors = !attributes.face_colors.empty();
  // MeshBridge's 3MF writer writes the core specification only (no materials extension).
  const std::string none = format == Format::threemf ? ": MeshBridge writes no 3MF materials"
                                                     : ": " + name + " holds none";
  if (vertex_colors && (format == Format::stl || format == Format::threemf))
    lost.push_back("vertex colours not written" + none);
  if (face_colors && (format == Format::obj || format == Format::stl || format == Format::threemf))
    lost.push_back("face colours not written" + none);
  // OBJ and OFF colours are red, green and blue: a channel the file lacked (a PLY of red only)
  // is written as 0.
  const bool rgb_format = format == Format::obj || format == Format::off;
  const std::string vertex_missing = missing_rgb(attributes.vertex_color_channels);
  if (vertex_colors && rgb_format && !vertex_missing.empty()) {
    lost.push_back("vertex colours written with " + vertex_missing + " 0: the file gave no " +
                   vertex_missing + ", and " + name + " colours have red, green and blue");
  }
  const std::string face_missing = missing_rgb(attributes.face_color_channels);
  if (face_colors && format == Format::off && !face_missing.empty()) {
    lost.push_back("face colours written with " + face_missing + " 0: the file gave no " +
                   face_missing + ", and OFF colours have red, green and blue");
  }
  // A colour on every element or none: the elements the file left without one get white.
  const std::size_t vertices_without = missing_count(attributes.vertex_color_missing);
  if (vertex_colors && vertices_without > 0 && (format == Format::ply || format == Format::off)) {
    lost.push_back(counted(vertices_without, "vertex") + " without a colour written white: " +
                   name + " gives every vertex a colour or none");
  }
  const std::size_t faces_without = missing_count(attributes.face_color_missing);
  if (face_colors && faces_without > 0 && format == Format::ply) {
    lost.push_back(counted(faces_without, "face") +
                   " without a colour written white: PLY gives every face a colour or none");
  }
  // STL, OBJ, OFF and PLY have no unit: slicers read them as millimetres.
  if (format != Format::threemf && !attributes.length_unit.empty() &&
      attributes.length_unit != "millimeter") {
    lost.push_back("3MF unit '" + attributes.length_unit + "' not written: " + name +
                   " has no unit, and the coordinates stay as written, in " +
                   units(attributes.length_unit) + " (a slicer reads them as millimetres)");
  }
  // Supports, surfaces and objects in no build item: 3MF keeps each an object of its own.
  const std::string others = describe_face_objects(attributes.face_objects);
  if (format != Format::threemf && !others.empty()) {
    lost.push_back("3MF objects that are not the printed model (" + others +
                   ") written into the one mesh with the model: " + name +
                   " has no objects, so a slicer prints them as part of the model (write 3MF "
                   "to keep them apart)");
  }
  if (format != Format::threemf && !attributes.metadata.empty()) {
    lost.push_back("3MF metadata not written (" + counted(attributes.metadata.size(), "entry") +
                   ": " + metadata_names(attributes.metadata) + "): " + name + " holds none");
  }
  if (format != Format::obj &&
      (!attributes.face_groups.empty() || !attributes.material_libraries.empty())) {
    lost.push_back("OBJ groups and materials not written (" +
                   counted(attributes.face_groups.size(), "o/g/usemtl line") + ", " +
                   counted(attributes.material_libraries.size(), "mtllib line") + "): " + name +
                   " holds none");
  }
  return lost;
}

std::vector<std::string> describe_not_held(const MeshAttributes& attributes) {
  std::vector<std::string> held_elsewhere;
  if (!attributes.vertex_colors.empty()) {
    const std::size_t without = missing_count(attributes.vertex_color_missing);
    held_elsewhere.push_back("vertex colours (" +
                             counted(attributes.vertex_colors.size() - without, "vertex") + ")");
  }
  if (!attributes.face_colors.empty()) {
    const std::size_t without = missing_count(attributes.face_color_missing);
    held_elsewhere.push_back("face colours (" +
                             counted(attributes.face_colors.size() - without, "face") + ")");
  }
  if (!attributes.face_groups.empty() || !attributes.material_libraries.empty()) {
    held_elsewhere.push_back("OBJ groups and materials (" +
                             counted(attributes.face_groups.size(), "o/g/usemtl line") + ", " +
                             counted(attributes.material_libraries.size(), "mtllib line") + ")");
  }
  if (attributes.texture_coordinates > 0)
    held_elsewhere.push_back(counted(attributes.texture_coordinates, "texture coordinate") +
                             " (vt)");
  if (attributes.normals > 0)
    held_elsewhere.push_back(counted(attributes.normals, "normal") + " (vn)");
  if (!attributes.length_unit.empty() && attributes.length_unit != "millimeter")
    held_elsewhere.push_back("3MF unit '" + attributes.length_unit + "'");
  const std::string others = describe_face_objects(attributes.face_objects);
  if (!others.empty())
    held_elsewhere.push_back("3MF objects that are not the printed model (" + others + ")");
  if (!attributes.metadata.empty()) {
    held_elsewhere.push_back("3MF metadata (" + counted(attributes.metadata.size(), "entry") +
                             ": " + metadata_names(attributes.metadata) + ")");
  }
  for (const NotKept& n : attributes.not_kept)
    held_elsewhere.push_back(n.what + ", on " + counted(n.count, n.noun));
  return held_elsewhere;
}

namespace {

WrittenOutput describe_written(const std::string& path, const Soup& soup,
                               const std::vector<Index>& face_origin,
                               const MeshAttributes& attributes, std::size_t vertices_welded) {
  WrittenOutput written;
  const detail::Format format = mesh_format(path);
  written.left_out = describe_unwritten(path, attributes);
  if (vertices_welded > 0 && !attributes.vertex_colors.empty()) {
    written.left_out.push_back("colours of " + counted(vertices_welded, "welded vertex") +
                               " not written: each takes the colour of the vertex it welded into");
  }
  // OBJ: the faces hole filling added have no input corner to take a vt or vn from.
  const CornerAttributes& corners = attributes.corners;
  if (format == detail::Format::obj &&
      (!corners.corner_texture.empty() || !corners.corner_normal.empty())) {
    const std::size_t added =
        static_cast<std::size_t>(std::count(face_origin.begin(), face_origin.end(), kNoIndex));
    if (added > 0) {
      const bool both = !corners.corner_texture.empty() && !corners.corner_normal.empty();
      written.left_out.push_back(
          counted(added, "face") + " added by hole filling written without " +
          (!corners.corner_texture.empty() ? "texture coordinates (vt)" : "") +
          (both ? " and " : "") + (!corners.corner_normal.empty() ? "normals (vn)" : "") +
          ": they have no input corner to take them from");
    }
  }
  if (format == detail::Format::stl || format == detail::Format::threemf) {
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      written.triangles += detail::polygon_triangle_count(soup, f);
      written.polygons_triangulated += soup.arity(f) > 3 ? 1 : 0;
    }
    std::size_t rounded = 0;  // vertices with a coordinate that is not exactly a float
    for (const Point& p : soup.positions) {
      rounded += static_cast<double>(static_cast<float>(p[0])) != p[0] ||
                 static_cast<double>(static_cast<float>(p[1])) != p[1] ||
                 static_cast<double>(static_cast<float>(p[2])) != p[2];
    }
    if (rounded > 0) {
      written.left_out.push_back("positions of " + counted(rounded, "vertex") +
                                 " rounded to 32-bit floats: " + name_of(format) +
                                 " holds no more");
    }
  }
#ifdef MESHBRIDGE_WITH_3MF
  if (format == detail::Format::threemf) {
    const detail::ThreeMfRounding r = detail::measure_3mf_rounding(
        path, soup, detail::output_face_objects(soup, face_origin, attributes.face_objects));
    if (r.moved > 0) {
      written.left_out.push_back("positions of " + counted(r.moved, "vertex") + " moved by up to " +
                                 shortest(r.largest_move) +
                                 " as lib3mf wrote them (3MF text, at most 6 decimals)");
    }
    if (r.collapsed > 0) {
      written.left_out.push_back(
          counted(r.collapsed, "triangle") +
          " written with two corners at one point: the mesh is finer than lib3mf's 6 decimals "
          "(write STL or PLY, or scale it up)");
    }
  }
#endif
  return written;
}

}  // namespace

WrittenOutput describe_written(const std::string& path, const Soup& soup,
                               const MeshAttributes& attributes, std::size_t vertices_welded) {
  return describe_written(path, soup, {}, attributes, vertices_welded);
}

WrittenOutput describe_written(const std::string& path, const IndexedMesh& mesh,
                               const MeshAttributes& attributes, std::size_t vertices_welded) {
  return describe_written(path, mesh.soup, mesh.face_origin, attributes, vertices_welded);
}

}  // namespace meshbridge
