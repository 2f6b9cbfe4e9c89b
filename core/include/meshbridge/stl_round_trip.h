// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file stl_round_trip.h
//! What a mesh becomes when written as STL and read back: the truth every STL route reports.

#include "meshbridge/close_gaps.h"
#include "meshbridge/indexed_mesh.h"

#include <cstddef>
#include <string>

namespace meshbridge {

//! The soup any STL reader gets back from `soup` written as STL: polygons cut into triangles by
//! ear clipping (as write_mesh() writes them), positions rounded to float32, vertices
//! welded by exact position in order of first use (as read_soup() and every STL reader weld).
//! #V' <= #V, #F' = number of triangles.
Soup stl_round_trip(const Soup& soup);

//! Singular edges plus singular vertices that detection finds in stl_round_trip(soup): what a
//! reader of the STL file sees of the split vertices' repair undone (0 when the repair survives).
std::size_t singular_elements_after_stl_round_trip(const Soup& soup);

//! The smallest `distance` for separate_split_vertices() after which the repaired `mesh` survives
//! STL: `u * 2^k` (k = 0, 1, ..., 60) where u is the float32 spacing (one unit in the last place)
//! at the largest absolute coordinate of the mesh (its scale: copies near the origin move as far
//! as copies at its far end, never by a denormal), the first for which
//! singular_elements_after_stl_round_trip() is 0. 0 when `mesh` has no split vertex.
//! \pre `mesh.vertex_origin` has one entry per vertex
//! \throw std::invalid_argument when no such distance exists (float32 merges vertices that are
//!        not copies of one split vertex, or the copies cannot be separated)
double smallest_stl_separation(const IndexedMesh& mesh);

//! As smallest_stl_separation(), the first `u * 2^k` after which the mesh also survives the gap
//! closing `weld` (default: the automatic tolerance, default_weld_tolerance() of the moved mesh)
//! of a repair or check that re-reads the STL: no two copies of one split vertex are within the
//! tolerance of each other at float32 precision, so that gap closing cannot weld them back. What
//! `meshbridge repair --separate auto` uses, so that repairing its STL output again changes
//! nothing. Each step costs one STL round trip and detection of the mesh.
//! \pre, \throw as smallest_stl_separation()
double stl_separation_surviving_weld(const IndexedMesh& mesh, const CloseGapsOptions& weld = {});

//! What separate_copies_for_stl() did to a repaired mesh before it is written as STL.
struct StlSeparation {
  std::size_t vertices_moved = 0;  //!< copies of split vertices moved (0: none to move, or kept)
  double distance = 0;             //!< how far each of them moved, in model units (0: none)
  //! Non-empty when the mesh has split vertices whose copies could not be moved apart (their
  //! positions are kept, and an STL reader welds them again): why.
  std::string kept_reason;
};

//! Prepares a repaired mesh for STL, which stores no shared vertices: moves every copy of a split
//! vertex (separate_split_vertices()) by stl_separation_surviving_weld(mesh), the smallest move
//! after which the file, read back by a reader that welds by exact float32 position (PrusaSlicer,
//! admesh, Cura, MeshLab, MeshBridge), keeps the copies apart and a repair of it welds nothing.
//! The moved copies are rounded to float32, as the file holds them. A mesh without split
//! vertices is left as it is. When no distance works, nothing moves and
//! `kept_reason` says why. What `repair`, `batch`, the Python module and the MeshLab plugin do
//! for an STL output unless asked to keep positions exact.
//! \pre `mesh.vertex_origin` has one entry per vertex 	hrow std::invalid_argument otherwise
StlSeparation separate_copies_for_stl(IndexedMesh& mesh);

}  // namespace meshbridge
