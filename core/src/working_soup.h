// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The soup every algorithm works on: only simple polygons (no repeated vertex index).

#include "meshbridge/soup.h"

#include <vector>

namespace meshbridge::detail {

//! Input polygons made simple. A polygon with a repeated vertex index is *degenerate*: its
//! consecutive repeats are collapsed, and one that still revisits a vertex (pinched) is split into
//! simple loops. Loops with fewer than 3 corners cannot exist in a half-edge mesh: a face left with
//! none is *excluded* (set aside, listed). When no polygon is degenerate the input is used as is.
class WorkingSoup {
 public:
  explicit WorkingSoup(const Soup& input);

  const Soup& soup() const { return identity_ ? input_ : owned_; }
  const Soup& input() const { return input_; }
  bool is_identity() const { return identity_; }

  Index face_origin(Index f) const { return identity_ ? f : face_origin_[f]; }
  Index corner_origin(Index c) const { return identity_ ? c : corner_origin_[c]; }

  const std::vector<Index>& degenerate_faces() const { return degenerate_; }
  const std::vector<Index>& excluded_faces() const { return excluded_; }
  std::size_t faces_split() const { return faces_split_; }
  std::size_t faces_added_by_split() const { return faces_added_by_split_; }

 private:
  const Soup& input_;
  bool identity_ = true;
  Soup owned_;
  std::vector<Index> face_origin_;
  std::vector<Index> corner_origin_;
  std::vector<Index> degenerate_;
  std::vector<Index> excluded_;
  std::size_t faces_split_ = 0;
  std::size_t faces_added_by_split_ = 0;
};

//! True if the polygon repeats a vertex index.
bool has_repeated_vertex(PolygonView polygon);

}  // namespace meshbridge::detail
