// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file vcg_methods.h
//! MeshLab's way, through the header-only vcglib of the MeshLab 2020.09 SDK: the same calls
//! as MeshLab's filter_clean (cleanfilter.cpp) on a minimal vcg mesh (float coordinates as
//! CMeshO, face normals, flags, FF and VF adjacency; no Qt, no MeshLab library).
//! Polygons with more than 3 corners are fan-triangulated, as MeshLab's importers do.
//! Every method times the build of the vcg mesh from the soup (MeshLab's import) and FF topology.

#include "harness.h"

namespace meshbridge::bench {

//! UpdateTopology::FaceFace, then Clean::CountNonManifoldEdgeFF and CountNonManifoldVertexFF
//! (what MeshLab's "Compute Topological Measures" reports). Output: the mesh unchanged.
void vcg_topology_counts(const Soup& soup, Clock& clock, Outcome& outcome);

//! "Repair non Manifold Edges by removing faces": Clean::RemoveNonManifoldFace (deletes the
//! smallest faces on every non-manifold edge until it is 2-manifold). With
//! `then_split_vertices`, also "Repair non Manifold Vertices by splitting" (FF recomputed,
//! Clean::SplitNonManifoldVertex with MeshLab's default displacement 0), one call each.
void vcg_remove_faces(const Soup& soup, Clock& clock, Outcome& outcome, bool then_split_vertices);

//! "Repair non Manifold Edges by splitting vertices": Clean::SplitManifoldComponents (each
//! edge-manifold component copied out in turn; quadratic in the number of components).
void vcg_split_components(const Soup& soup, Clock& clock, Outcome& outcome);

}  // namespace meshbridge::bench
