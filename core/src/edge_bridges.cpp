// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/edge_bridges.h"

#include "pipeline/grouping.h"

#include <algorithm>
#include <utility>

namespace meshbridge {

std::vector<Index> corner_faces(const Soup& soup) {
  std::vector<Index> corner_face(soup.num_corners());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    std::fill(corner_face.begin() + soup.face_begin[f],
              corner_face.begin() + soup.face_begin[f + 1], static_cast<Index>(f));
  }
  return corner_face;
}

namespace {

// FaceOf: anything with operator[](corner) giving the corner's face.
template <class FaceOf>
EdgeBridges group_sides_by(const Soup& soup, const FaceOf& corner_face) {
  const std::size_t num_corners = soup.num_corners();
  const std::size_t num_vertices = soup.num_vertices();
  const auto& cv = soup.corner_vertices;

  // Counting sort of the sides by their smaller vertex; `high` keeps each side's larger vertex
  // (freed on return). `sorted` becomes the contenders (no copy). The smaller vertex is looked
  // up again in the second pass rather than kept (one array of fresh memory less).
  std::vector<Index> high(num_corners);
  std::vector<Index> bucket_begin(num_vertices + 1, 0);
  std::vector<Index> sorted(num_corners);
  {
    for (std::size_t c = 0; c < num_corners; ++c) {
      const Index a = cv[c];
      const Index b = cv[soup.next_corner(static_cast<Index>(c), corner_face[c])];
      high[c] = std::max(a, b);
      ++bucket_begin[std::min(a, b) + 1];
    }
    for (std::size_t v = 0; v < num_vertices; ++v)
      bucket_begin[v + 1] += bucket_begin[v];
    std::vector<Index> fill(bucket_begin.begin(), bucket_begin.end() - 1);
    for (std::size_t c = 0; c < num_corners; ++c) {
      const Index a = cv[c];
      const Index b = cv[soup.next_corner(static_cast<Index>(c), corner_face[c])];
      sorted[fill[std::min(a, b)]++] = static_cast<Index>(c);
    }
  }

  EdgeBridges bridges;
  bridges.begin.reserve(num_corners / 2 + 2);

  // Within a bucket, order by (larger vertex, corner): insertion sort for the usual handful of
  // sides, std::sort for the rare crowded vertex (no quadratic worst case).
  const auto before = [&](Index a, Index b) {
    return high[a] < high[b] || (high[a] == high[b] && a < b);
  };
  for (std::size_t v = 0; v < num_vertices; ++v) {
    if (bucket_begin[v] == bucket_begin[v + 1])
      continue;
    Index* first = sorted.data() + bucket_begin[v];
    Index* last = sorted.data() + bucket_begin[v + 1];
    if (last - first > 32) {
      std::sort(first, last, before);
    } else {
      for (Index* i = first + 1; i < last; ++i) {
        const Index c = *i;
        Index* j = i;
        while (j > first && before(c, *(j - 1))) {
          *j = *(j - 1);
          --j;
        }
        *j = c;
      }
    }
    for (Index* i = first; i < last;) {
      const Index other = high[*i];
      while (i < last && high[*i] == other)
        ++i;
      bridges.begin.push_back(static_cast<Index>(i - sorted.data()));
    }
  }
  bridges.contenders = std::move(sorted);
  return bridges;
}

}  // namespace

EdgeBridges group_sides(const Soup& soup, const std::vector<Index>& corner_face) {
  return group_sides_by(soup, corner_face);
}

namespace detail {

EdgeBridges group_sides(const Soup& soup, const CornerFaces& corner_face) {
  return group_sides_by(soup, corner_face);
}

}  // namespace detail

}  // namespace meshbridge
