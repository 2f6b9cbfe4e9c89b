// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file mesh_types.h
//! The OpenMesh mesh type MeshBridge builds, and conversion from an IndexedMesh.

#include "meshbridge/indexed_mesh.h"

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>

#include <cstddef>

namespace meshbridge {

struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};

//! Polygon mesh with double positions.
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;

//! Names of the provenance properties that to_openmesh() adds.
inline constexpr const char* kVertexOriginProperty = "v:origin";  //!< input vertex (Index)
//! Input face (Index); kNoIndex for a face hole filling added.
inline constexpr const char* kFaceOriginProperty = "f:origin";

//! An OpenMesh mesh with every vertex and polygon of `mesh`, in order, with the provenance
//! properties `v:origin` and `f:origin` when `mesh` has origins.
struct OpenMeshBuild {
  PolyMesh mesh;
  std::size_t add_face_failures = 0;  //!< OpenMesh refused these faces (0 for repaired meshes)
};
//! Builds with one add_face() per polygon; a refused polygon is counted, never retried.
OpenMeshBuild to_openmesh(const IndexedMesh& mesh);

//! The same, into `out` (which must be empty), returning the number of add_face failures.
//! OpenMesh's meshes have no move operations: `a = std::move(b)` copies the whole mesh, so
//! code that keeps a PolyMesh as a member builds it in place with this.
std::size_t fill_openmesh(const IndexedMesh& mesh, PolyMesh& out);

}  // namespace meshbridge
