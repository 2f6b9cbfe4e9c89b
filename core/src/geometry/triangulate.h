// SPDX-License-Identifier: GPL-3.0-or-later
// Polygons to triangles for the formats that hold triangles only (STL, 3MF, and the STL round
// trip that predicts what a reader gets back): ear clipping in the polygon's plane, so that a
// non-convex polygon is covered by triangles inside it, not by a fan that can reach outside.

#pragma once

#include "meshbridge/soup.h"

#include <array>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace meshbridge::detail {

//! Reusable buffers of triangulate_polygon().
struct Triangulation {
  std::vector<std::array<Index, 3>> triangles;  //!< the result: corners as vertex indices
  std::vector<double> u, v;                     // (scratch) the corners in the polygon's plane
  std::vector<Index> previous, next;            // (scratch) the ring of corners left
  std::vector<Index> ring;                      // (scratch) one simple loop of a pinched polygon
  //! triangulate_keyhole()'s result: the triangles' corners as positions in its `vertices`
  std::vector<std::array<Index, 3>> positions;
  //! Undirected edges (edge_key()) an ear's diagonal should not be: the sides of the soup's
  //! polygons and the diagonals chosen so far (avoid_existing_edges()); empty: no such check.
  std::unordered_set<std::uint64_t> taken;
};

//! The key of the undirected edge {a, b} in Triangulation::taken.
inline std::uint64_t edge_key(Index a, Index b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

//! Makes the triangulate_polygon() calls on `soup` that follow choose no diagonal that is already
//! an edge of the mesh (a side of a polygon, or a diagonal chosen for an earlier polygon) wherever
//! the polygon has another ear: a diagonal that reused an edge would give that edge three or
//! more triangles in the written file. Call it once per soup before triangulating its polygons
//! in order; it does nothing (no memory, no time) when every polygon is a triangle.
void avoid_existing_edges(const Soup& soup, Triangulation& t);

//! A keyhole polygon (DESIGN 3) runs a -> b and later b -> a (a slit): an outline and holes
//! joined by slits, as one loop of corners, `vertices` (vertex indices of `soup`, in order).
//! Ear-clips it as one weakly simple polygon, as a polygon with holes is cut once its holes are
//! bridged to the outline (Eberly, "Triangulation by ear clipping"; mapbox earcut): the ends of a
//! slit are two corners each, and a corner at the place of an ear's point does not block it.
//! True, with m - 2 triangles (m: corners after collapsing consecutive repeats) in `t.triangles`
//! (vertex indices) and `t.positions` (positions in `vertices`), when exactly one of its simple
//! loops (simple_loops()) turns the polygon's way round (the outline), the others the other way
//! (the holes), and every triangle turns that way: then no triangle overlaps another or covers
//! a hole. False otherwise (no slit, a slit to a loop outside the outline, a hole wound like the
//! outline, no ear left): such a polygon is split into its simple loops like any pinched one.
bool triangulate_keyhole(const Soup& soup, const std::vector<Index>& vertices, Triangulation& t);

//! The triangles of polygon `f` of `soup` (n >= 3 corners), each running the polygon's way
//! round, into `t.triangles`: a triangle as it is; larger polygons by ear clipping (Meisters 1975;
//! O(n^2)) in the plane of their Newell normal, cutting off at each step the first convex corner
//! whose triangle holds no other corner of the ring and whose diagonal is not in `t.taken` (when
//! every ear's diagonal is taken, the first ear): n - 2 triangles. A polygon of more than 3
//! corners that repeats a vertex is cut as repair cuts it, so it gets the triangles repair would
//! give it (polygon_triangle_count()): a keyhole polygon as one polygon with holes
//! (triangulate_keyhole()); otherwise (pinched, "1 2 3 1 4 5") split into simple loops
//! (simple_loops()), each cut on its own; if no loop is left, it is fanned as it is (its degenerate
//! triangles keep the record). A ring with no ear left (self-intersecting, or flat to a line), a
//! zero normal, or more than 4096 corners has the rest fanned from its first remaining corner.
void triangulate_polygon(const Soup& soup, std::size_t f, Triangulation& t);

//! How many triangles triangulate_polygon() gives polygon `f` of `soup`: n - 2, or for a
//! keyhole polygon its triangulate_keyhole() count, or for another pinched polygon of more than 3
//! corners the sum over its simple loops.
std::size_t polygon_triangle_count(const Soup& soup, std::size_t f);

}  // namespace meshbridge::detail
