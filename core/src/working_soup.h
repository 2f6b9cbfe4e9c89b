// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The soup every algorithm works on: only simple polygons (no repeated vertex index).

#include "meshbridge/soup.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace meshbridge::detail {

//! Input polygons made simple. A polygon with a repeated vertex index is *degenerate*: its
//! consecutive repeats are collapsed, and one that still revisits a vertex (pinched) is split into
//! simple loops. Loops with fewer than 3 corners cannot exist in a half-edge mesh: a face left with
//! none is *set aside* (listed). When no polygon is degenerate the input is used as is.
//! A *keyhole polygon* (an outline and holes joined by slits, triangulate_keyhole()) is split into
//! its loops here too, as detection sees the file's edges; its triangles are kept beside
//! (keyholes()), and repair puts them in place of its loops, so that the outline's loop does not
//! cover the holes.
class WorkingSoup {
 public:
  explicit WorkingSoup(const Soup& input);

  const Soup& soup() const { return identity_ ? input_ : owned_; }
  const Soup& input() const { return input_; }
  bool is_identity() const { return identity_; }

  Index face_origin(Index f) const { return identity_ ? f : face_origin_[f]; }
  Index corner_origin(Index c) const { return identity_ ? c : corner_origin_[c]; }

  const std::vector<Index>& degenerate_faces() const { return degenerate_; }
  const std::vector<Index>& faces_set_aside() const { return set_aside_; }
  //! Pinched polygons split, and the extra faces that repair makes of them: a keyhole polygon
  //! one per triangle after the first, another one per loop after the first.
  std::size_t faces_split() const { return faces_split_; }
  std::size_t faces_added_by_split() const { return faces_added_by_split_; }
  //! Keyhole slits: two-corner loops of pinched polygons (the polygon runs a -> b and later
  //! b -> a), as (face of the working soup's first loop of that polygon, a, b) with a, b
  //! vertices. No face of this soup holds them; detection still counts their edge and joins the
  //! polygon's loops through them, as the file joins them. `in_keyhole`: the polygon is in
  //! keyholes() (its triangles hold the slit), otherwise repair sets the slit aside.
  struct Slit {
    Index face, a, b;
    bool in_keyhole;
  };
  const std::vector<Slit>& slits() const { return slits_; }
  std::size_t slits_set_aside() const { return slits_.size() - slits_in_keyholes_; }
  //! A keyhole polygon cut as one polygon with holes: its loops are faces `first_face` ..
  //! `first_face + num_loops - 1` of soup(); repair replaces them by the triangles
  //! `corners[first_corner .. first_corner + 3 * num_triangles)` (corners of input(), each
  //! triangle running the polygon's way round).
  struct Keyhole {
    Index first_face, num_loops, first_corner, num_triangles;
  };
  const std::vector<Keyhole>& keyholes() const { return keyholes_; }
  const std::vector<Index>& keyhole_corners() const { return keyhole_corners_; }

 private:
  const Soup& input_;
  bool identity_ = true;
  Soup owned_;
  std::vector<Index> face_origin_;
  std::vector<Index> corner_origin_;
  std::vector<Index> degenerate_;
  std::vector<Index> set_aside_;
  std::size_t faces_split_ = 0;
  std::size_t faces_added_by_split_ = 0;
  std::vector<Slit> slits_;
  std::size_t slits_in_keyholes_ = 0;
  std::vector<Keyhole> keyholes_;
  std::vector<Index> keyhole_corners_;
};

//! True if the polygon repeats a vertex index.
bool has_repeated_vertex(PolygonView polygon);

//! Splits a polygon that repeats a vertex into simple loops of >= 3 corners: consecutive repeats
//! collapse (cyclically), then a loop is cut out each time a vertex comes back, the earlier corner
//! of that vertex staying. `ids` are the polygon's corners in order (corner ids, or vertex indices
//! themselves), `vertex(id)` their vertex; returns the loops as lists of ids (none if no loop of 3
//! distinct corners is left). The one rule for repair (WorkingSoup) and the writers of triangles.
//! `slits`, when given, gets the two ids of each loop of two corners that is left out: a keyhole's
//! slit, where the polygon runs a -> b and later b -> a.
template <class VertexOf>
std::vector<std::vector<Index>> simple_loops(
    std::vector<Index> ids, VertexOf vertex,
    std::vector<std::pair<Index, Index>>* slits = nullptr) {
  std::vector<Index> collapsed;
  for (Index c : ids) {
    if (collapsed.empty() || vertex(collapsed.back()) != vertex(c))
      collapsed.push_back(c);
  }
  while (collapsed.size() > 1 && vertex(collapsed.back()) == vertex(collapsed.front()))
    collapsed.pop_back();
  std::vector<std::vector<Index>> loops;
  std::vector<Index> stack;
  for (Index c : collapsed) {
    auto again =
        std::find_if(stack.begin(), stack.end(), [&](Index s) { return vertex(s) == vertex(c); });
    if (again != stack.end()) {
      std::vector<Index> loop(again, stack.end());
      if (loop.size() >= 3)
        loops.push_back(std::move(loop));
      else if (loop.size() == 2 && slits != nullptr)
        slits->emplace_back(loop[0], loop[1]);
      stack.erase(again + 1, stack.end());
      continue;  // keep the earlier corner of the revisited vertex
    }
    stack.push_back(c);
  }
  if (stack.size() >= 3)
    loops.push_back(std::move(stack));
  else if (stack.size() == 2 && slits != nullptr)
    slits->emplace_back(stack[0], stack[1]);
  return loops;
}

}  // namespace meshbridge::detail
