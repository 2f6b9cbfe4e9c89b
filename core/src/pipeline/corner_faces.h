// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The face of every corner: c / k when every polygon has k corners (a triangle soup), else a
// table of #C entries. Most files are all triangles or all quads, and the table would be the
// largest array of the grouping after the soup itself (4 bytes per corner, freshly paged).

#include "meshbridge/soup.h"

#include <vector>

namespace meshbridge::detail {

class CornerFaces {
 public:
  CornerFaces() = default;  //!< of no corners
  //! The faces of `soup`'s corners; a table only when its polygons differ in size.
  explicit CornerFaces(const Soup& soup);
  //! A view of `table` (#C entries, as from corner_faces()), which must outlive this.
  explicit CornerFaces(const std::vector<Index>& table) : table_(table.data()) {}

  // Moving a vector keeps its buffer, so a moved table_ still points into owned_.
  CornerFaces(CornerFaces&&) noexcept = default;
  CornerFaces& operator=(CornerFaces&&) noexcept = default;
  CornerFaces(const CornerFaces&) = delete;
  CornerFaces& operator=(const CornerFaces&) = delete;

  //! Face of corner c.
  Index operator[](Index c) const {
    if (arity_ == 3)
      return c / 3;  // the usual case: a multiplication, not a division
    return arity_ != 0 ? c / arity_ : table_[c];
  }

 private:
  Index arity_ = 0;           //!< k when every polygon has k corners, else 0
  std::vector<Index> owned_;  //!< the table, when built here
  const Index* table_ = nullptr;
};

}  // namespace meshbridge::detail
