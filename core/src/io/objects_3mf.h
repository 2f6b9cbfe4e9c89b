// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The objects a 3MF output holds: the faces of a mesh grouped by the 3MF object they were read
// from (MeshAttributes::face_objects), so that a support stays a support. Shared by the writer
// and by the measurement of what it wrote (included by them only: needs lib3mf's headers).

#include "meshbridge/indexed_mesh.h"
#include "meshbridge/io.h"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <string>
#include <vector>

namespace meshbridge::detail {

//! One mesh object of a 3MF output.
struct Object3mf {
  FaceObject kind;  //!< its type, and whether a build item places it
  //! The soup vertex of each of its vertices, in the object's order: every vertex of the soup
  //! when the output has one object, else the vertices its faces use, ascending.
  std::vector<Index> vertices;
  std::vector<NMR::MODELMESHTRIANGLE> triangles;  //!< corners as the object's vertex indices
};

//! The objects of `soup` whose faces have the kinds `face_objects` (one per face, or empty: all
//! of the model): one per kind, in the order of their first faces, each face's triangles
//! (triangulate_polygon()) in face order.
//! \throw WriteError naming `path` and the face for a triangle that names a vertex twice (lib3mf
//!        refuses it)
std::vector<Object3mf> objects_3mf(const Soup& soup, const std::vector<FaceObject>& face_objects,
                                   const std::string& path);

//! lib3mf's eModelObjectType of `type`.
DWORD lib3mf_object_type(ObjectType type);

}  // namespace meshbridge::detail
