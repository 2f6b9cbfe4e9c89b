// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/openmesh_legacy.h"

#include "meshbridge/io.h"

#include "meshbridge/errors.h"
#include "meshbridge/mesh_types.h"
#include "meshbridge/validate.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <sys/stat.h>
#include <unistd.h>
#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

// TEMPORARY: the previous OpenMesh-based reading and writing, moved here unchanged so that
// formats not yet read by MeshBridge's own code keep working. Delete with the last user.

namespace meshbridge::detail {

namespace {

using OpenMesh::IO::BaseImporter;

// Captures what a reader reports, unchanged: no add_face is refused, no vertex duplicated.
class SoupImporter : public BaseImporter {
 public:
  //! \param file_size bounds what reserve() believes: no header makes it reserve more than a
  //! file of this size can hold.
  //! The reader may add at most file_size / 2 + 16 vertices and file_size + 16 faces: every
  //! format spends at least 2 bytes on a vertex ("v\n", three int8 coordinates) and 1 on a face
  //! (a binary PLY corner count). More means the reader loops on a header count with nothing
  //! behind it (e.g. a PLY vertex element without properties): add_vertex and add_face then
  //! throw ReadError instead of letting the soup grow to gigabytes.
  SoupImporter(Soup& soup, const std::string& path, std::uintmax_t file_size)
      : soup_(soup),
        path_(path),
        file_size_(file_size),
        max_vertices_(file_size / 2 + 16),
        max_faces_(file_size + 16) {}

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return add_vertex(OpenMesh::Vec3d(p[0], p[1], p[2]));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    if (soup_.num_vertices() >= max_vertices_)
      throw_fabricated("vertices", max_vertices_);
    return OpenMesh::VertexHandle(static_cast<int>(soup_.add_vertex(p)));
  }
  OpenMesh::VertexHandle add_vertex() override { return add_vertex(OpenMesh::Vec3d(0, 0, 0)); }
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    ++edges_;
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(const VHandles& indices) override {
    if (soup_.num_faces() >= max_faces_)
      throw_fabricated("faces", max_faces_);
    for (const auto& vh : indices) {
      if (vh.idx() < 0) {
        bad_index_ = "face " + std::to_string(soup_.num_faces()) + " refers to vertex index " +
                     std::to_string(vh.idx());
      }
    }
    for (const auto& vh : indices)
      soup_.corner_vertices.push_back(static_cast<Index>(vh.idx()));
    soup_.face_begin.push_back(static_cast<Index>(soup_.corner_vertices.size()));
    return OpenMesh::FaceHandle(static_cast<int>(soup_.num_faces() - 1));
  }
  OpenMesh::FaceHandle add_face(OpenMesh::HalfedgeHandle) override {
    return OpenMesh::FaceHandle();
  }
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(OpenMesh::FaceHandle, OpenMesh::VertexHandle,
                          const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(OpenMesh::FaceHandle, int) override {}
  void set_point(OpenMesh::VertexHandle vh, const OpenMesh::Vec3f& p) override {
    if (vh.idx() >= 0 && static_cast<std::size_t>(vh.idx()) < soup_.num_vertices()) {
      soup_.positions[vh.idx()] = OpenMesh::Vec3d(p[0], p[1], p[2]);
    }
  }
  void set_halfedge(OpenMesh::VertexHandle, OpenMesh::HalfedgeHandle) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::VertexHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::VertexHandle, const OpenMesh::Vec4f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec2f&) override {}
  void set_status(OpenMesh::VertexHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(OpenMesh::HalfedgeHandle, OpenMesh::HalfedgeHandle) override {}
  void set_face(OpenMesh::HalfedgeHandle, OpenMesh::FaceHandle) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec2f&) override {}
  void set_texcoord(OpenMesh::VertexHandle, const OpenMesh::Vec3f&) override {}
  void set_texcoord(OpenMesh::HalfedgeHandle, const OpenMesh::Vec3f&) override {}
  void set_status(OpenMesh::HalfedgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::EdgeHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::EdgeHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_normal(OpenMesh::FaceHandle, const OpenMesh::Vec3d&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4uc&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec3f&) override {}
  void set_color(OpenMesh::FaceHandle, const OpenMesh::Vec4f&) override {}
  void set_status(OpenMesh::FaceHandle, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
  void reserve(unsigned int vertices, unsigned int, unsigned int faces) override {
    // Headers may lie: reserve only what a file of this size could hold (a vertex takes at
    // least 3 bytes, a face 2), and never more than 2^24 elements up front.
    const std::uintmax_t cap = std::min<std::uintmax_t>(1u << 24, file_size_ / 2 + 16);
    const std::size_t v = static_cast<std::size_t>(std::min<std::uintmax_t>(vertices, cap));
    const std::size_t f = static_cast<std::size_t>(std::min<std::uintmax_t>(faces, cap));
    soup_.reserve(v, f, 3 * f);
  }
  std::size_t n_vertices() const override { return soup_.num_vertices(); }
  std::size_t n_faces() const override { return soup_.num_faces(); }
  std::size_t n_edges() const override { return edges_; }

  const std::string& bad_index() const { return bad_index_; }

 private:
  [[noreturn]] void throw_fabricated(const char* what, std::uintmax_t limit) const {
    throw ReadError(path_ + ": OpenMesh's reader produced more than " + std::to_string(limit) +
                    " " + what + ", more than a file of " + std::to_string(file_size_) +
                    " bytes can hold (a header count with no data behind it)");
  }

  Soup& soup_;
  std::string path_;
  std::uintmax_t file_size_ = 0;
  std::uintmax_t max_vertices_ = 0;
  std::uintmax_t max_faces_ = 0;
  std::size_t edges_ = 0;
  std::string bad_index_;
};

// Collects what OpenMesh prints on its error stream (and its readers print on std::cerr directly)
// while a reader or writer runs, by pointing std::cerr at a buffer meanwhile. OpenMesh's progress
// log (omlog) is muted too: a library does not print. (Connecting and disconnecting a target of
// omerr() per call instead leaks: OpenMesh's multiplex_streambuf::disconnect forgets the target
// without deleting it.)
class CapturedOpenMeshErrors {
 public:
  CapturedOpenMeshErrors()
      : previous_(std::cerr.rdbuf(captured_.rdbuf())),
        log_was_enabled_(omlog().is_enabled()),
        errors_were_enabled_(omerr().is_enabled()) {
    omlog().disable();
  }
  // Restores both streams: a reader that disables omerr() for a while does not re-enable it when
  // the importer throws through it.
  ~CapturedOpenMeshErrors() {
    omerr().flush();
    std::cerr.rdbuf(previous_);
    if (log_was_enabled_)
      omlog().enable();
    if (errors_were_enabled_)
      omerr().enable();
  }
  CapturedOpenMeshErrors(const CapturedOpenMeshErrors&) = delete;
  CapturedOpenMeshErrors& operator=(const CapturedOpenMeshErrors&) = delete;

  //! What was printed, lines joined by "; " (at most 300 characters).
  std::string text() {
    omerr().flush();
    std::string printed = captured_.str();
    while (!printed.empty() && std::isspace(static_cast<unsigned char>(printed.back())))
      printed.pop_back();
    for (auto at = printed.find('\n'); at != std::string::npos; at = printed.find('\n', at))
      printed.replace(at, 1, "; ");
    return printed.size() > 300 ? printed.substr(0, 300) + "..." : printed;
  }

 private:
  std::ostringstream captured_;  // declared first: constructed before std::cerr points at it
  std::streambuf* previous_;
  bool log_was_enabled_;
  bool errors_were_enabled_;
};

// Counts what the file itself declares, without OpenMesh: OBJ records, OFF and ASCII/binary PLY
// header counts. Returns {0, 0} where the format declares nothing (STL).
ReadInfo declared_counts(const std::string& path, const std::string& ext) {
  ReadInfo info;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  if (ext == "obj") {
    while (std::getline(in, line)) {
      std::size_t i = line.find_first_not_of(" \t");
      if (i == std::string::npos)
        continue;
      const char kind = line[i];
      if (kind == 'f' && line.find_first_not_of(" \t\r", i + 1) == std::string::npos) {
        ++info.declared_faces;  // "f" with no vertex at all: a face record OpenMesh skips
        continue;
      }
      if (i + 1 >= line.size())
        continue;
      const char after = line[i + 1];
      if (after != ' ' && after != '\t')
        continue;
      if (kind == 'v')
        ++info.declared_vertices;
      if (kind == 'f')
        ++info.declared_faces;
    }
  } else if (ext == "off") {
    // [ST][C][N][4]OFF, comments, then "V F E".
    std::string token;
    std::vector<std::string> tokens;
    while (tokens.size() < 3 && std::getline(in, line)) {
      const auto hash = line.find('#');
      if (hash != std::string::npos)
        line.erase(hash);
      std::istringstream words(line);
      while (words >> token && tokens.size() < 3) {
        if (token.find("OFF") != std::string::npos && tokens.empty())
          continue;
        tokens.push_back(token);
      }
    }
    if (tokens.size() == 3) {
      info.declared_vertices = std::strtoull(tokens[0].c_str(), nullptr, 10);
      info.declared_faces = std::strtoull(tokens[1].c_str(), nullptr, 10);
    }
  } else if (ext == "ply") {
    while (std::getline(in, line)) {
      std::istringstream words(line);
      std::string a, b, count;
      words >> a >> b >> count;
      if (a == "element" && b == "vertex")
        info.declared_vertices = std::strtoull(count.c_str(), nullptr, 10);
      if (a == "element" && b == "face")
        info.declared_faces = std::strtoull(count.c_str(), nullptr, 10);
      if (a == "end_header")
        break;
    }
  }
  return info;
}

// --- Checks before OpenMesh's readers run -----------------------------------------------------
//
// OpenMesh 9's OFF, PLY and STL readers trust the counts a file declares and keep going after
// their stream has failed: a header that lies makes them loop billions of times, push gigabytes
// of stale indices, pass on uninitialised values, weld a NaN onto an arbitrary vertex, or (a PLY
// header without end_header) never stop. The checks below replay the stream operations those
// readers will perform, in the same order and with the same types, store nothing, and throw a
// ReadError (InvalidSoupError for a non-finite coordinate) that names the problem. A file that
// passes is read by OpenMesh without a failed extraction, so everything it passes on is in the
// file. They return the number of faces the file declares (0: not known).

std::string count_text(std::uintmax_t n, const char* what) {
  return std::to_string(n) + " " + what;
}

// _OFFReader_::can_u_read's header flags: [ST][C][N][4][n]OFF[ BINARY].
struct OffHeader {
  bool readable = false, texcoords = false, colors = false, normals = false, binary = false;
};

OffHeader off_header(const std::string& first_line) {
  OffHeader h;
  const std::string& p = first_line;
  std::size_t i = 0;
  std::size_t remaining = p.size() + 1;  // getline's gcount counts the newline
  if (remaining > 1 && p.compare(0, 2, "ST") == 0) {
    h.texcoords = true;
    i += 2;
    remaining -= 2;
  }
  if (remaining > 0 && i < p.size() && p[i] == 'C') {
    h.colors = true;
    ++i;
    --remaining;
  }
  if (remaining > 0 && i < p.size() && p[i] == 'N') {
    h.normals = true;
    ++i;
    --remaining;
  }
  bool too_high = false;
  for (char dimension : {'4', 'n'}) {
    if (remaining > 0 && i < p.size() && p[i] == dimension) {
      too_high = true;
      ++i;
      --remaining;
    }
  }
  if (remaining < 3 || p.compare(i, 3, "OFF") != 0 || too_high)
    return h;
  i += 4;
  remaining = remaining >= 4 ? remaining - 4 : 0;
  h.binary = remaining >= 6 && i <= p.size() && p.compare(i, 6, "BINARY") == 0;
  h.readable = true;
  return h;
}

std::uint32_t little_endian_u32(const unsigned char* b) {
  return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
         std::uint32_t(b[3]) << 24;
}

std::size_t check_off(const std::string& path, std::uintmax_t size) {
  std::ifstream in(path, std::ios::binary);
  std::string first_line;
  std::getline(in, first_line);
  const OffHeader h = off_header(first_line);
  if (!h.readable)
    return 0;  // OpenMesh refuses it itself
  const std::string where = path + ": ";
  if (h.binary) {
    // Little-endian 32-bit words: V F E, vertices of 3 (+3 normal, +3 colour, +2 texcoord)
    // floats, faces of a count and that many indices.
    std::uintmax_t pos = static_cast<std::uintmax_t>(in.tellg());
    unsigned char word[12];
    if (!in.read(reinterpret_cast<char*>(word), 12))
      throw ReadError(where + "binary OFF ends before its vertex, face and edge counts");
    pos += 12;
    const std::uint32_t nv = little_endian_u32(word), nf = little_endian_u32(word + 4);
    const std::uintmax_t vertex_bytes =
        4u * (3u + (h.normals ? 3u : 0u) + (h.colors ? 3u : 0u) + (h.texcoords ? 2u : 0u));
    if (std::uintmax_t(nv) * vertex_bytes > size - pos) {
      throw ReadError(where + "binary OFF declares " + count_text(nv, "vertices") + " (" +
                      std::to_string(std::uintmax_t(nv) * vertex_bytes) + " bytes) but only " +
                      std::to_string(size - pos) +
                      " bytes follow its header (a truncated file or a false count)");
    }
    pos += std::uintmax_t(nv) * vertex_bytes;
    if (std::uintmax_t(nf) * 4 > size - pos) {
      throw ReadError(where + "binary OFF declares " + count_text(nf, "faces") + " but only " +
                      std::to_string(size - pos) + " bytes follow its vertices");
    }
    in.seekg(static_cast<std::streamoff>(pos));
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (size - pos < 4 || !in.read(reinterpret_cast<char*>(word), 4)) {
        throw ReadError(where + "binary OFF ends after " + std::to_string(f) + " of " +
                        count_text(nf, "faces"));
      }
      pos += 4;
      const std::uint32_t corners = little_endian_u32(word);
      if (std::uintmax_t(corners) * 4 > size - pos) {
        throw ReadError(where + "binary OFF face " + std::to_string(f) + " claims " +
                        count_text(corners, "corners") + ", more than the rest of the file holds");
      }
      pos += std::uintmax_t(corners) * 4;
      in.seekg(static_cast<std::streamoff>(pos));
    }
    return nf;
  }

  // ASCII: as _OFFReader_::read_ascii: counts, then per vertex 3 floats (+3 normal floats) and
  // the rest of the line; per face an unsigned corner count and that many unsigned indices (and
  // the rest of the line when the header has C).
  unsigned int nv = 0, nf = 0, ne = 0;
  in >> nv >> nf >> ne;
  if (in.fail()) {
    throw ReadError(where + "no vertex, face and edge counts on the line after '" +
                    first_line.substr(0, 20) + "' (OpenMesh's OFF reader allows no comments)");
  }
  // The shortest vertex record is "0 0 0\n", the shortest face record "0\n".
  if (nv > size / 6 || nf > size / 2) {
    throw ReadError(where + "the OFF header declares " + count_text(nv, "vertices") + " and " +
                    count_text(nf, "faces") + ", more than a file of " + count_text(size, "bytes") +
                    " can hold (a false or negative count)");
  }
  float x = 0;
  std::string rest;
  unsigned int v = 0;
  for (; v < nv && !in.eof(); ++v) {
    in >> x >> x >> x;
    if (h.normals)
      in >> x >> x >> x;
    if (in.fail()) {
      throw ReadError(where + "OFF vertex " + std::to_string(v) + " of " + std::to_string(nv) +
                      ": expected " + (h.normals ? "6" : "3") +
                      " numbers (a truncated file, a false count, or a value such as 'nan')");
    }
    std::getline(in, rest);
  }
  if (v < nv) {
    throw ReadError(where + "the file declares " + count_text(nv, "vertices") + " but ends after " +
                    std::to_string(v));
  }
  unsigned int corners = 0, index = 0;
  for (unsigned int f = 0; f < nf; ++f) {
    in >> corners;
    if (in.fail()) {
      throw ReadError(where + "OFF face " + std::to_string(f) + " of " + std::to_string(nf) +
                      " is missing: the file ends or has no corner count there");
    }
    const std::streamoff at = in.tellg();
    if (at < 0 || std::uintmax_t(corners) > (size - std::uintmax_t(at)) / 2 + 1) {
      throw ReadError(where + "OFF face " + std::to_string(f) + " claims " +
                      count_text(corners, "corners") + ", more than the rest of the file holds");
    }
    for (unsigned int c = 0; c < corners; ++c) {
      in >> index;
      if (in.fail()) {
        throw ReadError(where + "OFF face " + std::to_string(f) + ": corner " + std::to_string(c) +
                        " of " + std::to_string(corners) + " is missing or not a vertex index");
      }
    }
    if (h.colors)
      std::getline(in, rest);
  }
  return nf;
}

// The PLY header as _PLYReader_::can_u_read parses it.
enum class PlyType { unsupported, i8, u8, i16, u16, i32, u32, f32, f64 };
enum class PlyRole { coordinate, vertex_number, color, custom, vertex_indices };

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::unsupported;        // the entry type for lists
  PlyType count_type = PlyType::unsupported;  // lists only
  bool is_list = false;
  PlyRole role = PlyRole::custom;
};

struct PlyElement {
  std::string name;
  unsigned int count = 0;
  std::vector<PlyProperty> properties;
};

struct PlyHeader {
  bool readable = false;
  bool binary = false, big_endian = false;
  std::streamoff body = 0;
  unsigned int face_count = 0;
  int dimension = 0;
  std::vector<PlyElement> elements;
};

PlyType ply_type(const std::string& a, const std::string& b) {
  // The order of _PLYReader_::get_property_type: the first name that matches either word.
  static const std::pair<const char*, PlyType> names[] = {
      {"float32", PlyType::f32}, {"float64", PlyType::f64}, {"float", PlyType::f32},
      {"double", PlyType::f64},  {"int8", PlyType::i8},     {"uint8", PlyType::u8},
      {"char", PlyType::i8},     {"uchar", PlyType::u8},    {"int32", PlyType::i32},
      {"uint32", PlyType::u32},  {"int", PlyType::i32},     {"uint", PlyType::u32},
      {"int16", PlyType::i16},   {"uint16", PlyType::u16},  {"short", PlyType::i16},
      {"ushort", PlyType::u16}};
  for (const auto& [name, type] : names) {
    if (a == name || b == name)
      return type;
  }
  return PlyType::unsupported;
}

std::size_t ply_size(PlyType t) {
  switch (t) {
    case PlyType::i8:
    case PlyType::u8:
      return 1;
    case PlyType::i16:
    case PlyType::u16:
      return 2;
    case PlyType::i32:
    case PlyType::u32:
    case PlyType::f32:
      return 4;
    case PlyType::f64:
      return 8;
    default:
      return 0;
  }
}

bool is_type_name(const std::string& s) {
  return ply_type(s, s) != PlyType::unsupported;
}

PlyHeader ply_header(std::istream& in, const std::string& path) {
  PlyHeader h;
  std::string line;
  std::getline(in, line);
  const auto first = line.find_first_not_of(" \t\r\n");
  const auto last = line.find_last_not_of(" \t\r\n");
  line = first == std::string::npos ? "" : line.substr(first, last - first + 1);
  if (line != "ply" && line != "PLY")
    return h;
  std::string keyword, format;
  float version = 0;
  in >> keyword >> format >> version;
  if (format == "binary_little_endian" || format == "binary_big_endian") {
    h.binary = true;
    h.big_endian = format == "binary_big_endian";
  } else if (format != "ascii") {
    return h;  // OpenMesh refuses it itself
  }
  std::string element_name;
  std::streamoff before_keyword = in.tellg();
  in >> keyword;
  while (keyword != "end_header") {
    if (in.fail()) {
      throw ReadError(path +
                      ": the PLY header is malformed or has no end_header line "
                      "(OpenMesh's reader would never stop looking for it)");
    }
    if (keyword == "comment") {
      std::getline(in, line);
    } else if (keyword == "element") {
      PlyElement element;
      in >> element.name >> element.count;
      if (in.fail()) {
        throw ReadError(path + ": PLY element '" + element.name + "' has no readable count");
      }
      element_name = element.name;
      if (element.name == "face")
        h.face_count = element.count;
      h.elements.push_back(element);
    } else if (keyword == "property") {
      if (h.elements.empty())
        throw ReadError(path + ": PLY property before any element in the header");
      PlyProperty property;
      std::string a, b;
      in >> a;
      if (a == "list") {
        std::string count_type, entry_type;
        in >> count_type >> entry_type >> property.name;
        if (count_type != "uint8" && count_type != "uint16" && count_type != "uchar" &&
            count_type != "int") {
          return h;  // OpenMesh refuses it itself
        }
        property.is_list = true;
        property.count_type = ply_type(count_type, count_type);
        property.type = ply_type(entry_type, entry_type);
        if (element_name == "face" &&
            (property.name == "vertex_index" || property.name == "vertex_indices")) {
          property.role = PlyRole::vertex_indices;
          if (property.type == PlyType::unsupported || property.type == PlyType::f32 ||
              property.type == PlyType::f64) {
            throw ReadError(path + ": PLY face property '" + property.name + "' is a list of '" +
                            entry_type + "', not of integers");
          }
          h.elements.back().properties.clear();
        }
      } else {
        in >> b;
        property.type = ply_type(a, b);
        property.name = is_type_name(a) ? b : (is_type_name(b) ? a : "Unsupported");
        const std::string& n = property.name;
        if (element_name == "vertex") {
          if (n == "x" || n == "y" || n == "z")
            ++h.dimension;
          if (n == "x" || n == "y" || n == "z" || n == "nx" || n == "ny" || n == "nz" || n == "u" ||
              n == "s" || n == "v" || n == "t") {
            property.role = PlyRole::coordinate;
          } else if (n == "red" || n == "green" || n == "blue" || n == "alpha" ||
                     n == "diffuse_red" || n == "diffuse_green" || n == "diffuse_blue") {
            property.role = PlyRole::color;
          }
        } else if (element_name == "face" &&
                   (n == "red" || n == "green" || n == "blue" || n == "alpha")) {
          property.role = PlyRole::color;
        }
        if (property.type == PlyType::unsupported)
          property.role = PlyRole::custom;
      }
      h.elements.back().properties.push_back(property);
    }
    before_keyword = in.tellg();
    in >> keyword;
  }
  if (h.binary) {
    in.seekg(before_keyword);
    char c1 = 0, c2 = 0;
    in.get(c1);
    in.get(c2);
    h.body = before_keyword + (c1 == 0x0D && c2 == 0x0A ? 14 : 12);
  } else {
    h.body = in.tellg();
  }
  h.readable = true;
  return h;
}

std::uint32_t read_unsigned(const unsigned char* b, std::size_t size, bool big_endian) {
  std::uint32_t value = 0;
  for (std::size_t i = 0; i < size; ++i)
    value |= std::uint32_t(b[big_endian ? size - 1 - i : i]) << (8 * i);
  return value;
}

std::size_t check_ply(const std::string& path, std::uintmax_t size) {
  std::ifstream in(path, std::ios::binary);
  const PlyHeader h = ply_header(in, path);
  if (!h.readable)
    return 0;  // OpenMesh refuses it itself
  const std::string where = path + ": ";
  if (h.dimension != 3) {
    // OpenMesh's ASCII reader refuses this, its binary reader reads on and makes up vertices.
    throw ReadError(where + "the PLY vertex element has " + std::to_string(h.dimension) +
                    " coordinate properties (x, y, z), not 3");
  }
  const auto what = [&](const PlyElement& e, unsigned int i) {
    return "PLY " + e.name + " " + std::to_string(i) + " of " + std::to_string(e.count);
  };
  std::uintmax_t pos = static_cast<std::uintmax_t>(h.body);  // binary: where the data is
  for (const PlyElement& e : h.elements) {
    const bool is_face = e.name == "face";
    const unsigned int count = is_face && !h.binary ? h.face_count : e.count;
    if (count > 0 && e.properties.empty()) {
      throw ReadError(where + "PLY element '" + e.name + "' declares " +
                      count_text(count, "items") + " without any property");
    }
    if (h.binary) {
      // Vertex and other elements: every property one scalar (OpenMesh skips list properties
      // outside 'vertex_indices' as one scalar). Faces: 'vertex_indices' is a count and entries.
      std::uintmax_t fixed = 0;
      const PlyProperty* list = nullptr;
      for (const PlyProperty& p : e.properties) {
        if (is_face && p.role == PlyRole::vertex_indices)
          list = &p;
        else
          fixed += ply_size(p.type);
      }
      if (count > 0 && fixed == 0 && list == nullptr) {
        throw ReadError(where + "PLY element '" + e.name +
                        "' has only properties of unknown types");
      }
      const std::uintmax_t remaining = size - std::min(size, pos);
      if (list == nullptr) {
        if (std::uintmax_t(count) * fixed > remaining) {
          throw ReadError(where + "binary PLY ends inside element '" + e.name +
                          "': " + count_text(count, "items") + " of " + count_text(fixed, "bytes") +
                          " need " + std::to_string(std::uintmax_t(count) * fixed) + " bytes, " +
                          std::to_string(remaining) +
                          " remain (a truncated file or a false count)");
        }
        pos += std::uintmax_t(count) * fixed;
      } else {
        const std::size_t count_bytes = ply_size(list->count_type);
        const std::size_t entry_bytes = ply_size(list->type);
        if (std::uintmax_t(count) * (fixed + count_bytes) > remaining) {
          throw ReadError(where + "binary PLY declares " + count_text(count, "faces") +
                          ", more than the " + std::to_string(remaining) +
                          " bytes after its vertices can hold (a truncated file or a false count)");
        }
        in.seekg(static_cast<std::streamoff>(pos));
        unsigned char bytes[8];
        for (unsigned int i = 0; i < count; ++i) {
          for (const PlyProperty& p : e.properties) {
            const std::size_t n = &p == list ? count_bytes : ply_size(p.type);
            if (size - std::min(size, pos) < n || !in.read(reinterpret_cast<char*>(bytes), n))
              throw ReadError(where + "binary PLY ends inside " + what(e, i));
            pos += n;
            if (&p != list)
              continue;
            // OpenMesh reads the count as unsigned: an int -1 is 4294967295 corners.
            const std::uint32_t corners = read_unsigned(bytes, n, h.big_endian);
            if (std::uintmax_t(corners) * entry_bytes > size - std::min(size, pos)) {
              throw ReadError(where + what(e, i) + " claims " + count_text(corners, "corners") +
                              ", more than the rest of the file holds");
            }
            pos += std::uintmax_t(corners) * entry_bytes;
            in.ignore(static_cast<std::streamsize>(std::uintmax_t(corners) * entry_bytes));
          }
        }
      }
    } else {
      if (in.eof())
        throw ReadError(where + "PLY file ends before element '" + e.name + "'");
      // As _PLYReader_::read_ascii: coordinates as float, colours as float or int, everything
      // else as one word; 'vertex_indices' as an unsigned count and unsigned entries.
      float number = 0;
      int integer = 0;
      unsigned int corners = 0, index = 0;
      std::string word;
      unsigned int i = 0;
      for (; i < count && !in.eof(); ++i) {
        for (const PlyProperty& p : e.properties) {
          const bool vertex_or_face = e.name == "vertex" || is_face;
          if (vertex_or_face && p.role == PlyRole::coordinate && e.name == "vertex") {
            in >> number;
          } else if (vertex_or_face && p.role == PlyRole::color) {
            if (p.type == PlyType::f32)
              in >> number;
            else
              in >> integer;
          } else if (is_face && p.role == PlyRole::vertex_indices) {
            in >> corners;
            const std::streamoff at = in.tellg();
            if (!in.fail() &&
                (at < 0 || std::uintmax_t(corners) > (size - std::uintmax_t(at)) / 2 + 1)) {
              throw ReadError(where + what(e, i) + " claims " + count_text(corners, "corners") +
                              ", more than the rest of the file holds");
            }
            for (unsigned int c = 0; c < corners && !in.fail(); ++c)
              in >> index;
          } else {
            in >> word;
          }
          if (in.fail()) {
            throw ReadError(where + what(e, i) + ": property '" + p.name +
                            "' is missing or unreadable (a truncated file, a false count, or a "
                            "value such as 'nan')");
          }
        }
      }
      if (i < count) {
        throw ReadError(where + "the PLY header declares " + count_text(count, e.name.c_str()) +
                        " elements but the file ends after " + std::to_string(i));
      }
    }
    if (is_face)
      return count;  // OpenMesh stops after the faces
  }
  return 0;
}

std::size_t check_stl(const std::string& path, std::uintmax_t size) {
  std::ifstream in(path, std::ios::binary);
  const std::string where = path + ": ";
  unsigned char head[84] = {};
  in.read(reinterpret_cast<char*>(head), 84);
  const std::uint32_t triangles = size >= 84 ? little_endian_u32(head + 80) : 0;
  if (size >= 84 && 84 + 50 * std::uintmax_t(triangles) == size) {
    // Binary, as _STLReader_::check_stl_type decides. Coordinates must be finite: OpenMesh
    // welds a NaN corner onto an arbitrary vertex.
    std::vector<char> block(50);
    for (std::uint32_t t = 0; t < triangles; ++t) {
      in.read(block.data(), 50);
      for (int c = 0; c < 9; ++c) {
        float x;
        std::memcpy(&x, block.data() + 12 + 4 * c, 4);
        if (!std::isfinite(x)) {
          throw InvalidSoupError(where + "binary STL triangle " + std::to_string(t) + ", corner " +
                                 std::to_string(c / 3) + " has a non-finite coordinate");
        }
      }
    }
    return triangles;
  }
  // ASCII, as _STLReader_::read_stla: a line containing "outer" starts a triangle whose three
  // next lines are "vertex x y z".
  in.clear();
  in.seekg(0);
  std::string line, word;
  std::size_t count = 0, number = 0;
  std::istringstream fields;
  while (in && !in.eof()) {
    std::getline(in, line);
    ++number;
    if (line.find("outer") == std::string::npos && line.find("OUTER") == std::string::npos)
      continue;
    for (int c = 0; c < 3; ++c) {
      std::getline(in, line);
      ++number;
      fields.clear();
      fields.str(line);
      float x = 0, y = 0, z = 0;
      fields >> word >> x >> y >> z;
      if (fields.fail() || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
        throw ReadError(where + "ASCII STL triangle " + std::to_string(count) + ", corner " +
                        std::to_string(c) + " (line " + std::to_string(number) +
                        ") is not 'vertex x y z' with three finite numbers");
      }
    }
    ++count;
  }
  if (count == 0) {
    const std::string start(reinterpret_cast<const char*>(head),
                            static_cast<std::size_t>(std::min<std::uintmax_t>(size, 5)));
    if (start != "solid") {
      throw ReadError(where + "neither ASCII STL (no 'solid') nor binary STL: a binary STL " +
                      (size >= 84
                           ? "whose header counts " + count_text(triangles, "triangles") + " has " +
                                 std::to_string(84 + 50 * std::uintmax_t(triangles)) + " bytes"
                           : std::string("has at least 84 bytes")) +
                      ", this file has " + std::to_string(size));
    }
  }
  return count;
}

// OBJ, as _OBJReader_::read parses face records: a record whose first corner gives a texture
// coordinate before any vertex index, such as "f /1 2 3", trips an assert in Debian's OpenMesh
// (or, without asserts, reads vhandles.back() of an empty vector). (Normals would too, but
// OpenMesh only reads them when asked to, and read_soup does not ask.) Also notes "mtllib" records:
// OpenMesh opens whatever file they name, relative to the OBJ (so "mtllib ../../dev/zero" never
// returns).
struct ObjCheck {
  bool has_material_library = false;
};

bool parses_as_int(const std::string& text) {
  std::istringstream in(text);
  int value = 0;
  in >> value;
  return !in.fail();
}

ObjCheck check_obj(const std::string& path) {
  ObjCheck result;
  std::ifstream in(path, std::ios::binary);
  std::string line, keyword, corner;
  std::vector<std::pair<std::size_t, std::string>> faces;  // line number, text after "f"
  std::size_t number = 0;
  while (std::getline(in, line)) {
    ++number;
    const auto first = line.find_first_not_of(" \t\r\n");
    if (first == std::string::npos || line[first] == '#')
      continue;
    const auto end = line.find_first_of(" \t\r\n", first);
    keyword.assign(line, first, end == std::string::npos ? std::string::npos : end - first);
    if (keyword == "mtllib")
      result.has_material_library = true;
    else if (keyword == "f" && end != std::string::npos)
      faces.emplace_back(number, line.substr(end));
  }
  for (const auto& [line_number, text] : faces) {
    std::istringstream corners(text);
    bool has_vertex = false;
    while (!has_vertex && corners >> corner) {
      std::string rest = corner;
      int component = 0;
      do {
        const auto slash = rest.find('/');
        std::string part = rest.substr(0, slash);
        rest = slash == std::string::npos ? "" : rest.substr(slash + 1);
        if (slash != std::string::npos && part.empty()) {
          ++component;
          continue;
        }
        if (slash == std::string::npos && !parses_as_int(part))
          continue;
        if (component == 0) {
          has_vertex = true;
        } else if (!has_vertex && component == 1) {
          throw ReadError(path + ": line " + std::to_string(line_number) + ": face corner '" +
                          corner +
                          "' has no vertex index before its texture coordinate (OpenMesh's OBJ "
                          "reader would abort)");
        }
        ++component;
      } while (!rest.empty());
    }
  }
  return result;
}

//! The OBJ file with every "mtllib" record turned into a comment, for OpenMesh to read from
//! memory: MeshBridge uses no materials, and OpenMesh would open any file such a record names.
std::string obj_without_material_libraries(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::size_t line_start = 0;
  while (line_start < text.size()) {
    std::size_t line_end = text.find('\n', line_start);
    if (line_end == std::string::npos)
      line_end = text.size();
    const std::size_t first = text.find_first_not_of(" \t\r", line_start);
    if (first < line_end && text.compare(first, 6, "mtllib") == 0 &&
        (first + 6 == line_end || std::isspace(static_cast<unsigned char>(text[first + 6])))) {
      text[first] = '#';
    }
    line_start = line_end + 1;
  }
  return text;
}

}  // namespace

