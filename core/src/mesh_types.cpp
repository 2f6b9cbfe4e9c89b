// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/mesh_types.h"

#include <OpenMesh/Core/Utils/PropertyManager.hh>

#include <vector>

namespace meshbridge {

OpenMeshBuild to_openmesh(const IndexedMesh& mesh) {
  OpenMeshBuild build;
  build.add_face_failures = fill_openmesh(mesh, build.mesh);
  return build;
}

std::size_t fill_openmesh(const IndexedMesh& mesh, PolyMesh& out) {
  std::size_t failures = 0;
  const Soup& soup = mesh.soup;
  out.reserve(soup.num_vertices(), soup.num_corners() / 2 + soup.num_vertices(), soup.num_faces());
  for (const Point& p : soup.positions)
    out.add_vertex(p);

  const bool has_origin = mesh.vertex_origin.size() == soup.num_vertices() &&
                          mesh.face_origin.size() == soup.num_faces();
  OpenMesh::VPropHandleT<Index> vertex_origin;
  OpenMesh::FPropHandleT<Index> face_origin;
  if (has_origin) {
    out.add_property(vertex_origin, kVertexOriginProperty);
    out.add_property(face_origin, kFaceOriginProperty);
    for (auto v : out.vertices())
      out.property(vertex_origin, v) = mesh.vertex_origin[v.idx()];
  }

  std::vector<OpenMesh::VertexHandle> handles;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    handles.clear();
    for (Index v : soup.polygon(f))
      handles.emplace_back(static_cast<int>(v));
    const OpenMesh::FaceHandle fh = out.add_face(handles);
    if (!fh.is_valid()) {
      ++failures;
      continue;
    }
    if (has_origin)
      out.property(face_origin, fh) = mesh.face_origin[f];
  }
  return failures;
}

}  // namespace meshbridge
