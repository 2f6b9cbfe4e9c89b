// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The angular order of the contenders around an edge (used by pairing and stitching).

#include "pipeline/grouping.h"

#include <vector>

namespace meshbridge::detail {

//! A contender in its edge's angular order.
struct OrderedSide {
  Index side;
  bool along;  //!< runs from the edge's smaller to its larger vertex
};

//! Normal of side c's face *where it leaves the edge* (not scaled to anything): for a triangle
//! its normal; for a larger polygon the sum of the unit normals of the triangles (a, b, next)
//! and (previous, a, b) at the side a -> b that agree with the polygon's Newell normal, so a bent
//! polygon sorts like its triangulation at that edge; the Newell normal if neither does. Zero
//! when the face is flat against its edge there (see kFlatAngle).
Point local_normal(const Soup& soup, const CornerFaces& corner_face, Index c);

//! A triangle (a, b, x) is flat against a -> b when x's distance from the line is at most this
//! times the triangle's longest side (about the angle, in radians, that it leaves the line at).
constexpr double kFlatAngle = 1e-7;

//! Sorts contenders of one edge around it. Reusable scratch inside; not thread-safe.
class AngularSorter {
 public:
  //! Sorts the sides [first, last) of edge e by the angle of their in-face direction (from
  //! local_normal()) around the axis from the edge's smaller to its larger vertex, starting after
  //! the widest gap. Faces within about 1e-7 rad of each other (coincident) are ordered
  //! along-running first, then against-running, each by face key; copies of one face by
  //! increasing corner if along-running, decreasing if against, so coincident copies nest. Sides
  //! whose face has no direction there (flat against the edge: zero or near-zero area) take no
  //! part: they go to `undirected`, in face-key order. Returns false if the edge has no axis (its
  //! end points coincide): then `order` is empty and every side is in `undirected`.
  bool sort(const Soup& soup, const GroupedSides& grouped, std::size_t e, const Index* first,
            const Index* last, std::vector<OrderedSide>& order, std::vector<Index>& undirected);

 private:
  struct Angled {
    double angle;
    bool along;
    Index side;
  };
  std::vector<Angled> scratch_;
  // Tie runs: the faces' keys, flat, and the run's order.
  std::vector<Index> key_, key_flat_;
  std::vector<std::size_t> key_begin_, run_;
  std::vector<Angled> sorted_run_;
};

//! A face's key, which does not depend on face order or polygon start: its sorted vertex list,
//! then its vertices from the smallest one on (so polygons on one vertex set differ).
void face_key(const Soup& soup, Index f, std::vector<Index>& key);

//! Orders sides by their faces' keys (face_key()), then by side.
void sort_by_face_key(const Soup& soup, const CornerFaces& corner_face, std::vector<Index>& sides);

//! `sides` of edge e in the order stitching walks them: the angular order, then the sides
//! without a direction in face-key order (all in face-key order if the edge has no axis).
void sort_by_angle(const Soup& soup, const GroupedSides& grouped, std::size_t e,
                   std::vector<Index>& sides);

}  // namespace meshbridge::detail
