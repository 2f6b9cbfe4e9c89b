// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file bridged_mesh.h
//! The paper's modified construction: every polygon of the soup in an OpenMesh mesh, with the
//! edge bridges (all contenders of every vertex pair, and their pairing) and the vertex bridge
//! (input vertex -> copies) beside it, so no adjacency is lost.

#include "meshbridge/edge_bridges.h"
#include "meshbridge/indexed_mesh.h"
#include "meshbridge/mesh_types.h"
#include "meshbridge/pairing.h"
#include "meshbridge/soup.h"

#include <vector>

namespace meshbridge {

struct BridgedMeshOptions {
  PairingPolicy pairing = PairingPolicy::geometric;  //!< pairing of singular-edge contenders
};

//! Result of build_bridged_mesh(). Faces keep their direction (nothing is flipped): a 2-sided
//! edge whose sides run the same way, and every unpaired contender, is a boundary in `mesh`.
struct BridgedMesh {
  PolyMesh mesh;                    //!< every kept polygon, in order, vertices split per fan
  IndexedMesh indexed;              //!< the same mesh as plain arrays with provenance
  EdgeBridges bridges;              //!< contenders per vertex pair, over indexed.soup corners
  std::vector<Index> mate;          //!< pairing: side paired with each side, or kNoIndex
  std::vector<Index> copies_begin;  //!< vertex bridge: #V_in+1 offsets into copies
  std::vector<Index> copies;        //!< mesh vertices made from each input vertex

  //! Mesh vertices (OpenMesh indices) that input vertex v became; one per fan.
  std::vector<Index> copies_of(Index v) const {
    return {copies.begin() + copies_begin[v], copies.begin() + copies_begin[v + 1]};
  }
};

//! Builds in two phases: group and pair the sides, split fans; then one add_face per polygon.
//! Polygons with a repeated vertex are collapsed or split (see DefectReport::degenerate_faces);
//! those with fewer than 3 distinct corners are left out and listed by detect_defects().
//! \pre `soup` passes validate_soup() \throw InvalidSoupError naming the offending element
BridgedMesh build_bridged_mesh(const Soup& soup, const BridgedMeshOptions& options = {});

}  // namespace meshbridge
