// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file polygon_triangles.h
//! The triangles every route that holds triangles only (the STL and 3MF writers, the STL round
//! trip, the MeshLab plugin's layer) cuts a soup's polygons into: one triangulation for all.

#include "meshbridge/soup.h"

#include <array>
#include <cstdint>
#include <vector>

namespace meshbridge {

//! The triangles of every polygon of a soup, as corner positions within their polygon.
struct PolygonTriangles {
  //! Each triangle's corners as positions 0..n-1 in its polygon of n corners, running the
  //! polygon's way round; a triangle of the soup is {0, 1, 2}.
  std::vector<std::array<std::uint32_t, 3>> corners;
  //! Face f's triangles are corners[first[f]] .. corners[first[f + 1] - 1]; #F + 1 entries.
  std::vector<Index> first;
};

//! The triangles that write_mesh() writes for `soup` in STL and 3MF: a polygon of n > 3 corners
//! is cut into n - 2 triangles by ear clipping in the plane of its Newell normal (Meisters
//! 1975), and no ear whose diagonal is already an edge of the mesh (a side of any polygon, or a
//! diagonal chosen for an earlier one) is taken while the polygon has another ear, so a closed
//! 2-manifold soup stays one when written as triangles. A keyhole polygon (an outline and holes
//! joined by slits: it runs a -> b and later b -> a) is cut as one polygon with holes, the holes
//! left open, its triangles naming the polygon's own corners; another polygon that repeats a
//! vertex is cut as its simple loops, its triangles naming each vertex by its first position.
//! \pre `soup` passes validate_soup()
PolygonTriangles triangles_as_written(const Soup& soup);

//! `soup` with each polygon replaced by its triangles_as_written(), in face order; the vertices
//! are the same. What a 3MF file of `soup` holds (an STL file also welds by position:
//! stl_round_trip()). #F' = number of triangles.
Soup as_triangles(const Soup& soup);

}  // namespace meshbridge
