// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/stock_build.h"

#include "meshbridge/validate.h"

#include "openmesh_streams.h"
#include "union_find.h"

#include <OpenMesh/Core/IO/importer/ImporterT.hh>

#include <sstream>

namespace meshbridge {

StockBuild build_stock(const Soup& soup, const StockBuildOptions& options) {
  validate_soup(soup);
  StockBuild build;
  StockBuildReport& report = build.report;
  PolyMesh& mesh = build.mesh;
  report.faces_in = soup.num_faces();
  report.vertices_in = soup.num_vertices();
  {
    detail::MutedOpenMeshErrors muted;
    OpenMesh::IO::ImporterT<PolyMesh> importer(mesh);
    importer.reserve(static_cast<unsigned>(soup.num_vertices()),
                     static_cast<unsigned>(soup.num_corners() / 2),
                     static_cast<unsigned>(soup.num_faces()));
    for (const Point& p : soup.positions)
      importer.add_vertex(p);
    OpenMesh::IO::BaseImporter::VHandles handles;
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      handles.clear();
      for (Index v : soup.polygon(f))
        handles.emplace_back(static_cast<int>(v));
      const std::size_t vertices_before = mesh.n_vertices();
      const OpenMesh::FaceHandle fh = importer.add_face(handles);
      if (!fh.is_valid()) {
        ++report.faces_lost;
      } else if (mesh.n_vertices() != vertices_before) {
        ++report.faces_detached;
      }
    }
  }
  report.vertices_created = mesh.n_vertices();
  report.faces_kept = mesh.n_faces();
  if (!options.count_boundary_and_components)
    return build;
  detail::UnionFind components(mesh.n_faces());
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e)) {
      ++report.boundary_edges;
    } else {
      const auto h = mesh.halfedge_handle(e, 0);
      components.unite(mesh.face_handle(h).idx(),
                       mesh.face_handle(mesh.opposite_halfedge_handle(h)).idx());
    }
  }
  for (std::size_t f = 0; f < mesh.n_faces(); ++f) {
    if (components.find(static_cast<Index>(f)) == f)
      ++report.components;
  }
  return build;
}

std::string to_text(const StockBuildReport& r) {
  std::ostringstream out;
  out << "vertices " << r.vertices_created << " (from " << r.vertices_in << "), faces kept "
      << r.faces_kept << " of " << r.faces_in << " (" << r.faces_detached
      << " detached on copied vertices, " << r.faces_lost << " lost), boundary edges "
      << r.boundary_edges << ", components " << r.components << "\n";
  return out.str();
}

}  // namespace meshbridge
