// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file canonical_models.h
//! The canonical cases of DESIGN.md section 4, built in code, and generators for stress inputs.
//!
//! Conventions shared by every function here:
//! - The soup is welded: a point shared by several faces is one vertex index, stored once, so
//!   shared vertices have bit-identical coordinates. No two vertices have the same position.
//! - Every closed solid is consistently oriented with outward normals: each polygon is
//!   counter-clockwise seen from outside (right-hand rule), so its signed volume is positive and
//!   within one solid every directed edge (a, b) occurs exactly once, together with (b, a).
//! - Quads are split into triangles (a, b, c), (a, c, d) unless stated otherwise.
//! - Output is deterministic: same vertex and face order on every run and platform (only the
//!   last bits of coordinates computed with cos/sin may depend on the C library).
//! - "Contenders" of a vertex pair are the polygon sides lying on it (see DESIGN.md section 3).
//!   In the defect lists below, every edge not mentioned has exactly 2 contenders running in
//!   opposite directions (a consistent manifold edge).

#include "meshbridge/soup.h"

#include <string>
#include <vector>

namespace meshbridge::models {

//! Two closed unit cubes touching along one edge: cube A = [0,1]^3, cube B = [1,2]x[1,2]x[0,1],
//! sharing the edge x = 1, y = 1 (vertices (1,1,0) and (1,1,1)).
//! 14 vertices, 24 triangles: faces 0-11 are cube A, faces 12-23 are cube B. Vertices 0-7 are
//! cube A's corners (corner c at (c&1, (c>>1)&1, (c>>2)&1)), then B's 6 unshared corners.
//! Defects: 1 singular edge with 4 contenders, its 2 end vertices are singular.
//! Correct repair: 16 vertices, 24 faces, 2 closed components, 0 boundary edges.
Soup two_cubes_sharing_edge();

//! Two tetrahedra sharing one apex vertex (0,0,0); the other one below (z = -1), one above
//! (z = +1). 7 vertices (vertex 0 is the apex), 8 triangles: faces 0-3 are the lower
//! tetrahedron, 4-7 the upper one.
//! Defects: 1 pinch vertex (vertex 0, two fans), no singular edge.
//! Correct repair: 8 vertices, 8 faces, 2 closed components.
Soup hourglass();

//! Two triangles in z = 0 (normals +z) sharing vertex 0 only. 5 vertices, 2 triangles.
//! Defects: 1 pinch vertex (vertex 0), 6 boundary edges, 1 component.
//! Correct repair: 6 vertices, 2 faces, 2 components.
Soup bowtie();

//! Three triangles on one edge, like the pages of a book: v0 = (0,0,0), v1 = (0,0,1) on the z
//! axis, apex i (vertex 2 + i) at angle 0, 120, 240 degrees around it (radius 1, z = 0.5).
//! Triangle i is (v0, v1, apex_i). 5 vertices, 3 triangles.
//! Defects: 1 singular edge {v0, v1} with 3 contenders, all running v0 -> v1 (so no pair of them
//! is orientation-compatible as given); v0 and v1 are singular; 6 boundary edges.
//! Correct repair: one pair kept (one face of it flipped), one face separated, 3 faces.
Soup book_of_three();

//! An open plate and a rib sheet standing on it (T-junction).
//! Plate: z = 0, [-2,2]x[-1,1], a 4x2 grid of quads split into 16 triangles, normals +z; its
//! vertices 0-14 are grid point (i, j) at (i - 2, j - 1, 0) with index j * 5 + i.
//! Rib: the sheet y = 0, x in [-2,2], z in [0,1], 4 quads split into 8 triangles, normals -y;
//! its bottom row is the plate's middle row (vertices 5-9), its top row is vertices 15-19.
//! 20 vertices, 24 triangles: faces 0-15 plate, 16-23 rib.
//! Defects: 4 singular edges (the joint y = 0, z = 0) with 3 contenders each, their 5 vertices
//! singular; boundary: the plate's rim (12 edges) and the rib's sides and top (6 edges).
//! Correct repair: plate stays one piece, rib separated, 0 faces lost.
Soup t_junction_plate_rib();

//! A closed box plate [0,4]x[0,2]x[-0.5,0] with a closed box rib [1,3]x[0.5,1.5]x[0,1] standing
//! on it. The plate is a box gridded at x in {0,1,3,4}, y in {0,0.5,1.5,2}, z in {-0.5,0}
//! (30 quads, 60 triangles, vertices 0-31); its top centre quad is the rib's footprint
//! [1,3]x[0.5,1.5]. The rib (12 triangles, 4 new vertices 32-35 on top) uses the footprint's 4
//! vertices and the same diagonal, so its 2 bottom triangles coincide with the 2 plate-top
//! triangles of the footprint, with opposite orientation. Both boxes outward.
//! 36 vertices, 72 triangles: faces 0-59 plate, 60-71 rib.
//! Defects: 5 singular edges with 4 contenders each (the footprint's 4 sides and its diagonal),
//! 4 singular vertices (the footprint's corners), 2 pairs of coincident (duplicate, opposite)
//! faces.
//! Correct repair: 2 closed components (plate, rib), 72 faces, 0 boundary edges.
Soup plate_with_box_rib();

//! The paper's model 2: a regular hexagon (circumradius 1, centre at the origin, z = 0) split
//! into 24 triangles (each of the 6 centre triangles split into 4 at its edge midpoints; 19
//! points), each extruded to height 1 into a closed triangular prism: bottom cap, top cap and 3
//! quad sides, all outward. Welded: neighbouring prisms share their side quad (coincident quads
//! with opposite orientation) and their vertical edge.
//! 38 vertices (0-18 at z = 0, 19-37 the same points at z = 1), 120 faces = 48 triangles +
//! 72 quads: prism p has faces 5p (bottom), 5p+1 (top), 5p+2 .. 5p+4 (sides).
//! Defects: 79 singular edges, all vertices singular, 30 pairs of coincident quads. Each of the
//! 30 interior horizontal edges at z = 0 and at z = 1 has 4 contenders (2 caps, 2 sides); the
//! vertical edge at a point with t incident triangles has 2t contenders: 12 at the centre and at
//! the 6 spoke midpoints (t = 6), 6 at the 6 rim midpoints (t = 3), 4 at the 6 hexagon corners
//! (t = 2). The 24 hexagon rim edges (12 at each height) have 2 contenders.
//! Correct repair: 24 closed components, 120 faces, none lost.
Soup prisms24_hexagon();

//! A Moebius strip: a quad strip with a half twist around the unit circle in z = 0, width 0.6,
//! welded at the seam. 2 * segments vertices (vertex 2i at v = -0.3, 2i + 1 at v = +0.3 of
//! station i), segments quads (quad i joins stations i and i + 1; the last one joins the
//! stations at the seam with the twist).
//! Defects: 1 non-orientable component: the seam rung {0, 1} is traversed in the same direction
//! by quads 0 and segments - 1 (1 orientation-inconsistent edge); 1 boundary loop of
//! 2 * segments edges.
//! \pre segments >= 3
//! \throw std::invalid_argument otherwise
Soup moebius_strip(int segments = 12);

//! A clean closed manifold: icosahedron on the unit sphere, each subdivision splits every
//! triangle into 4 with the midpoints pushed to the sphere. 10 * 4^s + 2 vertices,
//! 20 * 4^s triangles (s = 1: 42 vertices, 80 triangles), outward, genus 0. No defects.
//! \pre 0 <= subdivisions <= 10
//! \throw std::invalid_argument otherwise
Soup icosphere(int subdivisions = 1);

//! The unit cube [0,1]^3 as 12 triangles minus the 2 triangles of its top face (z = 1).
//! 8 vertices (corner c at (c&1, (c>>1)&1, (c>>2)&1)), 10 triangles, outward.
//! Defects: 1 boundary loop of 4 edges (the hole), no singular element.
Soup cube_with_hole();

//! 3D checkerboard of unit cubes (stress input): of the n^3 cells (i, j, k) in [0,n)^3, cell
//! (i, j, k) = [i,i+1]x[j,j+1]x[k,k+1] is a cube iff i + j + k is even; ceil(n^3 / 2) cubes,
//! 12 triangles each (cell order: i fastest, then j, then k; 12 consecutive faces per cube).
//! Vertices are the used integer lattice points, numbered in lattice order (x fastest, then y,
//! then z): all (n+1)^3 of them for odd n, (n+1)^3 - 4 for even n >= 2 (4 grid corners touch
//! only an odd cell).
//! n = 56: 87,808 cubes, 1,053,696 triangles, 185,189 vertices.
//! Defects: every lattice edge shared by two cubes has 4 contenders: exactly the 3 * n * (n-1)^2
//! unit edges not on the grid's outer surface (508,200 for n = 56); all other edges have 2.
//! Their end points are singular vertices. No boundary edges, no shared faces.
//! Correct repair: every cube closed and separate (8 vertices per cube; 702,464 for n = 56).
//! \pre 0 <= n <= 600 (so that all corner indices fit in 32 bits)
//! \throw std::invalid_argument otherwise
Soup checkerboard_cubes(int n);

//! A clean closed torus (control input): n stations around the major circle (radius 1), m
//! around the minor circle (radius 0.25). n * m vertices (vertex i * m + j), 2 * n * m
//! triangles, outward, genus 1. No defects.
//! \pre n >= 3, m >= 3, n * m <= 2^28
//! \throw std::invalid_argument otherwise
Soup torus_grid(int n, int m);

//! A model with the file name (without extension) it is stored under in resources/models/.
struct NamedModel {
  std::string name;  //!< file stem, e.g. "twocubes"
  Soup soup;
};

//! The bundled resource set, in this order: twocubes, hourglass, bowtie, book_of_three,
//! t_junction_rib, plate_box_rib, prisms24, moebius (12 segments), icosphere (1 subdivision),
//! cube_with_hole.
std::vector<NamedModel> canonical_models();

}  // namespace meshbridge::models
