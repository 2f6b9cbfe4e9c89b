// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Disjoint sets that also know, per element, whether its set was reversed since it joined.

#include "meshbridge/soup.h"

#include <vector>

namespace meshbridge::detail {

class ParityUnionFind {
 public:
  explicit ParityUnionFind(std::size_t n) : parent_(n), parity_(n, 0), size_(n, 1) {
    for (std::size_t i = 0; i < n; ++i)
      parent_[i] = static_cast<Index>(i);
  }
  //! Root of x; `flip` receives the accumulated reversal of x.
  Index find(Index x, char& flip) {
    // First pass: root and total parity; second pass: compress.
    Index root = x;
    char total = 0;
    while (parent_[root] != root) {
      total ^= parity_[root];
      root = parent_[root];
    }
    flip = static_cast<char>(total ^ parity_[root]);
    char below_root = total;  // parity of x relative to root, excluding the root's own
    while (parent_[x] != root && x != root) {
      const Index next = parent_[x];
      const char own = parity_[x];
      parent_[x] = root;
      parity_[x] = below_root;
      below_root ^= own;
      x = next;
    }
    return root;
  }
  //! Joins the sets of roots a and b, reversing b's set first if `reverse_b`.
  void unite_roots(Index a, Index b, bool reverse_b) {
    parity_[b] = static_cast<char>(parity_[b] ^ (reverse_b ? 1 : 0) ^ parity_[a]);
    parent_[b] = a;
    size_[a] += size_[b];
  }
  Index size(Index root) const { return size_[root]; }

 private:
  std::vector<Index> parent_;
  std::vector<char> parity_;
  std::vector<Index> size_;
};

}  // namespace meshbridge::detail