void read_with_openmesh(const MappedFile& file, const std::string& ext, Soup& soup,
                        ReadInfo& info) {
  const std::string& path = file.path();
  const auto size = static_cast<std::uintmax_t>(file.size());
  // OpenMesh's readers trust what a file declares; check it first (see check_off etc.).
  std::size_t declared_faces = 0;
  if (ext == "off")
    declared_faces = check_off(path, size);
  else if (ext == "ply")
    declared_faces = check_ply(path, size);
  else if (ext == "stl")
    declared_faces = check_stl(path, size);
  std::istringstream obj_text;
  const bool from_memory = ext == "obj" && check_obj(path).has_material_library;
  if (from_memory)
    obj_text.str(obj_without_material_libraries(path));

  SoupImporter importer(soup, path, size);
  OpenMesh::IO::Options options;
  bool ok = false;
  std::string reader_message;
  {
    CapturedOpenMeshErrors errors;
    ok = from_memory ? OpenMesh::IO::IOManager().read(obj_text, "obj", importer, options)
                     : OpenMesh::IO::IOManager().read(path, importer, options);
    reader_message = errors.text();
  }
  if (!ok) {
    throw ReadError(path + ": OpenMesh's reader could not parse the file" +
                    (reader_message.empty() ? std::string() : " (" + reader_message + ")"));
  }
  ReadInfo declared = declared_counts(path, ext);
  if (ext == "stl")
    declared.declared_faces = declared_faces;  // triangles in the file, welded ones included
  if (declared.declared_vertices > soup.num_vertices()) {
    throw ReadError(path + ": the file declares " + std::to_string(declared.declared_vertices) +
                    " vertices but OpenMesh's reader read " + std::to_string(soup.num_vertices()) +
                    " (an unparseable coordinate such as 'nan', or a truncated file)");
  }
  info = declared;
  if (declared.declared_faces > soup.num_faces())
    info.faces_dropped_by_reader = declared.declared_faces - soup.num_faces();
  if (!importer.bad_index().empty())
    throw ReadError(path + ": " + importer.bad_index());
}

