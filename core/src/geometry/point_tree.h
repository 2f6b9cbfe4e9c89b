// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A static kd-tree over points for gap closing's "boundary vertices near a boundary side"
// queries (close_gaps.cpp): median splits on the longest box side (Bentley 1975; as nanoflann
// and CGAL's Kd_tree), leaves of up to 8 points.

#include "meshbridge/soup.h"

#include <cstddef>
#include <utility>
#include <vector>

namespace meshbridge::detail {

// A static kd-tree over a set of points (leaves of up to 8), for "points near a segment"
// queries whose cost follows the number of boxes the segment passes near, not the side lengths.
class PointTree {
 public:
  //! The tree of `points` (indices into `positions`). \pre `positions` outlives the tree
  PointTree(const std::vector<Point>& positions, std::vector<Index> points)
      : positions_(positions), points_(std::move(points)) {
    if (!points_.empty()) {
      nodes_.reserve(points_.size() / 2 + 1);
      nodes_.resize(1);
      build(0, 0, points_.size());
    }
  }

  // Calls visit(v) for every point whose node box, grown by r, the segment a-b meets (a superset
  // of the points within r of the segment; callers check distances exactly).
  template <class Visit>
  void for_each_near_segment(const Point& a, const Point& b, double r, Visit&& visit) const {
    if (nodes_.empty())
      return;
    std::vector<std::size_t> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (!segment_meets_box(a, b, node.lo - Point(r, r, r), node.hi + Point(r, r, r)))
        continue;
      if (node.left == 0) {
        for (std::size_t i = node.first; i < node.last; ++i)
          visit(points_[i]);
      } else {
        stack.push_back(node.left);
        stack.push_back(node.left + 1);
      }
    }
  }

 private:
  struct Node {
    Point lo, hi;
    std::size_t first = 0, last = 0;
    std::size_t left = 0;  // children left and left + 1; 0 for a leaf
  };

  // Fills node `slot` (already allocated) for points_[first, last) and its subtree.
  void build(std::size_t slot, std::size_t first, std::size_t last);

  // Slab test: does the segment a-b meet the box [lo, hi]?
  static bool segment_meets_box(const Point& a, const Point& b, const Point& lo, const Point& hi);

  const std::vector<Point>& positions_;
  std::vector<Index> points_;
  std::vector<Node> nodes_;
};

}  // namespace meshbridge::detail
