// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file stl_round_trip.h
//! What a mesh becomes when written as STL and read back: the truth every STL route reports.

#include "meshbridge/close_gaps.h"
#include "meshbridge/indexed_mesh.h"

#include <cstddef>

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

}  // namespace meshbridge
