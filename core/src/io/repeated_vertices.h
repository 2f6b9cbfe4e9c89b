// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Per-face-vertex soups (every triangle written with its own corners: OBJ, PLY, OFF and 3MF
// exporters that do not index) welded by exact position, as STL is (DESIGN 8a, soups).

#include "meshbridge/io.h"
#include "meshbridge/soup.h"

#include <cstddef>

namespace meshbridge::detail {

//! If no vertex of `soup` is used by two corners (each face has vertices of its own) and welding
//! by position would make at least half of the polygon sides share their edge with another side
//! (a surface written per face vertex), every group of used vertices
//! at one position
//! (-0 = +0; with per-vertex colours in `attributes`, also the same colour) becomes its first
//! vertex; the others are removed, survivors and unused vertices keep their order, and the
//! per-vertex attributes follow. A soup where some vertex is shared (an indexed mesh, a repaired
//! mesh whose split copies are each shared by their fan), or whose faces would meet only at
//! vertices (the two triangles of a repaired bowtie), is left as it is. Linear time (hash
//! buckets). Returns the number of vertices removed. Indices out of range: left for the caller's
//! validation (nothing is welded).
std::size_t weld_repeated_vertices(Soup& soup, MeshAttributes* attributes);

//! The test weld_repeated_vertices() puts to a weld: whether at least half of the polygon sides
//! (between different vertices) share their edge with another side when corner c is at vertex
//! `welded[soup.corner_vertices[c]]`, one of `vertices`.
bool most_sides_shared_when_welded(const Soup& soup, const Index* welded, std::size_t vertices);

}  // namespace meshbridge::detail
