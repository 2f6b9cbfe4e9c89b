// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/detect_defects.h"

#include "meshbridge/validate.h"

#include "detection.h"
#include "pipeline/fans.h"
#include "pipeline/orientation.h"
#include "union_find.h"

#include <algorithm>
#include <cmath>

namespace meshbridge {

namespace detail {

// Polygons whose vertex set an earlier polygon has. Faces are bucketed by their smallest vertex
// (counting sort, O(#F + #V)); within a bucket a face is a duplicate if an earlier face of the
// bucket has the same sorted vertex list. Small buckets (the usual handful of faces) compare
// those lists pairwise in one flat buffer; crowded ones are sorted by (list, face), so equal
// lists end up side by side and all but the earliest face of each run are duplicates.
std::vector<Index> duplicate_polygons(const Soup& soup) {
  const std::size_t num_faces = soup.num_faces();
  std::vector<Index> smallest(num_faces);
  std::vector<Index> bucket_begin(soup.num_vertices() + 1, 0);
  for (Index f = 0; f < num_faces; ++f) {
    const PolygonView p = soup.polygon(f);
    smallest[f] = *std::min_element(p.begin(), p.end());
    ++bucket_begin[smallest[f] + 1];
  }
  for (std::size_t v = 0; v < soup.num_vertices(); ++v)
    bucket_begin[v + 1] += bucket_begin[v];
  std::vector<Index> bucketed(num_faces);  // each bucket in increasing face order
  {
    std::vector<Index> fill(bucket_begin.begin(), bucket_begin.end() - 1);
    for (Index f = 0; f < num_faces; ++f)
      bucketed[fill[smallest[f]]++] = f;
  }
  constexpr Index kPairwise = 16;  // largest bucket compared pairwise
  std::vector<Index> duplicates;
  std::vector<Index> keys;       // small bucket: sorted vertex lists, flat
  std::vector<Index> key_begin;  // small bucket: where each face's list starts in `keys`
  std::vector<std::pair<std::vector<Index>, Index>> bucket;  // crowded bucket
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    const Index first = bucket_begin[v];
    const Index last = bucket_begin[v + 1];
    if (last - first < 2)
      continue;
    if (last - first <= kPairwise) {
      keys.clear();
      key_begin.clear();
      for (Index i = first; i < last; ++i) {
        const PolygonView p = soup.polygon(bucketed[i]);
        key_begin.push_back(static_cast<Index>(keys.size()));
        const std::size_t start = keys.size();
        keys.insert(keys.end(), p.begin(), p.end());
        if (p.size() > 16) {
          std::sort(keys.begin() + static_cast<std::ptrdiff_t>(start), keys.end());
          continue;
        }
        for (std::size_t j = start + 1; j < keys.size(); ++j) {  // insertion sort: a few corners
          const Index x = keys[j];
          std::size_t k = j;
          for (; k > start && x < keys[k - 1]; --k)
            keys[k] = keys[k - 1];
          keys[k] = x;
        }
      }
      key_begin.push_back(static_cast<Index>(keys.size()));
      const auto list = [&](Index i) {
        return std::make_pair(keys.data() + key_begin[i], keys.data() + key_begin[i + 1]);
      };
      for (Index i = 1; i < last - first; ++i) {
        const auto [a, a_end] = list(i);
        for (Index j = 0; j < i; ++j) {
          const auto [b, b_end] = list(j);
          if (std::equal(a, a_end, b, b_end)) {
            duplicates.push_back(bucketed[first + i]);
            break;
          }
        }
      }
      continue;
    }
    bucket.resize(last - first);
    for (Index i = first; i < last; ++i) {
      const PolygonView p = soup.polygon(bucketed[i]);
      auto& entry = bucket[i - first];
      entry.first.assign(p.begin(), p.end());
      std::sort(entry.first.begin(), entry.first.end());
      entry.second = bucketed[i];
    }
    std::sort(bucket.begin(), bucket.end());  // by vertex list, then by face
    for (std::size_t i = 1; i < bucket.size(); ++i) {
      if (bucket[i].first == bucket[i - 1].first)
        duplicates.push_back(bucket[i].second);
    }
  }
  std::sort(duplicates.begin(), duplicates.end());
  return duplicates;
}

namespace {

// Detection on `working`, whose sides are grouped into `corner_face` and `bridges`. With `owned`
// (== &bridges) the grouping is consumed as it is read: its corner_edge array becomes the manifold
// pairing (every side's entry is read through its edge before it is overwritten) and the bridges
// are freed once the edges are scanned, so the fans and the rest allocate into their room.
DefectReport detect_grouped(const WorkingSoup& working, const std::vector<Index>& corner_face,
                            const EdgeBridges& bridges, EdgeBridges* owned) {
  const Soup& input = working.input();
  const Soup& soup = working.soup();
  const auto& cv = soup.corner_vertices;
  const std::size_t num_edges = bridges.num_edges();
  DefectReport report;
  report.num_vertices = input.num_vertices();
  report.num_faces = input.num_faces();
  report.num_edges = num_edges;
  report.degenerate_faces = working.degenerate_faces();
  report.excluded_faces = working.excluded_faces();

  // Edges: singular, boundary, inconsistent; the manifold pairing for fans and orientation.
  std::vector<Index> manifold_mate;
  if (owned != nullptr)
    manifold_mate = std::move(owned->corner_edge);  // #C, overwritten below side by side
  else
    manifold_mate.resize(soup.num_corners());
  std::vector<char> on_singular_edge(soup.num_vertices(), 0);
  UnionFind boundary_chains(soup.num_vertices());
  UnionFind components(soup.num_faces());
  for (std::size_t e = 0; e < num_edges; ++e) {
    const Index first = bridges.begin[e];
    const Index k = bridges.num_contenders(e);
    const VertexPair pair{bridges.edge_v0[e], bridges.edge_v1[e]};
    for (Index i = first + 1; i < first + k; ++i) {
      components.unite(corner_face[bridges.contenders[first]], corner_face[bridges.contenders[i]]);
    }
    if (k == 2) {
      const Index a = bridges.contenders[first], b = bridges.contenders[first + 1];
      manifold_mate[a] = b;
      manifold_mate[b] = a;
      // Both run from the edge's smaller vertex to its larger one, or both the other way.
      if ((cv[a] == pair.v0) == (cv[b] == pair.v0)) {
        report.inconsistent_edges.push_back(pair);
      }
      continue;
    }
    for (Index i = first; i < first + k; ++i)
      manifold_mate[bridges.contenders[i]] = kNoIndex;
    if (k == 1) {
      report.boundary_edges.push_back(pair);
      boundary_chains.unite(pair.v0, pair.v1);
    } else {
      report.singular_edges.push_back({pair, k});
      on_singular_edge[pair.v0] = 1;
      on_singular_edge[pair.v1] = 1;
    }
  }
  if (owned != nullptr)
    *owned = EdgeBridges();  // not read again: freed before the fans allocate
  {
    std::vector<char> counted(soup.num_vertices(), 0);
    for (const VertexPair& p : report.boundary_edges) {
      for (Index v : {p.v0, p.v1}) {
        const Index r = boundary_chains.find(v);
        if (!counted[r]) {
          counted[r] = 1;
          ++report.num_boundary_loops;
        }
      }
    }
  }

  // Vertices: isolated, on singular edges, pinched (more than one fan through 2-sided edges).
  std::vector<char> pinched(soup.num_vertices(), 0);
  {
    const std::vector<Index> vertex_origin =
        split_fans(soup, corner_face, manifold_mate).vertex_origin;
    for (std::size_t i = soup.num_vertices(); i < vertex_origin.size(); ++i) {
      pinched[vertex_origin[i]] = 1;
    }
  }
  std::vector<char> used(soup.num_vertices(), 0);
  for (Index v : soup.corner_vertices)
    used[v] = 1;
  std::size_t used_count = 0;
  for (Index v = 0; v < soup.num_vertices(); ++v) {
    used_count += used[v];
    if (!used[v]) {
      report.isolated_vertices.push_back(v);
    } else if (on_singular_edge[v]) {
      report.singular_edge_vertices.push_back(v);
    } else if (pinched[v]) {
      report.pinch_vertices.push_back(v);
    }
  }

  // Orientability through 2-sided edges.
  if (!report.inconsistent_edges.empty()) {
    std::vector<char> flipped;
    report.num_nonorientable_components =
        orient_consistently(soup, corner_face, false, manifold_mate, flipped)
            .nonorientable_components;
  }
  manifold_mate = std::vector<Index>();  // freed before the face checks allocate

  for (Index f = 0; f < soup.num_faces(); ++f) {
    if (components.find(f) == f)
      ++report.num_components;
  }
  report.euler_characteristic = static_cast<long long>(used_count) -
                                static_cast<long long>(num_edges) +
                                static_cast<long long>(soup.num_faces());

  // Faces, in input numbering. Zero area: |vector area|^2 <= (1e-12 * sum of squared sides)^2.
  for (Index f = 0; f < input.num_faces(); ++f) {
    const PolygonView polygon = input.polygon(f);
    double squared_sides = 0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      squared_sides +=
          (input.positions[polygon[(i + 1) % polygon.size()]] - input.positions[polygon[i]])
              .sqrnorm();
    }
    const double limit = 1e-12 * squared_sides;
    if (newell_normal(input, f).sqrnorm() <= limit * limit)
      report.zero_area_faces.push_back(f);
  }
  // Duplicates among the polygons as built (a collapsed polygon can duplicate another), reported
  // by input face.
  for (Index f : duplicate_polygons(soup))
    report.duplicate_faces.push_back(working.face_origin(f));
  std::sort(report.duplicate_faces.begin(), report.duplicate_faces.end());
  report.duplicate_faces.erase(
      std::unique(report.duplicate_faces.begin(), report.duplicate_faces.end()),
      report.duplicate_faces.end());

  report.watertight = soup.num_faces() > 0 && report.boundary_edges.empty() &&
                      report.singular_edges.empty() && report.num_singular_vertices() == 0 &&
                      report.inconsistent_edges.empty() && report.num_nonorientable_components == 0;
  return report;
}

}  // namespace

DefectReport detect(const WorkingSoup& working, const GroupedSides& grouped) {
  return detect_grouped(working, grouped.corner_face, grouped.bridges, nullptr);
}

DefectReport detect(const WorkingSoup& working, GroupedSides&& grouped) {
  return detect_grouped(working, grouped.corner_face, grouped.bridges, &grouped.bridges);
}

}  // namespace detail

DefectReport detect_defects(const Soup& soup) {
  validate_soup(soup);
  const detail::WorkingSoup working(soup);
  return detail::detect(working, detail::group_sides(working.soup()));
}

}  // namespace meshbridge
