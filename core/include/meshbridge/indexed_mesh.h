// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file indexed_mesh.h
//! A plain indexed mesh with provenance: what repair hands to adapters (MeshLab, files).

#include "meshbridge/soup.h"

#include <vector>

namespace meshbridge {

//! Positions + polygons + where every element came from in the input soup.
//!
//! Adapters copy per-vertex attributes through `vertex_origin`, per-face attributes through
//! `face_origin` and per-wedge (corner) attributes through `corner_origin`. A flipped face has its
//! corners reversed, and `corner_origin` follows that.
struct IndexedMesh {
  Soup soup;                         //!< the mesh itself
  std::vector<Index> vertex_origin;  //!< #V': input vertex of each output vertex
  std::vector<Index> face_origin;    //!< #F': input face of each output face (order preserved)
  std::vector<Index> corner_origin;  //!< #C': input corner (index into input corner_vertices)
};

}  // namespace meshbridge
