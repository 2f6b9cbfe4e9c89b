// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file fill_holes.h
//! Closing small holes of a repaired mesh with new triangles (DESIGN 8a, "Holes"), through CGAL
//! Polygon Mesh Processing's triangulate_hole: the minimum-weight triangulation of the hole's
//! boundary polygon of P. Liepa, "Filling Holes in Meshes" (SGP 2003). Loops of up to 100 edges
//! are searched over all triangulations (cubic in the length: about 10 ms at 100 edges), so the
//! patch depends on the loop alone; longer ones over the 3D Delaunay triangulation of the loop
//! first (CGAL's default, fast), whose result can vary with the process's earlier allocations.
//! No vertex is added.

#include "meshbridge/indexed_mesh.h"

#include <cstddef>

namespace meshbridge {

//! The `max_edges` that `--fill-holes` without a number (and the MeshLab filters' suggestion)
//! uses: 32 edges closes the holes a broken export leaves (a missing quad or a few triangles, a
//! screw hole's rim of 8 to 32 sides) and leaves open the rims of a model that is open on purpose
//! (a vase, a scanned surface), whose boundaries run to hundreds of edges. It also bounds the
//! cost: CGAL's fallback search, when the Delaunay search finds no valid patch, is cubic in the
//! loop's length (32^3 steps: microseconds).
inline constexpr std::size_t kDefaultFillHolesMaxEdges = 32;

//! What hole filling may do. Default: off.
struct FillHolesOptions {
  std::size_t max_edges = 0;  //!< fill boundary loops of at most this many edges; 0 = off (default)
};

//! What hole filling did. Every count is exact.
struct FillHolesReport {
  std::size_t max_edges = 0;     //!< as requested (0: filling was off)
  std::size_t holes_filled = 0;  //!< boundary loops closed
  std::size_t faces_added = 0;   //!< new triangles
  //! boundary loops left open: longer than max_edges, or with no valid patch (CGAL found none,
  //! or patches_refused)
  std::size_t holes_left = 0;
  //! Of holes_left: loops whose patch was refused because it would not close a hole but lay a
  //! second layer on the surface: a triangle of no area, one over an existing face, or one
  //! folded back onto the face across its edge (under 1 degree: the outline of an open sheet,
  //! a loose triangle, quad or grid, is no hole).
  std::size_t patches_refused = 0;
};

//! Fills every boundary loop of `mesh` with at most `options.max_edges` edges with triangles
//! between the loop's own vertices (CGAL::Polygon_mesh_processing::triangulate_hole, Liepa 2003),
//! oriented like the faces around the loop.
//!
//! `mesh` is the output of repair(): polygons of any arity over `mesh.soup.positions` (#V by 3,
//! in the soup's length unit), every edge with one or two sides, the two running in opposite
//! directions, no singular vertex. Existing faces, vertices and their provenance are untouched;
//! the new triangles are appended after them, in the order of the loops (ordered by their
//! lowest-numbered boundary side), with `face_origin` kNoIndex and three `corner_origin`
//! kNoIndex each: "no input element" (carry_attributes and the writers give such faces the
//! default colour). `face_origin` thus stays non-decreasing. A loop that CGAL cannot triangulate
//! without creating an edge the mesh already has is left open and counted in `holes_left`, as
//! are the loops longer than `max_edges` and the loops whose patch would not close a hole but lie
//! on the surface (FillHolesReport::patches_refused): the outline of an open sheet stays open. With
//! `max_edges` 0 nothing is read or changed and the report is all zeros. \pre `mesh.soup` passes
//! validate_soup(); every polygon has 3 or more distinct corners; every edge has at most two sides,
//! in opposite directions; no vertex is singular (a pinch); the origin arrays have one entry per
//! vertex, face and corner, or are all empty (then they stay empty). \throw std::invalid_argument
//! naming the first element that breaks a precondition \throw std::runtime_error if `max_edges` > 0
//! in a build without CGAL (has_hole_filling())
FillHolesReport fill_holes(IndexedMesh& mesh, const FillHolesOptions& options = {});

//! True if this build can fill holes (it was built with CGAL >= 5.5).
bool has_hole_filling();

}  // namespace meshbridge
