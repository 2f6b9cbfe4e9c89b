// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/pairing.h"

#include "geometry/newell_normal.h"
#include "geometry/signed_volume.h"
#include "parallel_parts.h"
#include "pipeline/angular_order.h"
#include "union_find.h"

#include <algorithm>
#include <cmath>

namespace meshbridge::detail {

namespace {

void pair(std::vector<Index>& mate, Index a, Index b) {
  mate[a] = b;
  mate[b] = a;
}

// Combinatorial rule over `sides` (in the order given): opposite-running sides first come,
// first paired. `waiting` is scratch space (kept between calls: no allocation per edge).
void pair_opposite_in_order(const Soup& soup, const CornerFaces& corner_face,
                            const std::vector<Index>& sides, std::vector<Index>& mate,
                            std::vector<Index> (&waiting)[2]) {
  // Each side takes the earliest still waiting side that runs the other way: the same pairs as
  // "each unpaired side takes the first later opposite one", in linear time.
  waiting[0].clear();
  waiting[1].clear();
  std::size_t head[2] = {0, 0};
  for (Index side : sides) {
    if (mate[side] != kNoIndex)
      continue;
    const int along = runs_along(soup, corner_face, side) ? 1 : 0;
    const int other = 1 - along;
    if (head[other] < waiting[other].size()) {
      pair(mate, waiting[other][head[other]++], side);
    } else {
      waiting[along].push_back(side);
    }
  }
}

// A singular edge's angular order, stored flat for all edges.
struct ContenderRange {
  const OrderedSide* first;
  const OrderedSide* last;
  const OrderedSide* begin() const { return first; }
  const OrderedSide* end() const { return last; }
  std::size_t size() const { return static_cast<std::size_t>(last - first); }
  const OrderedSide& operator[](std::size_t i) const { return first[i]; }
};

// The angular orders of a share of the singular edges (edge i of the share: flat[order_begin[i]
// .. order_begin[i + 1]]), and their sides without a direction (likewise in undirected).
struct SortedEdges {
  std::vector<OrderedSide> flat;
  std::vector<Index> undirected;
  std::vector<Index> order_begin, undirected_begin;
};

// Fewer singular edges than this per thread cost more to start a thread for than they save.
constexpr std::size_t kLeastEdgesPerThread = 4096;

// The side of a contender face that looks into the wedge after it (counter-clockwise) and the
// one that looks into the wedge before it. Face side ids: 2f front, 2f+1 back.
Index ccw_face_side(const OrderedSide& c, Index face) {
  return 2 * face + (c.along ? 0 : 1);
}
Index cw_face_side(const OrderedSide& c, Index face) {
  return 2 * face + (c.along ? 1 : 0);
}

// Pairs cyclic neighbours (in `cycle`) whose wedge lies behind both faces: the first runs against
// the axis, the next along it. In an inside-out component (`inside_out`, per face) behind and in
// front swap: its faces are read as if reversed.
void pair_behind_neighbours(const std::vector<OrderedSide>& cycle, const CornerFaces& corner_face,
                            const std::vector<char>& inside_out, std::vector<Index>& mate) {
  const std::size_t m = cycle.size();
  if (m < 2)
    return;
  const auto along = [&](const OrderedSide& o) {
    return o.along != (inside_out[corner_face[o.side]] != 0);
  };
  for (std::size_t t = 0; t < m; ++t) {
    const OrderedSide& a = cycle[t];
    const OrderedSide& b = cycle[(t + 1) % m];
    if (!along(a) && along(b) && mate[a.side] == kNoIndex && mate[b.side] == kNoIndex) {
      pair(mate, a.side, b.side);
    }
  }
}

// Per face: 1 if its component (faces joined through any edge) is closed (an even number of
// sides on every edge, so its signed volume does not depend on where it is measured from) and
// encloses a negative volume as written (far above rounding: |volume| > 1e-9 x the sum of the
// terms' magnitudes). Open components are read as written. Such a component is inside out as a
// whole; pairing reads it as if reversed, so that reversing every face of the input pairs the same
// sides (DESIGN 8a, intent: the space around a model is void, whichever way the file winds it).
std::vector<char> inside_out_faces(const Soup& soup, const GroupedSides& grouped) {
  const CornerFaces& corner_face = grouped.corner_face;
  const EdgeBridges& bridges = grouped.bridges;
  const std::size_t num_faces = soup.num_faces();
  UnionFind components(num_faces);
  std::vector<Index> odd_edge_face;  // a face on each edge with an odd number of sides
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index first = corner_face[bridges.contenders[bridges.begin[e]]];
    for (Index i = bridges.begin[e] + 1; i < bridges.begin[e + 1]; ++i)
      components.unite(first, corner_face[bridges.contenders[i]]);
    if (bridges.num_contenders(e) % 2 == 1)
      odd_edge_face.push_back(first);
  }
  std::vector<Index> root(num_faces);
  std::vector<double> volume(num_faces, 0.0), magnitude(num_faces, 0.0);
  std::vector<Index> reference(num_faces, kNoIndex);  // a vertex of each component
  for (Index f = 0; f < num_faces; ++f) {
    const Index r = root[f] = components.find(f);
    const PolygonView p = soup.polygon(f);
    if (reference[r] == kNoIndex)
      reference[r] = p[0];
    add_fan_volume(soup, p, soup.positions[reference[r]], volume[r], magnitude[r]);
  }
  std::vector<char> open(num_faces, 0);  // per root
  for (Index f : odd_edge_face)
    open[components.find(f)] = 1;
  std::vector<char> inside_out(num_faces, 0);
  for (Index f = 0; f < num_faces; ++f) {
    const Index r = root[f];
    inside_out[f] = !open[r] && volume[r] < -1e-9 * magnitude[r];
  }
  return inside_out;
}

// Per face: 1 if it separates no material from void (see pair_contenders). Consumes `regions`:
// votes are summed per region, numbered densely, so they take memory per region, not per side.
std::vector<char> sheets(const Soup& soup, UnionFind&& regions) {
  const std::size_t num_faces = soup.num_faces();
  Index num_regions = 0;
  const std::vector<Index> region =
      std::move(regions).take_labels([&num_regions](Index) { return num_regions++; });
  std::vector<double> vote(num_regions, 0.0);
  std::vector<float> weight(num_regions, 0.0f);  // only scales the rounding tolerance
  for (Index f = 0; f < num_faces; ++f) {
    const double area = newell_normal(soup, f).norm();
    const Index front = region[2 * f], back = region[2 * f + 1];
    vote[front] -= area;
    vote[back] += area;
    weight[front] += static_cast<float>(area);
    weight[back] += static_cast<float>(area);
  }
  // Votes that cancel to rounding (a face and its reversed copy) say nothing.
  const auto kind = [&](Index r) {
    if (std::abs(vote[r]) <= 1e-9 * weight[r])
      return 0;
    return vote[r] > 0 ? 1 : -1;
  };
  std::vector<char> sheet(num_faces, 0);
  for (Index f = 0; f < num_faces; ++f) {
    const Index front = region[2 * f], back = region[2 * f + 1];
    sheet[f] = front == back || (kind(front) != 0 && kind(front) == kind(back));
  }
  return sheet;
}

}  // namespace

