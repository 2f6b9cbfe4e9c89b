// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The cross-check of the differential tests: OpenMesh's own readers, through an importer that
// captures every vertex and face they pass on (no add_face refused, nothing duplicated). Tests
// only: MeshBridge reads files with its own readers (core/src/io/).

#include "meshbridge/soup.h"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/importer/BaseImporter.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <string>
#include <vector>

namespace meshbridge::test_support {

//! What OpenMesh's reader passed on: the soup, plus per-vertex and per-face colours.
struct OpenMeshReading {
  bool ok = false;
  Soup soup;
  std::vector<OpenMesh::Vec4uc> vertex_colors, face_colors;  //!< empty if the file has none
};

class CapturingImporter : public OpenMesh::IO::BaseImporter {
 public:
  explicit CapturingImporter(OpenMeshReading& r) : r_(r) {}
  using VH = OpenMesh::VertexHandle;
  using FH = OpenMesh::FaceHandle;
  using HH = OpenMesh::HalfedgeHandle;
  using EH = OpenMesh::EdgeHandle;

  VH add_vertex(const OpenMesh::Vec3f& p) override { return add_vertex(OpenMesh::Vec3d(p)); }
  VH add_vertex(const OpenMesh::Vec3d& p) override {
    return VH(static_cast<int>(r_.soup.add_vertex(p)));
  }
  VH add_vertex() override { return add_vertex(OpenMesh::Vec3d(0, 0, 0)); }
  HH add_edge(VH, VH) override { return HH(); }
  FH add_face(const VHandles& indices) override {
    for (const VH& v : indices)
      r_.soup.corner_vertices.push_back(static_cast<Index>(v.idx()));
    r_.soup.face_begin.push_back(static_cast<Index>(r_.soup.corner_vertices.size()));
    return FH(static_cast<int>(r_.soup.num_faces() - 1));
  }
  FH add_face(HH) override { return FH(); }
  void add_face_texcoords(FH, VH, const std::vector<OpenMesh::Vec2f>&) override {}
  void add_face_texcoords(FH, VH, const std::vector<OpenMesh::Vec3f>&) override {}
  void set_face_texindex(FH, int) override {}
  void set_point(VH v, const OpenMesh::Vec3f& p) override {
    r_.soup.positions[v.idx()] = OpenMesh::Vec3d(p);
  }
  void set_halfedge(VH, HH) override {}
  void set_normal(VH, const OpenMesh::Vec3f&) override {}
  void set_normal(VH, const OpenMesh::Vec3d&) override {}
  void set_color(VH v, const OpenMesh::Vec3uc& c) override {
    set_color(v, OpenMesh::Vec4uc(c[0], c[1], c[2], 255));
  }
  void set_color(VH v, const OpenMesh::Vec4uc& c) override {
    r_.vertex_colors.resize(r_.soup.num_vertices());
    r_.vertex_colors[v.idx()] = c;
  }
  void set_color(VH, const OpenMesh::Vec3f&) override {}
  void set_color(VH, const OpenMesh::Vec4f&) override {}
  void set_texcoord(VH, const OpenMesh::Vec2f&) override {}
  void set_status(VH, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_next(HH, HH) override {}
  void set_face(HH, FH) override {}
  void request_face_texcoords2D() override {}
  void set_texcoord(HH, const OpenMesh::Vec2f&) override {}
  void set_texcoord(VH, const OpenMesh::Vec3f&) override {}
  void set_texcoord(HH, const OpenMesh::Vec3f&) override {}
  void set_status(HH, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_color(EH, const OpenMesh::Vec3uc&) override {}
  void set_color(EH, const OpenMesh::Vec4uc&) override {}
  void set_color(EH, const OpenMesh::Vec3f&) override {}
  void set_color(EH, const OpenMesh::Vec4f&) override {}
  void set_status(EH, const OpenMesh::Attributes::StatusInfo&) override {}
  void set_normal(FH, const OpenMesh::Vec3f&) override {}
  void set_normal(FH, const OpenMesh::Vec3d&) override {}
  void set_color(FH f, const OpenMesh::Vec3uc& c) override {
    set_color(f, OpenMesh::Vec4uc(c[0], c[1], c[2], 255));
  }
  void set_color(FH f, const OpenMesh::Vec4uc& c) override {
    r_.face_colors.resize(r_.soup.num_faces());
    r_.face_colors[f.idx()] = c;
  }
  void set_color(FH, const OpenMesh::Vec3f&) override {}
  void set_color(FH, const OpenMesh::Vec4f&) override {}
  void set_status(FH, const OpenMesh::Attributes::StatusInfo&) override {}
  void add_texture_information(int, std::string) override {}
  void reserve(unsigned int, unsigned int, unsigned int) override {}
  std::size_t n_vertices() const override { return r_.soup.num_vertices(); }
  std::size_t n_faces() const override { return r_.soup.num_faces(); }
  std::size_t n_edges() const override { return 0; }

 private:
  OpenMeshReading& r_;
};

//! Reads `path` with OpenMesh's reader for its extension; `colors`: ask for vertex and face
//! colours (OpenMesh reads them only when asked).
inline OpenMeshReading read_with_openmesh(const std::string& path, bool colors = false) {
  OpenMeshReading r;
  CapturingImporter importer(r);
  OpenMesh::IO::Options options;
  if (colors) {
    options += OpenMesh::IO::Options::VertexColor;
    options += OpenMesh::IO::Options::FaceColor;
    options += OpenMesh::IO::Options::ColorAlpha;
  }
  omlog().disable();
  r.ok = OpenMesh::IO::IOManager().read(path, importer, options);
  omlog().enable();
  return r;
}

}  // namespace meshbridge::test_support
