// SPDX-License-Identifier: GPL-3.0-or-later
#include "defect_tubes.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/allocate.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace meshbridge::meshlab {
namespace {

using Vec = vcg::Point3d;

Vec to_vec(const Point& p) {
  return Vec(p[0], p[1], p[2]);
}

//! Two unit vectors perpendicular to `axis` (unit) and to each other.
void frame(const Vec& axis, Vec& u, Vec& w) {
  const Vec helper = std::abs(axis[0]) < 0.9 ? Vec(1, 0, 0) : Vec(0, 1, 0);
  u = (axis ^ helper).Normalize();
  w = (axis ^ u).Normalize();
}

//! Appends geometry to `layer` through preallocated iterators.
class TubeWriter {
 public:
  TubeWriter(CMeshO& layer, std::size_t vertices, std::size_t faces)
      : layer_(layer),
        vi_(vcg::tri::Allocator<CMeshO>::AddVertices(layer, vertices)),
        fi_(vcg::tri::Allocator<CMeshO>::AddFaces(layer, faces)),
        face_color_(layer.face.IsColorEnabled()) {}

  void tube(Vec a, Vec b, double radius, int sides, vcg::Color4b color, float quality) {
    Vec axis = b - a;
    const double length = axis.Norm();
    axis = length > 0 ? axis / length : Vec(0, 0, 1);
    a -= axis * radius;
    b += axis * radius;
    Vec u, w;
    frame(axis, u, w);
    const std::size_t first = index();
    for (int end = 0; end < 2; ++end) {
      for (int k = 0; k < sides; ++k) {
        const double t = 2.0 * M_PI * k / sides;
        vertex((end == 0 ? a : b) + (u * std::cos(t) + w * std::sin(t)) * radius, color, quality);
      }
    }
    for (int k = 0; k < sides; ++k) {
      const std::size_t a0 = first + std::size_t(k), a1 = first + std::size_t((k + 1) % sides);
      const std::size_t b0 = a0 + std::size_t(sides), b1 = a1 + std::size_t(sides);
      face(a0, a1, b1, color);  // outward: counter-clockwise seen from outside
      face(a0, b1, b0, color);
    }
  }