std::vector<Index> pair_contenders(const Soup& soup, const GroupedSides& grouped,
                                   PairingPolicy policy) {
  const CornerFaces& corner_face = grouped.corner_face;
  const EdgeBridges& bridges = grouped.bridges;
  std::vector<Index> mate(soup.num_corners(), kNoIndex);
  std::vector<Index> singular;
  std::size_t singular_sides = 0;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index first = bridges.begin[e];
    const Index k = bridges.num_contenders(e);
    if (k == 2) {
      pair(mate, bridges.contenders[first], bridges.contenders[first + 1]);
    } else if (k > 2) {
      singular.push_back(static_cast<Index>(e));
      singular_sides += k;
    }
  }
  if (singular.empty())
    return mate;

  std::vector<Index> sides, waiting[2];
  const auto combinatorial = [&](std::size_t e) {
    sides.assign(bridges.contenders.begin() + bridges.begin[e],
                 bridges.contenders.begin() + bridges.begin[e + 1]);
    pair_opposite_in_order(soup, corner_face, sides, mate, waiting);
  };
  if (policy == PairingPolicy::combinatorial) {
    for (Index e : singular)
      combinatorial(e);
    return mate;
  }

  // Geometric: the angular order of every singular edge's contenders that have a direction
  // there; those without one (flat against the edge) are kept aside per edge. Edges are
  // independent: with several threads each sorts a share of them into buffers of its own.
  const unsigned parts = static_cast<unsigned>(std::clamp<std::size_t>(
      singular.size() / kLeastEdgesPerThread, 1, std::max(worker_threads(), 1u)));
  std::vector<SortedEdges> sorted(parts);
  run_parts(parts, [&](unsigned t) {
    SortedEdges& part = sorted[t];
    const std::size_t first = part_begin(singular.size(), parts, t);
    const std::size_t last = part_begin(singular.size(), parts, t + 1);
    AngularSorter sorter;
    std::vector<OrderedSide> order_scratch;
    std::vector<Index> undirected_scratch;
    part.flat.reserve(singular_sides / parts + 64);  // the sides with a direction: seldom fewer
    part.order_begin.assign(1, 0);
    part.undirected_begin.assign(1, 0);
    for (std::size_t s = first; s < last; ++s) {
      const Index e = singular[s];
      sorter.sort(soup, grouped, e, bridges.contenders.data() + bridges.begin[e],
                  bridges.contenders.data() + bridges.begin[e + 1], order_scratch,
                  undirected_scratch);
      if (order_scratch.size() >= 2) {
        part.flat.insert(part.flat.end(), order_scratch.begin(), order_scratch.end());
        part.undirected.insert(part.undirected.end(), undirected_scratch.begin(),
                               undirected_scratch.end());
      } else {  // nothing to order: every side waits for elimination, in face-key order
        std::vector<Index> waiting_sides(undirected_scratch);
        for (const OrderedSide& o : order_scratch)
          waiting_sides.push_back(o.side);
        sort_by_face_key(soup, corner_face, waiting_sides);
        part.undirected.insert(part.undirected.end(), waiting_sides.begin(), waiting_sides.end());
      }
      part.order_begin.push_back(static_cast<Index>(part.flat.size()));
      part.undirected_begin.push_back(static_cast<Index>(part.undirected.size()));
    }
  });
  const auto order_of = [&](std::size_t s, unsigned t) {
    const SortedEdges& part = sorted[t];
    const std::size_t i = s - part_begin(singular.size(), parts, t);
    return ContenderRange{part.flat.data() + part.order_begin[i],
                          part.flat.data() + part.order_begin[i + 1]};
  };

  // Regions of space: face sides joined across every wedge. Face side 2f looks the way the
  // face's normal points (its front), 2f+1 behind it.
  UnionFind regions(2 * soup.num_faces());
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index first = bridges.begin[e];
    const Index k = bridges.num_contenders(e);
    if (k == 1) {
      const Index f = corner_face[bridges.contenders[first]];
      regions.unite(2 * f, 2 * f + 1);
    } else if (k == 2) {
      const Index a = bridges.contenders[first], b = bridges.contenders[first + 1];
      const Index fa = corner_face[a], fb = corner_face[b];
      const bool opposite = runs_along(soup, corner_face, a) != runs_along(soup, corner_face, b);
      regions.unite(2 * fa, 2 * fb + (opposite ? 0 : 1));
      regions.unite(2 * fa + 1, 2 * fb + (opposite ? 1 : 0));
    }
  }
  for (std::size_t s = 0, part = 0; s < singular.size(); ++s) {
    while (s >= part_begin(singular.size(), parts, part + 1))
      ++part;
    const ContenderRange order = order_of(s, part);
    for (std::size_t t = 0; t < order.size(); ++t) {
      const OrderedSide& a = order[t];
      const OrderedSide& b = order[(t + 1) % order.size()];
      regions.unite(ccw_face_side(a, corner_face[a.side]), cw_face_side(b, corner_face[b.side]));
    }
  }
  // Material or void: every face votes, with its area, that the region behind it is material
  // and the one in front of it void. A face whose two sides lie in one region, or in two regions
  // of the same kind (a membrane between two solids, a sheet in the open), separates nothing:
  // it is a sheet.
  const std::vector<char> sheet = sheets(soup, std::move(regions));
  const std::vector<char> inside_out = inside_out_faces(soup, grouped);

  // Each edge's pairs touch only its own sides: the edges are paired in the same shares.
  run_parts(parts, [&](unsigned t) {
    const SortedEdges& part = sorted[t];
    const std::size_t first = part_begin(singular.size(), parts, t);
    const std::size_t last = part_begin(singular.size(), parts, t + 1);
    std::vector<OrderedSide> cycle;
    std::vector<Index> edge_sides, waiting_scratch[2];
    for (std::size_t s = first; s < last; ++s) {
      const ContenderRange order = order_of(s, t);
      // (a) solids first: the sheets are taken out of the cycle.
      cycle.clear();
      for (const auto& c : order)
        if (!sheet[corner_face[c.side]])
          cycle.push_back(c);
      pair_behind_neighbours(cycle, corner_face, inside_out, mate);
      // (b) everything still unpaired.
      cycle.clear();
      for (const auto& c : order)
        if (mate[c.side] == kNoIndex)
          cycle.push_back(c);
      pair_behind_neighbours(cycle, corner_face, inside_out, mate);
      // (c) elimination, opposite-running only: what is left in cyclic order, then the sides
      //     without a direction, in face-key order.
      edge_sides.clear();
      for (const auto& c : cycle)
        if (mate[c.side] == kNoIndex)
          edge_sides.push_back(c.side);
      const std::size_t i = s - first;
      edge_sides.insert(edge_sides.end(), part.undirected.begin() + part.undirected_begin[i],
                        part.undirected.begin() + part.undirected_begin[i + 1]);
      pair_opposite_in_order(soup, corner_face, edge_sides, mate, waiting_scratch);
    }
  });
  return mate;
}

}  // namespace meshbridge::detail
