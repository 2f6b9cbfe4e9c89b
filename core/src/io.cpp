// SPDX-License-Identifier: GPL-3.0-or-later
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
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

namespace meshbridge {

namespace {

using OpenMesh::IO::BaseImporter;

// Captures what a reader reports, unchanged: no add_face is refused, no vertex duplicated.
class SoupImporter : public BaseImporter {
 public:
  explicit SoupImporter(Soup& soup) : soup_(soup) {}

  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3f& p) override {
    return add_vertex(OpenMesh::Vec3d(p[0], p[1], p[2]));
  }
  OpenMesh::VertexHandle add_vertex(const OpenMesh::Vec3d& p) override {
    return OpenMesh::VertexHandle(static_cast<int>(soup_.add_vertex(p)));
  }
  OpenMesh::VertexHandle add_vertex() override { return add_vertex(OpenMesh::Vec3d(0, 0, 0)); }
  OpenMesh::HalfedgeHandle add_edge(OpenMesh::VertexHandle, OpenMesh::VertexHandle) override {
    ++edges_;
    return OpenMesh::HalfedgeHandle();
  }
  OpenMesh::FaceHandle add_face(const VHandles& indices) override {
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
    // Headers may lie: reserve only what a sane file of this kind could hold.
    soup_.reserve(std::min(vertices, 1u << 24), std::min(faces, 1u << 24),
                  3 * static_cast<std::size_t>(std::min(faces, 1u << 24)));
  }
  std::size_t n_vertices() const override { return soup_.num_vertices(); }
  std::size_t n_faces() const override { return soup_.num_faces(); }
  std::size_t n_edges() const override { return edges_; }

  const std::string& bad_index() const { return bad_index_; }

 private:
  Soup& soup_;
  std::size_t edges_ = 0;
  std::string bad_index_;
};

std::string lower_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
    return "";
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  return ext;
}

// Collects what OpenMesh prints on its error stream while a reader or writer runs.
// OpenMesh's progress log (omlog) is muted meanwhile: a library does not print.
class CapturedOpenMeshErrors {
 public:
  CapturedOpenMeshErrors() : log_was_enabled_(omlog().is_enabled()) {
    omerr().connect(captured_);
    omerr().disconnect(std::cerr);
    omlog().disable();
  }
  ~CapturedOpenMeshErrors() {
    omerr().flush();
    omerr().disconnect(captured_);
    omerr().connect(std::cerr);
    if (log_was_enabled_)
      omlog().enable();
  }
  std::string first_line() {
    omerr().flush();
    std::string text = captured_.str();
    const auto end = text.find('\n');
    return text.substr(0, end);
  }

 private:
  std::ostringstream captured_;
  bool log_was_enabled_;
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
      if (i == std::string::npos || i + 1 >= line.size())
        continue;
      const char kind = line[i];
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

}  // namespace

bool is_supported_mesh_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == "obj" || ext == "off" || ext == "ply" || ext == "stl";
}

Soup read_soup(const std::string& path, ReadInfo* info) {
  struct stat file_status {};
  if (stat(path.c_str(), &file_status) != 0) {
    throw ReadError(path + ": cannot open (" + std::strerror(errno) + ")");
  }
  if (S_ISDIR(file_status.st_mode))
    throw ReadError(path + ": is a directory, not a mesh file");
  if (!is_supported_mesh_file(path)) {
    throw ReadError(path + ": unknown format (expected .obj, .off, .ply or .stl)");
  }
  {
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
      throw ReadError(path + ": cannot open for reading");
  }
  if (file_status.st_size == 0)
    throw ReadError(path + ": file is empty");

  Soup soup;
  SoupImporter importer(soup);
  OpenMesh::IO::Options options;
  bool ok = false;
  std::string reader_message;
  {
    CapturedOpenMeshErrors errors;
    ok = OpenMesh::IO::IOManager().read(path, importer, options);
    reader_message = errors.first_line();
  }
  if (!ok) {
    throw ReadError(path + ": OpenMesh's reader could not parse the file" +
                    (reader_message.empty() ? std::string() : " (" + reader_message + ")"));
  }
  const ReadInfo declared = declared_counts(path, lower_extension(path));
  if (declared.declared_vertices > soup.num_vertices()) {
    throw ReadError(path + ": the file declares " + std::to_string(declared.declared_vertices) +
                    " vertices but OpenMesh's reader read " + std::to_string(soup.num_vertices()) +
                    " (an unparseable coordinate such as 'nan', or a truncated file)");
  }
  if (info != nullptr) {
    *info = declared;
    if (declared.declared_faces > soup.num_faces()) {
      info->faces_dropped_by_reader = declared.declared_faces - soup.num_faces();
    }
  }
  if (!importer.bad_index().empty())
    throw ReadError(path + ": " + importer.bad_index());
  if (soup.num_faces() == 0) {
    throw ReadError(path + ": no polygons in the file (" + std::to_string(soup.num_vertices()) +
                    " vertices)");
  }
  try {
    validate_soup(soup);
  } catch (const InvalidSoupError& error) {
    throw InvalidSoupError(path + ": " + error.what());
  }
  return soup;
}

void write_mesh(const std::string& path, const IndexedMesh& mesh) {
  const std::string ext = lower_extension(path);
  if (!is_supported_mesh_file(path)) {
    throw WriteError(path + ": unknown format (expected .obj, .off, .ply or .stl)");
  }
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

  const auto slash = path.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  const std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string temporary = dir + "." + name + ".tmp" + std::to_string(::getpid()) + "." + ext;
  OpenMesh::IO::Options options;
  if (ext == "stl")
    options += OpenMesh::IO::Options::Binary;
  if (ext == "stl")
    build.mesh.request_face_normals(), build.mesh.update_face_normals();
  bool ok = false;
  std::string writer_message;
  {
    CapturedOpenMeshErrors errors;
    ok = OpenMesh::IO::write_mesh(build.mesh, temporary, options, 17);
    writer_message = errors.first_line();
  }
  if (!ok) {
    std::remove(temporary.c_str());
    throw WriteError(path + ": OpenMesh's writer failed" +
                     (writer_message.empty() ? std::string() : " (" + writer_message + ")"));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw WriteError(path + ": cannot move the written file into place (" + reason + ")");
  }
}

}  // namespace meshbridge
