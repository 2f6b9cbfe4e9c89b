// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Disjoint sets over 0..n-1 with path halving and union by index (the smaller root wins,
// which keeps results independent of the order of unions).

#include "meshbridge/soup.h"

#include <utility>
#include <vector>

namespace meshbridge::detail {

class UnionFind {
 public:
  explicit UnionFind(std::size_t n) : parent_(n) {
    for (std::size_t i = 0; i < n; ++i)
      parent_[i] = static_cast<Index>(i);
  }
  Index find(Index x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }
  //! Returns true if x and y were in different sets.
  bool unite(Index x, Index y) {
    x = find(x);
    y = find(y);
    if (x == y)
      return false;
    if (x < y)
      std::swap(x, y);
    parent_[x] = y;
    return true;
  }
  std::size_t size() const { return parent_.size(); }

  //! Consumes the sets: element x gets label_of_root(r) of its set's root r (the set's smallest
  //! element), called once per set in increasing order of roots. One pass, no find(): a parent is
  //! always smaller than its child, so it is labelled first.
  template <class LabelOfRoot>
  std::vector<Index> take_labels(LabelOfRoot label_of_root) && {
    for (std::size_t x = 0; x < parent_.size(); ++x) {
      const Index p = parent_[x];
      parent_[x] = p == x ? label_of_root(static_cast<Index>(x)) : parent_[p];
    }
    return std::move(parent_);
  }

 private:
  std::vector<Index> parent_;
};

}  // namespace meshbridge::detail