  void marker(Vec c, double radius, vcg::Color4b color) {
    const std::size_t first = index();
    const Vec dirs[6] = {Vec(1, 0, 0),  Vec(-1, 0, 0), Vec(0, 1, 0),
                         Vec(0, -1, 0), Vec(0, 0, 1),  Vec(0, 0, -1)};
    for (const Vec& d : dirs)
      vertex(c + d * radius, color, 0.0f);
    // Octahedron: +x=0 -x=1 +y=2 -y=3 +z=4 -z=5, counter-clockwise seen from outside.
    static const int tris[8][3] = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                   {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    for (const auto& t : tris)
      face(first + std::size_t(t[0]), first + std::size_t(t[1]), first + std::size_t(t[2]), color);
  }

 private:
  std::size_t index() const { return std::size_t(vi_ - layer_.vert.begin()); }
  void vertex(const Vec& p, vcg::Color4b color, float quality) {
    vi_->P() = CMeshO::CoordType(CMeshO::ScalarType(p[0]), CMeshO::ScalarType(p[1]),
                                 CMeshO::ScalarType(p[2]));
    vi_->C() = color;
    vi_->Q() = quality;
    ++vi_;
  }
  void face(std::size_t a, std::size_t b, std::size_t c, vcg::Color4b color) {
    fi_->V(0) = &layer_.vert[a];
    fi_->V(1) = &layer_.vert[b];
    fi_->V(2) = &layer_.vert[c];
    if (face_color_)
      fi_->C() = color;
    ++fi_;
  }

  CMeshO& layer_;
  CMeshO::VertexIterator vi_;
  CMeshO::FaceIterator fi_;
  bool face_color_;
};

}  // namespace

std::size_t triangles_per_tube(const DefectTubeOptions& options) {
  return 2 * std::size_t(std::max(options.sides, 0));
}

DefectLayerCounts build_defect_tubes(const CMeshSoup& input, const DefectReport& report,
                                     CMeshO& layer, const DefectTubeOptions& options,
                                     const DefectColors& colors) {
  layer.Clear();
  DefectLayerCounts counts;
  if (options.sides < 3)
    throw std::invalid_argument("defect tubes need at least 3 sides, got " +
                                std::to_string(options.sides));
  const std::size_t nv = input.soup.num_vertices();
  auto position = [&](Index v) {
    if (v >= nv)
      throw std::invalid_argument("defect report names vertex " + std::to_string(v) +
                                  " of a soup with " + std::to_string(nv));
    return to_vec(input.soup.positions[v]);
  };
  const std::size_t edges = report.singular_edges.size() + report.boundary_edges.size();
  const std::size_t markers = report.singular_edge_vertices.size() + report.pinch_vertices.size();
  if (edges + markers == 0)
    return counts;
  // Validate every index before allocating, so a bad report leaves `layer` empty.
  for (const SingularEdge& e : report.singular_edges)
    position(e.vertices.v0), position(e.vertices.v1);
  for (const VertexPair& e : report.boundary_edges)
    position(e.v0), position(e.v1);
  for (Index v : report.singular_edge_vertices)
    position(v);
  for (Index v : report.pinch_vertices)
    position(v);

  vcg::Box3d box;
  for (const Point& p : input.soup.positions)
    box.Add(to_vec(p));
  double diagonal = box.IsNull() ? 0.0 : box.Diag();
  if (!(diagonal > 0))
    diagonal = 1.0;  // all vertices coincide: any visible size will do
  const double radius = options.radius_fraction * diagonal;
  const std::size_t sides = std::size_t(options.sides);
  const auto tube_radius = [&](Vec a, Vec b) {
    const double length = (b - a).Norm();
    return length > 0 ? std::min(radius, options.tube_edge_fraction * length) : radius;
  };
  // The shortest edge (polygon side of nonzero length) at each marked vertex.
  std::vector<double> shortest(markers ? nv : 0, std::numeric_limits<double>::infinity());
  const Soup& soup = input.soup;
  for (std::size_t f = 0; markers && f < soup.num_faces(); ++f) {
    const Index begin = soup.face_begin[f], end = soup.face_begin[f + 1];
    for (Index c = begin; c < end; ++c) {
      const Index a = soup.corner_vertices[c],
                  b = soup.corner_vertices[c + 1 < end ? c + 1 : begin];
      const double length = (to_vec(soup.positions[a]) - to_vec(soup.positions[b])).Norm();
      if (length > 0) {
        shortest[a] = std::min(shortest[a], length);
        shortest[b] = std::min(shortest[b], length);
      }
    }
  }
  const auto marker_radius = [&](Index v) {
    return std::min(radius * options.marker_scale, std::isfinite(shortest[v])
                                                       ? options.marker_edge_fraction * shortest[v]
                                                       : radius * options.marker_scale);
  };

  TubeWriter out(layer, 2 * sides * edges + 6 * markers,
                 triangles_per_tube(options) * edges + kTrianglesPerMarker * markers);
  for (const SingularEdge& e : report.singular_edges) {
    const Vec a = position(e.vertices.v0), b = position(e.vertices.v1);
    out.tube(a, b, tube_radius(a, b), options.sides, colors.singular_edge, float(e.contenders));
    ++counts.singular_edges;
  }
  for (const VertexPair& e : report.boundary_edges) {
    const Vec a = position(e.v0), b = position(e.v1);
    out.tube(a, b, tube_radius(a, b), options.sides, colors.boundary_edge, 1.0f);
    ++counts.boundary_edges;
  }
  for (Index v : report.singular_edge_vertices) {
    out.marker(position(v), marker_radius(v), colors.singular_edge_vertex);
    ++counts.singular_vertex_markers;
  }
  for (Index v : report.pinch_vertices) {
    out.marker(position(v), marker_radius(v), colors.pinch_vertex);
    ++counts.singular_vertex_markers;
  }
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(layer);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalized(layer);
  vcg::tri::UpdateBounding<CMeshO>::Box(layer);
  return counts;
}

}  // namespace meshbridge::meshlab
