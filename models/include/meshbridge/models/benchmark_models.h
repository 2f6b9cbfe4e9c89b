// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file benchmark_models.h
//! Scalable inputs for bench/: random soups with a known share of singular edges, and the
//! paper's two models at any resolution. The conventions of canonical_models.h hold here too
//! (welded, deterministic, quads split as (a, b, c), (a, c, d) unless stated otherwise).

#include "meshbridge/soup.h"

#include <cstddef>
#include <cstdint>

namespace meshbridge::models {

//! Options of random_singular_soup().
struct RandomSoupOptions {
  int n = 256;  //!< torus stations around the major circle (as torus_grid), >= 3
  int m = 128;  //!< torus stations around the minor circle, >= 3
  //! Share of the torus's 3 * n * m edges that get fins, in [0, 1]; the number of singular
  //! edges is exactly llround(singular_fraction * 3 * n * m).
  double singular_fraction = 0.1;
  int max_fins = 2;        //!< each chosen edge gets 1 .. max_fins fins (uniformly), in [1, 8]
  std::uint64_t seed = 1;  //!< same seed, same soup on every platform (own splitmix64)
};

//! A random soup with a given fraction of singular edges: the clean torus_grid(n, m) (its
//! vertices and faces first, unchanged), then, for each chosen torus edge {a, b} in increasing
//! edge order, its fins: triangles (a, b, apex) or (b, a, apex) (orientation drawn at random),
//! each with its own new apex vertex standing off the surface (fins of one edge fan out within
//! 60 degrees of the outward normal).
//! Edge e of quad q = i * m + j is e = 3 q + {0: (i,j)-(i+1,j), 1: (i,j)-(i,j+1),
//! 2: the diagonal (i,j)-(i+1,j+1)}.
//! Counts: n * m + fins vertices, 2 * n * m + fins triangles, where fins is between k and
//! k * max_fins for k = llround(singular_fraction * 3 * n * m).
//! Defects: exactly k singular edges (3 .. max_fins + 2 contenders each), their end points
//! singular; 2 boundary edges per fin; orientation conflicts where a fin runs the same way as
//! both torus faces of its edge. All other edges have 2 contenders.
//! \pre n >= 3, m >= 3, n * m <= 2^26, 0 <= singular_fraction <= 1, 1 <= max_fins <= 8
//! \throw std::invalid_argument otherwise
Soup random_singular_soup(const RandomSoupOptions& options = {});

//! The paper's model 2 at subdivision level k: the regular hexagon of prisms24_hexagon()
//! (circumradius 1, centre at the origin, z = 0), its 6 centre triangles each cut into (2k)^2
//! triangles (their edges split into s = 2k segments), each triangle extruded to height 1 into a
//! closed outward prism: bottom cap (-z), top cap (+z), then its 3 quad sides (not split),
//! 5 faces per prism, prism p has faces 5p .. 5p + 4. k = 1 is the 24 prisms of
//! prisms24_hexagon() (same points, other numbering).
//! Points: the triangular lattice a * (1, 0) / s + b * (1/2, sqrt(3)/2) / s with |a|, |b|,
//! |a + b| <= s, b slowest; P = 3s^2 + 3s + 1 of them, vertices 0 .. P-1 at z = 0 and P .. 2P-1
//! the same points at z = 1. Prisms: T = 6s^2 = 24 k^2, one per lattice triangle in cell order.
//! Counts: 2P vertices, 5T faces (2T triangles, 3T quads).
//! Defects: 2(9s^2 - 3s) + P singular edges: the 9s^2 - 3s interior lattice edges at z = 0 and
//! at z = 1 have 4 contenders; the vertical edge at a lattice point with t triangles has 2t
//! contenders (t = 6 inside, 3 on the rim, 2 at the 6 corners); all 2P vertices are singular;
//! 9s^2 - 3s pairs of coincident quads (opposite orientation). The 12s rim edges have 2.
//! Correct repair: 24 k^2 closed components, 0 faces lost.
//! \pre 1 <= k <= 64
//! \throw std::invalid_argument otherwise
Soup prisms_hexagon(int k);

//! Options of stiffened_plate().
struct StiffenedPlateOptions {
  int resolution = 2;  //!< r: grid cells per unit length, plate and ribs alike, >= 1
  int ribs = 3;        //!< R: stiffeners parallel to x, at y = 1 .. R, >= 0
  int cross_ribs = 0;  //!< C: stiffeners parallel to y, at x = 2, 4, .. 2C, >= 0
};

//! The paper's model 1: a plate with stiffener ribs, as open sheets (a shell model). The plate
//! is [0, X] x [0, Y] at z = 0 with X = 2(C + 1), Y = R + 1, a grid of nx = X r by ny = Y r
//! split quads, normals +z; its vertices come first, (i, j) at (i / r, j / r, 0) is vertex
//! j (nx + 1) + i. Then the R ribs (sheets y = 1 .. R, x in [0, X], z in [0, 1], nx by r split
//! quads, normals -y), then the C cross ribs (sheets x = 2 .. 2C, y in [0, Y], ny by r split
//! quads, normals +x). Every rib stands on a plate grid line and shares its foot vertices with
//! the plate; a cross rib shares the vertical line where it crosses a rib (r edges).
//! Counts: V = (nx+1)(ny+1) + R (nx+1) r + C ((ny+1) r - R r) vertices,
//! F = 2 nx ny + 2 R nx r + 2 C ny r triangles.
//! Defects: R nx + C ny singular edges with 3 contenders (the ribs' feet) and R C r with 4 (the
//! crossings); R (nx+1) + C (ny+1) - R C + R C r singular vertices; boundary: the plate's rim,
//! every rib's top and its two free ends: 2(nx + ny) + R (nx + 2r) + C (ny + 2r) edges.
//! Correct repair: 0 faces lost; the plate stays one piece, each rib is cut off at its foot.
//! \pre resolution >= 1, ribs >= 0, cross_ribs >= 0, and at most 2^28 faces
//! \throw std::invalid_argument otherwise
Soup stiffened_plate(const StiffenedPlateOptions& options = {});

}  // namespace meshbridge::models
