// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/detect_defects.h"

#include "meshbridge/validate.h"

#include "detection.h"
#include "geometry/newell_normal.h"
#include "parallel_parts.h"
#include "pipeline/fans.h"
#include "pipeline/orientation.h"
#include "pipeline/vertex_pairs.h"
#include "union_find.h"

#include <algorithm>
#include <cmath>
#include <future>

namespace meshbridge {

namespace detail {

// Polygons whose vertex set an earlier polygon has. Faces are bucketed by their smallest vertex
// (counting sort, O(#F + #V)); within a bucket a face is a duplicate if an earlier face of the
// bucket has the same sorted vertex list. Small buckets (the usual handful of faces) compare
// those lists pairwise in one flat buffer; crowded ones are sorted by (list, face), so equal
// lists end up side by side and all but the earliest face of each run are duplicates.
std::vector<Index> duplicate_polygons(const Soup& soup) {
  const std::size_t num_faces = soup.num_faces();
  const auto smallest = [&soup](Index f) {  // recomputed, not stored: 4 bytes a face less
    const PolygonView p = soup.polygon(f);
    return *std::min_element(p.begin(), p.end());
  };
  std::vector<Index> bucket_begin(soup.num_vertices() + 1, 0);
  for (Index f = 0; f < num_faces; ++f)
    ++bucket_begin[smallest(f) + 1];
  for (std::size_t v = 0; v < soup.num_vertices(); ++v)
    bucket_begin[v + 1] += bucket_begin[v];
  std::vector<Index> bucketed(num_faces);  // each bucket in increasing face order
  {
    std::vector<Index> fill(bucket_begin.begin(), bucket_begin.end() - 1);
    for (Index f = 0; f < num_faces; ++f)
      bucketed[fill[smallest(f)]++] = f;
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

// The per-edge part of detection, fed every vertex pair once in increasing (v0, v1) order with
// its contenders: edges sorted into singular, boundary, inconsistent; the manifold pairing (a
// 2-sided edge's sides are each other's mate, every other side has none); and the links that
// join faces across singular edges, for the components.
struct EdgeTally {
  explicit EdgeTally(const WorkingSoup& working)
      : cv(working.soup().corner_vertices),
        manifold_mate(working.soup().num_corners()),
        on_singular_edge(working.soup().num_vertices(), 0) {
    report.num_vertices = working.input().num_vertices();
    report.num_faces = working.input().num_faces();
    // A keyhole polygon is counted once, as a keyhole (keyhole_polygons_triangulated), not as
    // degenerate: repair cuts it as one polygon with holes.
    std::size_t k = 0;
    for (Index f : working.degenerate_faces()) {
      while (k < working.keyholes().size() &&
             working.face_origin(working.keyholes()[k].first_face) < f)
        ++k;
      if (k == working.keyholes().size() ||
          working.face_origin(working.keyholes()[k].first_face) != f)
        report.degenerate_faces.push_back(f);
    }
    report.faces_set_aside = working.faces_set_aside();
    for (const WorkingSoup::Slit& s : working.slits())
      slit_pairs.push_back({std::min(s.a, s.b), std::max(s.a, s.b)});
    std::sort(slit_pairs.begin(), slit_pairs.end());
    slit_pairs.erase(std::unique(slit_pairs.begin(), slit_pairs.end()), slit_pairs.end());
    slit_is_edge.assign(slit_pairs.size(), 0);
  }

  void operator()(VertexPair pair, const Index* sides, Index k) {
    if (!slit_pairs.empty()) {
      const auto it = std::lower_bound(slit_pairs.begin(), slit_pairs.end(), pair);
      if (it != slit_pairs.end() && *it == pair)
        slit_is_edge[it - slit_pairs.begin()] = 1;
    }
    if (k == 2) {
      const Index a = sides[0], b = sides[1];
      manifold_mate[a] = b;
      manifold_mate[b] = a;
      // Both run from the edge's smaller vertex to its larger one, or both the other way.
      if ((cv[a] == pair.v0) == (cv[b] == pair.v0))
        report.inconsistent_edges.push_back(pair);
      return;
    }
    for (Index i = 0; i < k; ++i)
      manifold_mate[sides[i]] = kNoIndex;
    if (k == 1) {
      report.boundary_edges.push_back(pair);
      return;
    }
    report.singular_edges.push_back({pair, k});
    on_singular_edge[pair.v0] = 1;
    on_singular_edge[pair.v1] = 1;
    for (Index i = 1; i < k; ++i)
      singular_links.emplace_back(sides[0], sides[i]);
  }

  const std::vector<Index>& cv;
  DefectReport report;
  std::vector<Index> manifold_mate;                     // #C
  std::vector<char> on_singular_edge;                   // #V
  std::vector<std::pair<Index, Index>> singular_links;  // sides on one singular edge
  std::vector<VertexPair> slit_pairs;                   // keyhole slits' edges, sorted
  std::vector<char> slit_is_edge;                       // per slit pair: some side lies on it
};

// The checks of single faces: zero area (in input numbering: |vector area|^2 <= (1e-12 * sum of
// squared sides)^2) and duplicates among the polygons as built (a collapsed polygon can duplicate
// another), reported by input face, sorted.
struct FaceChecks {
  std::vector<Index> zero_area_faces;
  std::vector<Index> duplicate_faces;
};

FaceChecks check_faces(const WorkingSoup& working) {
  const Soup& input = working.input();
  FaceChecks checks;
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
      checks.zero_area_faces.push_back(f);
  }
  for (Index f : duplicate_polygons(working.soup()))
    checks.duplicate_faces.push_back(working.face_origin(f));
  std::sort(checks.duplicate_faces.begin(), checks.duplicate_faces.end());
  checks.duplicate_faces.erase(
      std::unique(checks.duplicate_faces.begin(), checks.duplicate_faces.end()),
      checks.duplicate_faces.end());
  return checks;
}

// Detection on `working` after its edges went through `tally` (num_edges of them).
// With `faces_alongside`, the face checks run on a thread of their own meanwhile.
DefectReport detect_tallied(const WorkingSoup& working, const CornerFaces& corner_face,
                            EdgeTally&& tally, std::size_t num_edges,
                            std::vector<Index>* manifold_mate_out = nullptr,
                            bool faces_alongside = false) {
  // (Where no thread can be started, the checks run when their result is asked for.)
  std::future<FaceChecks> face_checks = std::async(
      faces_alongside ? std::launch::async | std::launch::deferred : std::launch::deferred,
      [&working] { return check_faces(working); });
  const Soup& soup = working.soup();
  DefectReport& report = tally.report;
  // A keyhole's slit is an edge of the file, though no face of the working soup has it.
  for (char is_edge : tally.slit_is_edge)
    num_edges += is_edge ? 0 : 1;
  report.num_edges = num_edges;
  report.slits_set_aside = working.slits_set_aside();
  report.keyhole_polygons_triangulated = working.keyholes().size();
  std::vector<Index>& manifold_mate = tally.manifold_mate;
  const std::vector<char>& on_singular_edge = tally.on_singular_edge;
  {
    UnionFind boundary_chains(soup.num_vertices());
    for (const VertexPair& p : report.boundary_edges)
      boundary_chains.unite(p.v0, p.v1);
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
  const std::vector<char> pinched = multi_fan_vertices(soup, corner_face, manifold_mate);
  std::vector<char> used(soup.num_vertices(), 0);
  for (Index v : soup.corner_vertices)
    used[v] = 1;
  for (const WorkingSoup::Slit& s : working.slits())  // a bridge's own vertex: the file uses it
    used[s.a] = used[s.b] = 1;
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

  // Components: faces joined through any edge (the pairing before orientation cuts any of it).
  {
    UnionFind components(soup.num_faces());
    for (Index c = 0; c < manifold_mate.size(); ++c) {
      if (manifold_mate[c] != kNoIndex && manifold_mate[c] > c)
        components.unite(corner_face[c], corner_face[manifold_mate[c]]);
    }
    for (const auto& [a, b] : tally.singular_links)
      components.unite(corner_face[a], corner_face[b]);
    // The loops of a polygon with a keyhole slit are joined through the slit.
    for (const WorkingSoup::Slit& s : working.slits()) {
      for (Index f = s.face + 1;
           f < soup.num_faces() && working.face_origin(f) == working.face_origin(s.face); ++f)
        components.unite(s.face, f);
    }
    for (Index f = 0; f < soup.num_faces(); ++f) {
      if (components.find(f) == f)
        ++report.num_components;
    }
  }

  // Orientability through 2-sided edges.
  if (!report.inconsistent_edges.empty()) {
    std::vector<char> flipped;
    report.num_nonorientable_components =
        orient_consistently(soup, corner_face, false, manifold_mate, flipped)
            .nonorientable_components;
  }
  if (manifold_mate_out != nullptr)
    *manifold_mate_out = std::move(manifold_mate);
  manifold_mate = std::vector<Index>();  // freed before the face checks allocate

  // A keyhole polygon counts once, as repair's triangles count (their diagonals and triangles
  // add as many edges as faces, less one): an outline with h holes adds 1 - h, not 1.
  std::size_t keyhole_loops = 0;
  for (const WorkingSoup::Keyhole& k : working.keyholes())
    keyhole_loops += k.num_loops - 1;
  report.euler_characteristic = static_cast<long long>(used_count) -
                                static_cast<long long>(num_edges) +
                                static_cast<long long>(soup.num_faces() - keyhole_loops);

  FaceChecks faces = face_checks.get();
  report.zero_area_faces = std::move(faces.zero_area_faces);
  report.duplicate_faces = std::move(faces.duplicate_faces);

  report.watertight = soup.num_faces() > 0 && report.boundary_edges.empty() &&
                      report.singular_edges.empty() && report.num_singular_vertices() == 0 &&
                      report.inconsistent_edges.empty() && report.num_nonorientable_components == 0;
  return std::move(report);
}

void tally_bridges(const Soup& soup, const GroupedSides& grouped, EdgeTally& tally) {
  const EdgeBridges& bridges = grouped.bridges;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const auto [v0, v1] = bridges.edge_vertices(e, soup, grouped.corner_face);
    tally(VertexPair{v0, v1}, bridges.contenders.data() + bridges.begin[e],
          bridges.num_contenders(e));
  }
}

}  // namespace

DefectReport detect(const WorkingSoup& working, const GroupedSides& grouped) {
  EdgeTally tally(working);
  tally_bridges(working.soup(), grouped, tally);
  return detect_tallied(working, grouped.corner_face, std::move(tally), grouped.bridges.num_edges(),
                        nullptr, worker_threads() > 1);
}

DefectReport detect(const WorkingSoup& working, std::vector<Index>* manifold_mate,
                    GroupedSides* grouped_out) {
  if (grouped_out == nullptr) {
    const CornerFaces corner_face(working.soup());
    EdgeTally tally(working);
    const std::size_t num_edges = for_each_vertex_pair(working.soup(), corner_face, tally);
    return detect_tallied(working, corner_face, std::move(tally), num_edges, manifold_mate,
                          worker_threads() > 1);
  }
  return detect_alongside(working, manifold_mate, grouped_out, false).get();
}

std::future<DefectReport> detect_alongside(const WorkingSoup& working,
                                           std::vector<Index>* manifold_mate,
                                           GroupedSides* grouped_out, bool alongside,
                                           bool closed_in_parallel) {
  CornerFaces corner_face(working.soup());
  EdgeTally tally(working);
  // Edge offsets are recorded from the first edge that is not 2-sided on (the ones before it
  // start at 0, 2, 4, ...): a closed 2-manifold candidate never allocates them.
  EdgeBridges bridges;
  std::size_t two_sided_prefix = 0;
  bool keep = false;
  const auto visit = [&](VertexPair pair, const Index* sides, Index k) {
    tally(pair, sides, k);
    if (!keep) {
      if (k == 2) {
        ++two_sided_prefix;
        return;
      }
      keep = true;  // a boundary or singular edge: repair will run the pipeline
      bridges.begin.reserve(working.soup().num_corners() / 2 + 2);  // as group_sides()
      for (std::size_t e = 1; e <= two_sided_prefix; ++e)
        bridges.begin.push_back(static_cast<Index>(2 * e));
    }
    bridges.begin.push_back(bridges.begin.back() + k);
  };
  const std::size_t num_edges =
      for_each_vertex_pair(working.soup(), corner_face, visit, &bridges.contenders);
  if (!keep) {
    bridges = EdgeBridges();  // freed before detection allocates
    *grouped_out = GroupedSides();
    // (A closed candidate: its face checks wait for the edge arrays to go, as one thread's
    // would; side by side they took the peak of a clean 1M torus above OpenMesh reading it.)
    std::promise<DefectReport> here;
    here.set_value(detect_tallied(working, corner_face, std::move(tally), num_edges, manifold_mate,
                                  closed_in_parallel && worker_threads() > 1));
    return here.get_future();
  }
  *grouped_out = GroupedSides{std::move(corner_face), std::move(bridges)};
  if (!alongside) {
    std::promise<DefectReport> here;
    here.set_value(detect_tallied(working, grouped_out->corner_face, std::move(tally), num_edges,
                                  manifold_mate, worker_threads() > 1));
    return here.get_future();
  }
  // (Where no thread can be started, the rest runs when the report is asked for.)
  return std::async(std::launch::async | std::launch::deferred,
                    [&working, tally = std::move(tally), num_edges]() mutable {
                      const CornerFaces own(working.soup());
                      return detect_tallied(working, own, std::move(tally), num_edges);
                    });
}

}  // namespace detail

DefectReport detect_defects(const Soup& soup) {
  validate_soup(soup);
  const detail::WorkingSoup working(soup);
  return detail::detect(working);
}

}  // namespace meshbridge
