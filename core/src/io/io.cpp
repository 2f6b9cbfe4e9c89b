// SPDX-License-Identifier: GPL-3.0-or-later
// The dispatcher: picks the reader or writer by extension, then checks and accounts for what
// every reader produced the same way (formats.h states the contract).

#include "meshbridge/io.h"
#include "meshbridge/validate.h"

#include "io/atomic_write.h"
#include "io/formats.h"
#include "io/mapped_file.h"
#include "io/repeated_vertices.h"
#include "meshbridge/counted.h"
#include "meshbridge/errors.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

namespace meshbridge {

MeshFormat mesh_format(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return MeshFormat::unknown;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (ext == "obj")
    return MeshFormat::obj;
  if (ext == "off")
    return MeshFormat::off;
  if (ext == "ply")
    return MeshFormat::ply;
  if (ext == "stl")
    return MeshFormat::stl;
  if (ext == "3mf")
    return MeshFormat::threemf;
  return MeshFormat::unknown;
}

namespace {

using detail::Format;

// Attributes belong to the input soup: every origin the mesh refers to must have its colour.
void check_attributes(const std::string& path, const IndexedMesh& mesh,
                      const MeshAttributes* attributes) {
  if (attributes == nullptr)
    return;
  const auto check = [&](std::size_t colors, std::size_t count, const std::vector<Index>& origin,
                         const char* what) {
    if (colors == 0)
      return;
    std::size_t needed = origin.empty() ? count : 0;
    for (Index o : origin) {
      if (o != kNoIndex)  // a face repair added (hole filling) has no input colour
        needed = std::max<std::size_t>(needed, std::size_t(o) + 1);
    }
    if (colors < needed) {
      throw WriteError(path + ": the attributes hold " + std::to_string(colors) + " " + what +
                       "(s) but the mesh needs " + std::to_string(needed) +
                       " (attributes of another mesh?)");
    }
  };
  check(attributes->vertex_colors.size(), mesh.soup.num_vertices(), mesh.vertex_origin,
        "vertex colour");
  check(attributes->face_colors.size(), mesh.soup.num_faces(), mesh.face_origin, "face colour");
  check(attributes->face_objects.size(), mesh.soup.num_faces(), mesh.face_origin,
        "face's 3MF object");
  const auto check_flags = [&](std::size_t flags, std::size_t colors, const char* what) {
    if (flags != 0 && flags != colors) {
      throw WriteError(path + ": the attributes hold " + std::to_string(flags) + " " + what +
                       " missing-colour flag(s) for " + std::to_string(colors) +
                       " colour(s) (expected none or one per colour)");
    }
  };
  check_flags(attributes->vertex_color_missing.size(), attributes->vertex_colors.size(), "vertex");
  check_flags(attributes->face_color_missing.size(), attributes->face_colors.size(), "face");
}

// True if the start of a text file has line ends but every one is a CR alone (no LF at all).
bool has_cr_line_ends_only(const detail::MappedFile& file) {
  const std::size_t n = std::min<std::size_t>(file.size(), std::size_t(1) << 16);
  return std::memchr(file.data(), '\n', n) == nullptr &&
         std::memchr(file.data(), '\r', n) != nullptr;
}

// A face corner past the file's last vertex is a malformed file: throws the ReadError that names
// the first one (OBJ: by its line, read again; the reader could not tell, as an OBJ face may name
// a vertex written after it). Returns if there is none.
void name_index_out_of_range(const detail::MappedFile& file, Format format, const Soup& soup) {
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView polygon = soup.polygon(f);
    for (std::size_t c = 0; c < polygon.size(); ++c) {
      if (polygon[c] < soup.num_vertices())
        continue;
      if (format == Format::obj)
        detail::throw_obj_index_out_of_range(file, {f, c, soup.num_vertices()});
      throw ReadError(file.path() + ": face " + std::to_string(f + 1) + ", corner " +
                      std::to_string(c + 1) + " refers to vertex index " +
                      std::to_string(polygon[c]) + ", but the file has " +
                      counted(soup.num_vertices(), "vertex") + " (counting from 0)");
    }
  }
}

}  // namespace

bool is_supported_mesh_file(const std::string& path) {
  return mesh_format(path) != Format::unknown;
}

