// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
//! \file self_intersections.h
//! Self-intersections (the paper's third geometric defect): face pairs that cross, found with
//! exact (filtered) predicates. Detection only: nothing is changed.

#include "meshbridge/soup.h"

#include <cstddef>
#include <string>
#include <vector>

namespace meshbridge {

//! Two faces of a soup, `f0 < f1`.
struct FacePair {
  Index f0 = kNoIndex;
  Index f1 = kNoIndex;
  friend bool operator==(const FacePair& a, const FacePair& b) {
    return a.f0 == b.f0 && a.f1 == b.f1;
  }
};

//! Options of find_self_intersections().
struct SelfIntersectionOptions {
  //! Threads to use; 0 (default) = as many as MeshBridge may use (MESHBRIDGE_THREADS, else the
  //! CPUs of this process, at most 8), one per 65,536 triangles; > 0 = exactly this many, at
  //! any size. The result (every list, in its order) is the same for every count.
  unsigned threads = 0;
};

//! What find_self_intersections() finds. Every list is sorted and free of repeats.
struct SelfIntersectionReport {
  std::vector<FacePair> face_pairs;  //!< pairs of faces that intersect (rules: see below)
  std::vector<Index> faces;          //!< faces in at least one such pair
  //! Pairs of connected components (faces connected through shared vertex indices; numbered
  //! 0, 1, ... in order of their first face) with a face of one crossing a face of the other:
  //! the shells of an assembly that cross. A component crossing only itself is not listed.
  std::vector<FacePair> component_pairs;
  std::size_t num_components = 0;  //!< components of the soup, as numbered above
  //! Triangles left out because their corners are collinear (zero area: detect_defects()
  //! reports such faces); a face all of whose triangles are degenerate takes no part.
  std::size_t degenerate_triangles = 0;

  bool has_self_intersections() const { return !face_pairs.empty(); }
};

//! True if this build can find self-intersections (it needs CGAL's predicates at build time).
bool self_intersections_available();

//! Finds the pairs of faces of `soup` that intersect. Polygons are cut into triangles as the
//! STL writer cuts them (ear clipping in their plane); two faces intersect when a triangle of
//! one and a triangle of the other do, decided with CGAL's exact-predicates kernel (Epick:
//! filtered, so touching and crossing are told apart without a tolerance). Vertices are compared
//! by position, so the copies of a vertex that repair splits count as one shared vertex.
//! Triangles of one face are never tested against each other. For two triangles that share
//! - no vertex: any common point counts (crossing, touching, or overlapping when coplanar), as
//!   CGAL's self_intersections counts it;
//! - one vertex: they intersect if either one's side opposite that vertex meets the other
//!   triangle (a fold through the shared corner); meeting at the shared vertex alone does not,
//!   nor touching along a side from it (a corner of one on a side of the other that starts at
//!   the shared vertex, the two off each other's plane or in one plane on either side of that
//!   side: so meet the faces around an edge that repair split at its midpoint);
//! - one edge (two vertices): they intersect only if they are coplanar and lie on the same side
//!   of that edge (folded flat onto each other); meeting along the shared edge alone does not;
//! - three vertices (the same triangle twice): they overlap, and count.
//! Broad phase: a uniform grid of about two cells per triangle; the cells are shared out among
//! the threads.
//! \pre `soup` passes validate_soup()
//! \throw InvalidSoupError naming the offending element
//! \throw std::runtime_error if self_intersections_available() is false
SelfIntersectionReport find_self_intersections(const Soup& soup,
                                               const SelfIntersectionOptions& options = {});

//! The lines `check` prints: the counts, each list with its first `max_listed` elements
//! (face pairs as "f0-f1", faces, component pairs as "c0-c1").
std::string to_text(const SelfIntersectionReport& report, std::size_t max_listed = 10);

}  // namespace meshbridge
