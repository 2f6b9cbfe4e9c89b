// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/objects_3mf.h"

#include "geometry/triangulate.h"
#include "meshbridge/errors.h"

#include <algorithm>

namespace meshbridge::detail {

std::vector<Object3mf> objects_3mf(const Soup& soup, const std::vector<FaceObject>& face_objects,
                                   const std::string& path) {
  std::vector<Object3mf> objects;
  // The object of each face (an index into `objects`).
  std::vector<std::size_t> object_of(face_objects.empty() ? 0 : soup.num_faces());
  for (std::size_t f = 0; f < object_of.size(); ++f) {
    const auto known = std::find_if(objects.begin(), objects.end(),
                                    [&](const Object3mf& o) { return o.kind == face_objects[f]; });
    object_of[f] = static_cast<std::size_t>(known - objects.begin());
    if (known == objects.end())
      objects.push_back({face_objects[f], {}, {}});
  }
  if (objects.empty())
    objects.push_back({});
  const bool one = objects.size() == 1;
  // Each object's index of each soup vertex (kNoIndex: unused there), one object at a time.
  std::vector<Index> local(one ? 0 : soup.num_vertices());
  Triangulation triangulation;
  avoid_existing_edges(soup, triangulation);  // no diagonal on an edge the mesh already has
  for (std::size_t o = 0; o < objects.size(); ++o) {
    Object3mf& object = objects[o];
    const auto mine = [&](std::size_t f) { return one || object_of[f] == o; };
    if (one) {
      object.vertices.resize(soup.num_vertices());
      for (std::size_t v = 0; v < soup.num_vertices(); ++v)
        object.vertices[v] = static_cast<Index>(v);
    } else {
      std::fill(local.begin(), local.end(), kNoIndex);
      for (std::size_t f = 0; f < soup.num_faces(); ++f) {
        if (mine(f)) {
          for (Index v : soup.polygon(f))
            local[v] = 0;
        }
      }
      for (std::size_t v = 0; v < local.size(); ++v) {
        if (local[v] != kNoIndex) {
          local[v] = static_cast<Index>(object.vertices.size());
          object.vertices.push_back(static_cast<Index>(v));
        }
      }
    }
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      if (!mine(f))
        continue;
      triangulate_polygon(soup, f, triangulation);
      for (const auto& [a, b, c] : triangulation.triangles) {
        // lib3mf refuses a triangle that names a vertex twice ("cannot store the mesh").
        if (a == b || b == c || a == c) {
          throw WriteError(path + ": face " + std::to_string(f) +
                           " names a vertex twice (a degenerate triangle), which 3MF refuses: "
                           "repair sets such faces aside or splits them");
        }
        if (one)
          object.triangles.push_back({{a, b, c}});
        else
          object.triangles.push_back({{local[a], local[b], local[c]}});
      }
    }
  }
  return objects;
}

DWORD lib3mf_object_type(ObjectType type) {
  switch (type) {
    case ObjectType::model:
      return NMR::MODELOBJECTTYPE_MODEL;
    case ObjectType::support:
      return NMR::MODELOBJECTTYPE_SUPPORT;
    case ObjectType::solidsupport:
      return NMR::MODELOBJECTTYPE_SOLIDSUPPORT;
    case ObjectType::surface:
      return NMR::MODELOBJECTTYPE_SURFACE;
    case ObjectType::other:
      break;
  }
  return NMR::MODELOBJECTTYPE_OTHER;
}

}  // namespace meshbridge::detail