void write_with_openmesh(AtomicOutput& out, const std::string& ext, const IndexedMesh& mesh) {
  const std::string& path = out.target();
  IndexedMesh fanned;
  const IndexedMesh* source = &mesh;
  if (ext == "stl") {
    fanned.soup.positions = mesh.soup.positions;
    for (std::size_t f = 0; f < mesh.soup.num_faces(); ++f) {
      const PolygonView p = mesh.soup.polygon(f);
      for (std::size_t i = 1; i + 1 < p.size(); ++i)
        fanned.soup.add_polygon({p[0], p[i], p[i + 1]});
    }
    source = &fanned;
  }
  OpenMeshBuild build = to_openmesh(*source);
  if (build.add_face_failures > 0) {
    throw WriteError(path + ": " + std::to_string(build.add_face_failures) +
                     " polygon(s) are not manifold and OpenMesh cannot hold them; repair first");
  }
  OpenMesh::IO::Options options;
  if (ext == "stl")
    options += OpenMesh::IO::Options::Binary;
  if (ext == "stl")
    build.mesh.request_face_normals(), build.mesh.update_face_normals();
  bool ok = false;
  std::string writer_message;
  {
    CapturedOpenMeshErrors errors;
    ok = OpenMesh::IO::write_mesh(build.mesh, out.temporary_path(), options, 17);
    writer_message = errors.text();
  }
  if (!ok) {
    throw WriteError(path + ": OpenMesh's writer failed" +
                     (writer_message.empty() ? std::string() : " (" + writer_message + ")"));
  }
}

}  // namespace meshbridge::detail
