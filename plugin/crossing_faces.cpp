// SPDX-License-Identifier: GPL-3.0-or-later
#include "crossing_faces.h"

#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <vcg/complex/allocate.h>

#include <stdexcept>
#include <string>

namespace meshbridge::meshlab {

std::size_t add_crossing_faces(const CMeshSoup& input, const SelfIntersectionReport& crossings,
                               CMeshO& layer, vcg::Color4b color) {
  const Soup& soup = input.soup;
  for (Index f : crossings.faces) {
    if (f >= soup.num_faces())
      throw std::invalid_argument("self-intersection report names face " + std::to_string(f) +
                                  " of a mesh with " + std::to_string(soup.num_faces()));
  }
  vcg::Box3d box;
  for (const Point& p : soup.positions)
    box.Add(vcg::Point3d(p[0], p[1], p[2]));
  const double diagonal = box.IsNull() || !(box.Diag() > 0) ? 1.0 : box.Diag();
  const double lift = kCrossingFaceLift * diagonal;

  // Triangles to draw: a fan of each face (the CMeshO soup holds triangles only).
  struct Triangle {
    Point a, b, c, offset;
  };
  std::vector<Triangle> triangles;
  std::size_t covered = 0;
  for (Index f : crossings.faces) {
    const PolygonView polygon = soup.polygon(f);
    const Point& a = soup.positions[polygon[0]];
    bool any = false;
    for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      const Point& b = soup.positions[polygon[k]];
      const Point& c = soup.positions[polygon[k + 1]];
      Point normal = (b - a) % (c - a);
      const double length = normal.norm();
      if (!(length > 0))
        continue;
      triangles.push_back({a, b, c, normal * (lift / length)});
      any = true;
    }
    covered += any ? 1 : 0;
  }
  if (triangles.empty())
    return covered;

  using Alloc = vcg::tri::Allocator<CMeshO>;
  const std::size_t first = layer.vert.size();
  auto vi = Alloc::AddVertices(layer, 6 * triangles.size());
  auto fi = Alloc::AddFaces(layer, 2 * triangles.size());
  const bool face_color = layer.face.IsColorEnabled();
  std::size_t next = first;
  const auto vertex = [&](const Point& p) {
    vi->P() = CMeshO::CoordType(CMeshO::ScalarType(p[0]), CMeshO::ScalarType(p[1]),
                                CMeshO::ScalarType(p[2]));
    vi->C() = color;
    vi->Q() = 0.0f;
    ++vi;
    return &layer.vert[next++];
  };
  const auto face = [&](const Point& a, const Point& b, const Point& c) {
    fi->V(0) = vertex(a);
    fi->V(1) = vertex(b);
    fi->V(2) = vertex(c);
    if (face_color)
      fi->C() = color;
    ++fi;
  };
  for (const Triangle& t : triangles) {
    face(t.a + t.offset, t.b + t.offset, t.c + t.offset);  // in front, facing out
    face(t.a - t.offset, t.c - t.offset, t.b - t.offset);  // behind, facing in
  }
  vcg::tri::UpdateNormal<CMeshO>::PerFaceNormalized(layer);
  vcg::tri::UpdateNormal<CMeshO>::PerVertexNormalized(layer);
  vcg::tri::UpdateBounding<CMeshO>::Box(layer);
  return covered;
}

}  // namespace meshbridge::meshlab