Soup read_soup(const std::string& path, ReadInfo* info, MeshAttributes* attributes) {
  const detail::MappedFile file(path);  // missing, directory, empty: ReadError
  const Format format = mesh_format(path);
  if (format == Format::unknown)
    throw ReadError(path + ": unknown format (expected .obj, .off, .ply, .stl or .3mf)");

  if ((format == Format::obj || format == Format::off) && has_cr_line_ends_only(file)) {
    throw ReadError(path +
                    ": its lines end in CR alone (classic Mac OS text); MeshBridge reads "
                    "LF or CRLF line ends: convert the file first (tr '\\r' '\\n')");
  }
  Soup soup;
  ReadInfo counts;
  if (attributes != nullptr)
    *attributes = MeshAttributes();
  switch (format) {
    case Format::obj:
      detail::read_obj(file, soup, counts, attributes);
      break;
    case Format::off:
      detail::read_off(file, soup, counts, attributes);
      break;
    case Format::ply:
      detail::read_ply(file, soup, counts, attributes);
      break;
    case Format::stl:
      detail::read_stl(file, soup, counts, attributes);
      break;
    case Format::threemf:
#ifdef MESHBRIDGE_WITH_3MF
      detail::read_3mf(file, soup, counts, attributes);
#else
      throw ReadError(path + ": this build of MeshBridge has no 3MF support (lib3mf 1.x)");
#endif
      break;
    case Format::unknown:
      break;
  }
  if (soup.num_faces() == 0) {
    const std::string looks_like = detail::other_format_hint(file.view(), format);
    throw ReadError(
        path + ": no polygons in the file (" + std::to_string(soup.num_vertices()) + " vertices" +
        (counts.dangling_edges > 0 ? ", " + std::to_string(counts.dangling_edges) + " edges"
                                   : std::string()) +
        (counts.lone_points > 0 ? ", " + std::to_string(counts.lone_points) + " points"
                                : std::string()) +
        (counts.empty_records > 0
             ? ", " + counted(counts.empty_records, "record") + " holding no face, such as a " +
                   "strip run of fewer than 3 vertices"
             : std::string()) +
        ")" +
        (counts.trailing_bytes > 0
             ? "; " + counted(counts.trailing_bytes, "byte") +
                   " follow the last declared element: a false count in the header?"
             : std::string()) +
        (counts.unknown_records > 0 && looks_like.empty()
             ? "; " + counted(counts.unknown_records, "line") +
                   " with an unknown keyword skipped (a misspelt or upper-case 'f'?)"
             : std::string()) +
        looks_like);
  }
  counts.float_coordinates = format == Format::stl || format == Format::threemf;
  // STL corners are welded by position already, and an OBJ soup may be welded while read.
  if (format != Format::stl && counts.vertices_welded_by_position == 0)
    counts.vertices_welded_by_position = detail::weld_repeated_vertices(soup, attributes);
  try {
    detail::account_faces(soup, counts);  // validates the soup on the way
  } catch (const InvalidSoupError& error) {
    name_index_out_of_range(file, format, soup);
    throw InvalidSoupError(path + ": " + error.what());
  }
  if (info != nullptr)
    *info = counts;
  return soup;
}

void write_file_atomically(const std::string& path,
                           const std::function<void(const std::string& temporary_path)>& fill) {
  detail::write_atomically(path, [&](detail::AtomicOutput& out) { fill(out.temporary_path()); });
}

void write_bytes_atomically(const std::string& path, std::string_view bytes) {
  detail::write_atomically(path, [&](detail::AtomicOutput& out) { out.write(bytes); });
}

void write_mesh(const std::string& path, const IndexedMesh& mesh, const MeshAttributes* attributes,
                const WriteOptions& options) {
  const Format format = mesh_format(path);
  if (format == Format::unknown)
    throw WriteError(path + ": unknown format (expected .obj, .off, .ply, .stl or .3mf)");
  // A writer indexes positions by every corner: an index out of range would write (or crash on)
  // memory beyond them, and a non-finite coordinate a file no reader takes back.
  try {
    validate_soup(mesh.soup);
  } catch (const InvalidSoupError& error) {
    throw InvalidSoupError(path + ": not written: " + error.what());
  }
  check_attributes(path, mesh, attributes);
  detail::write_atomically(path, [&](detail::AtomicOutput& out) {
    switch (format) {
      case Format::obj:
        detail::write_obj(out, mesh, attributes, options);
        break;
      case Format::off:
        detail::write_off(out, mesh, attributes, options);
        break;
      case Format::ply:
        detail::write_ply(out, mesh, attributes, options);
        break;
      case Format::stl:
        detail::write_stl(out, mesh, attributes, options);
        break;
      case Format::threemf:
#ifdef MESHBRIDGE_WITH_3MF
        detail::write_3mf(out, mesh, attributes, options);
#else
        throw WriteError(path + ": this build of MeshBridge has no 3MF support (lib3mf 1.x)");
#endif
        break;
      case Format::unknown:
        break;
    }
  });
}

}  // namespace meshbridge
