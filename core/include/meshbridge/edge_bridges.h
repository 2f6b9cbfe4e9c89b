// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file edge_bridges.h
//! Edge bridges: every polygon side grouped with the others on the same vertex pair.
//!
//! Glossary (our word -> the field's):
//! - *side* (of a polygon, identified by its corner) ~ half-edge;
//! - *contender* ~ one of the half-edges on a vertex pair (geometry-central: a *sibling*);
//! - *edge bridge* ~ all half-edges of an edge, manifold or not (the sibling list);
//! - *mate* (the side a side is paired with) ~ opposite / twin half-edge;
//! - *unpaired* side ~ boundary half-edge; *cut* = unpaired on purpose;
//! - *singular edge* ~ non-manifold (complex) edge: more than two sides;
//! - *fan* ~ umbrella (one connected ring or wedge of faces around a vertex); a vertex with
//!   several fans is a non-manifold (complex) vertex, *pinch* if its edges are all manifold;
//! - *stitched* ~ glued / zipped: unpaired sides paired again after orientation;
//! - *set aside* (a polygon with fewer than 3 distinct corners; listed as `faces_set_aside`
//!   in reports) ~ a degenerate face dropped by other readers;
//! - *sheet* ~ a face with the same side of space (material or void) on both sides.
//! - *triangulated* (a polygon written as triangles, `polygons_triangulated`): ear-clipped,
//!   fanned only where ear clipping gives up (geometry/triangulate.h);
//! - *color* in identifiers (`vertex_colors`, `ColorScale`, MeshLab's `color_faces` and
//!   `colored_faces`), as OpenMesh, vcglib and the formats spell it; prose and messages write
//!   British "colour".

#include "meshbridge/soup.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace meshbridge {

//! All contenders of every edge. A *contender* is a polygon side, identified by its corner c
//! (the side runs from corner c to the next corner of its polygon).
//!
//! Edge e is the vertex pair `edge_vertices(e, ...)` = (v0 < v1) and its contenders are
//! `contenders[begin[e] .. begin[e+1])`, in increasing corner order. Edges are numbered in
//! increasing (v0, v1) order, so the numbering depends on the vertices only, not on face order.
//! 1 contender: boundary edge; 2: manifold edge; more: singular edge.
struct EdgeBridges {
  std::vector<Index> begin{0};    //!< #E+1 offsets into contenders
  std::vector<Index> contenders;  //!< #C corners, grouped by edge

  std::size_t num_edges() const { return begin.size() - 1; }
  Index num_contenders(std::size_t e) const { return begin[e + 1] - begin[e]; }

  //! The vertex pair (v0 < v1) of edge e, read off its first contender (not stored: two arrays
  //! of #E entries less). \param corner_face face of each corner (anything indexable by corner,
  //! as `corner_faces(soup)`) \pre e < num_edges()
  template <class CornerFace>
  std::pair<Index, Index> edge_vertices(std::size_t e, const Soup& soup,
                                        const CornerFace& corner_face) const {
    const Index c = contenders[begin[e]];
    const Index a = soup.corner_vertices[c];
    const Index b = soup.corner_vertices[soup.next_corner(c, corner_face[c])];
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  }
};

//! Groups the sides of `soup` by vertex pair in O(#C) (counting sort by smaller vertex).
//! \param corner_face face of each corner (as from `corner_faces(soup)`)
//! \pre `soup` passes validate_soup()
EdgeBridges group_sides(const Soup& soup, const std::vector<Index>& corner_face);

//! Face of each corner: #C entries.
std::vector<Index> corner_faces(const Soup& soup);

}  // namespace meshbridge
