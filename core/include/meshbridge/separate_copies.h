// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file separate_copies.h
//! Making a repair survive formats without shared vertices (STL).

#include "meshbridge/indexed_mesh.h"

#include <cstddef>

namespace meshbridge {

//! Moves every copy of a split vertex (all output vertices whose input vertex has more than one
//! copy) by `distance` toward the centroid of its own fan's polygon centroids, so a reader that
//! welds by exact position (every STL reader) no longer merges the copies again.
//! \pre `mesh.vertex_origin` has one entry per vertex, `distance` is finite and >= 0
//! \throw std::invalid_argument otherwise
//! \return number of vertices moved
std::size_t separate_split_vertices(IndexedMesh& mesh, double distance);

}  // namespace meshbridge
