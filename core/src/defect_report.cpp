// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/defect_report.h"

#include <sstream>

namespace meshbridge {

bool DefectReport::has_defects() const {
  // Isolated vertices and zero-area faces are listed, not defects (see the header).
  return !singular_edges.empty() || num_singular_vertices() > 0 || !boundary_edges.empty() ||
         !degenerate_faces.empty() || !faces_set_aside.empty() || !duplicate_faces.empty() ||
         !inconsistent_edges.empty() || num_nonorientable_components > 0 ||
         records_without_corners > 0 || keyhole_polygons_triangulated > 0;
}

namespace {

template <class T, class Print>
void list(std::ostringstream& out, const char* label, const std::vector<T>& items,
          std::size_t max_listed, Print print) {
  out << "  " << label << ": " << items.size();
  if (!items.empty() && max_listed > 0) {
    out << "  [";
    for (std::size_t i = 0; i < items.size() && i < max_listed; ++i) {
      out << (i ? " " : "");
      print(items[i]);
    }
    if (items.size() > max_listed)
      out << " ...";
    out << "]";
  }
  out << "\n";
}

}  // namespace

std::string to_text(const DefectReport& r, std::size_t max_listed) {
  std::ostringstream out;
  const auto index = [&](Index i) { out << i; };
  const auto pair = [&](const VertexPair& p) { out << p.v0 << "-" << p.v1; };
  out << "vertices " << r.num_vertices << ", faces " << r.num_faces_of_file() << ", edges "
      << r.num_edges << ", components " << r.num_components << ", Euler characteristic "
      << r.euler_characteristic << ", watertight " << (r.watertight ? "yes" : "no") << "\n";
  list(out, "singular edges", r.singular_edges, max_listed, [&](const SingularEdge& e) {
    out << e.vertices.v0 << "-" << e.vertices.v1 << " (" << e.contenders << " faces)";
  });
  list(out, "singular vertices on singular edges", r.singular_edge_vertices, max_listed, index);
  list(out, "pinch vertices", r.pinch_vertices, max_listed, index);
  list(out, "boundary edges", r.boundary_edges, max_listed, pair);
  out << "  boundary loops: " << r.num_boundary_loops << "\n";
  list(out, "inconsistently oriented edges", r.inconsistent_edges, max_listed, pair);
  out << "  non-orientable components: " << r.num_nonorientable_components << "\n";
  list(out, "isolated vertices", r.isolated_vertices, max_listed, index);
  list(out, "degenerate faces (repeated vertex)", r.degenerate_faces, max_listed, index);
  list(out, "faces set aside (< 3 distinct vertices)", r.faces_set_aside, max_listed, index);
  if (r.keyhole_polygons_triangulated > 0) {
    out << "  keyhole polygons (an outline and holes joined by slits, a-b and later b-a; "
           "triangulated by repair, the holes left open): "
        << r.keyhole_polygons_triangulated << "\n";
  }
  if (r.slits_set_aside > 0) {
    out << "  keyhole slits (a polygon running a-b and later b-a; set aside by repair, their "
           "edges counted): "
        << r.slits_set_aside << "\n";
  }
  if (r.records_without_corners > 0)
    out << "  face records without any corner (set aside, not in the list): "
        << r.records_without_corners << "\n";
  list(out, "zero-area faces", r.zero_area_faces, max_listed, index);
  list(out, "duplicate faces", r.duplicate_faces, max_listed, index);
  return out.str();
}

}  // namespace meshbridge
