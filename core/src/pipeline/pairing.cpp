// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/pairing.h"

#include "union_find.h"

#include <algorithm>
#include <cmath>

namespace meshbridge::detail {

namespace {

// Angles are "diamond" pseudo-angles: monotonic in the true angle, 4 per full turn, and
// between 0.5 and 1 per radian, so a tie tolerance of 1e-7 is 1e-7 to 2e-7 rad.
constexpr double kFullTurn = 4.0;
constexpr double kTieAngle = 1e-7;

// Pseudo-angle of (x, y) in [0, 4): no trigonometry.
double pseudo_angle(double x, double y) {
  if (y >= 0)
    return x >= 0 ? y / (x + y) : 1 - x / (-x + y);
  return x < 0 ? 2 - y / (-x - y) : 3 + x / (x - y);
}

void pair(std::vector<Index>& mate, Index a, Index b) {
  mate[a] = b;
  mate[b] = a;
}

// Combinatorial rule over `sides` (in the order given): opposite-running sides first come,
// first paired.
void pair_opposite_in_order(const Soup& soup, const EdgeBridges& bridges,
                            const std::vector<Index>& sides, std::vector<Index>& mate) {
  // Each side takes the earliest still waiting side that runs the other way: the same pairs as
  // "each unpaired side takes the first later opposite one", in linear time.
  std::vector<Index> waiting[2];
  std::size_t head[2] = {0, 0};
  for (Index side : sides) {
    if (mate[side] != kNoIndex)
      continue;
    const int along = runs_along(soup, bridges, side) ? 1 : 0;
    const int other = 1 - along;
    if (head[other] < waiting[other].size()) {
      pair(mate, waiting[other][head[other]++], side);
    } else {
      waiting[along].push_back(side);
    }
  }
}

struct AngularContender {
  double angle;
  bool along;
  Index side;
};

// A contender in its edge's angular order, the angle dropped once sorted (half the memory).
struct OrderedSide {
  Index side;
  bool along;
};

struct ContenderRange {
  const OrderedSide* first;
  const OrderedSide* last;
  const OrderedSide* begin() const { return first; }
  const OrderedSide* end() const { return last; }
  std::size_t size() const { return static_cast<std::size_t>(last - first); }
  const OrderedSide& operator[](std::size_t i) const { return first[i]; }
};

// Sorts the given sides of edge e by angle around its axis; false if the geometry is unusable.
template <class NormalOf>
bool angular_order(const Soup& soup, const EdgeBridges& bridges, std::size_t e,
                   const Index* sides_begin, const Index* sides_end, NormalOf normal_of,
                   std::vector<AngularContender>& order) {
  order.clear();
  Point axis = soup.positions[bridges.edge_v1[e]] - soup.positions[bridges.edge_v0[e]];
  const double length = axis.norm();
  if (!(length > 0))
    return false;
  axis /= length;
  // A frame (e1, e2) perpendicular to the axis.
  const int least = std::abs(axis[0]) <= std::abs(axis[1])
                        ? (std::abs(axis[0]) <= std::abs(axis[2]) ? 0 : 2)
                        : (std::abs(axis[1]) <= std::abs(axis[2]) ? 1 : 2);
  Point helper(0, 0, 0);
  helper[least] = 1;
  Point e1 = OpenMesh::cross(axis, helper).normalized();
  Point e2 = OpenMesh::cross(axis, e1);

  for (const Index* it = sides_begin; it != sides_end; ++it) {
    const Index side = *it;
    const Point n = normal_of(side);
    const bool along = runs_along(soup, bridges, side);
    Point d = OpenMesh::cross(n, axis);
    if (!along)
      d = -d;
    const double dn = d.norm();
    if (!(dn > 1e-12 * n.norm()) || !(dn > 0))
      return false;
    order.push_back({pseudo_angle(OpenMesh::dot(d, e1), OpenMesh::dot(d, e2)), along, side});
  }
  std::sort(order.begin(), order.end(),
            [](const AngularContender& a, const AngularContender& b) { return a.angle < b.angle; });
  // Start the cycle after the widest gap, so no run of ties straddles the cut.
  const std::size_t k = order.size();
  std::size_t widest = k - 1;
  double widest_gap = order.front().angle + kFullTurn - order.back().angle;
  for (std::size_t i = 0; i + 1 < k; ++i) {
    const double gap = order[i + 1].angle - order[i].angle;
    if (gap > widest_gap) {
      widest_gap = gap;
      widest = i;
    }
  }
  const std::size_t first = (widest + 1) % k;
  for (std::size_t i = 0; i < first; ++i)
    order[i].angle += kFullTurn;
  std::rotate(order.begin(), order.begin() + first, order.end());
  // Within a run of ties: along-running sides first by increasing corner, then against-running
  // ones by decreasing corner, so coincident copies nest (the outermost pair of the cycle is
  // made of the first copies) and never interleave.
  for (std::size_t i = 0; i < k;) {
    std::size_t j = i + 1;
    while (j < k && order[j].angle - order[j - 1].angle <= kTieAngle)
      ++j;
    std::sort(order.begin() + i, order.begin() + j,
              [](const AngularContender& a, const AngularContender& b) {
                if (a.along != b.along)
                  return a.along;
                return a.along ? a.side < b.side : a.side > b.side;
              });
    i = j;
  }
  return true;
}

// The side of a contender face that looks into the wedge after it (counter-clockwise) and the
// one that looks into the wedge before it. Face side ids: 2f front, 2f+1 back.
Index ccw_face_side(const OrderedSide& c, Index face) {
  return 2 * face + (c.along ? 0 : 1);
}
Index cw_face_side(const OrderedSide& c, Index face) {
  return 2 * face + (c.along ? 1 : 0);
}

// Pairs cyclic neighbours (in `cycle`) whose wedge lies behind both faces: the first runs against
// the axis, the next along it.
void pair_behind_neighbours(const std::vector<OrderedSide>& cycle, std::vector<Index>& mate) {
  const std::size_t m = cycle.size();
  if (m < 2)
    return;
  for (std::size_t t = 0; t < m; ++t) {
    const OrderedSide& a = cycle[t];
    const OrderedSide& b = cycle[(t + 1) % m];
    if (!a.along && b.along && mate[a.side] == kNoIndex && mate[b.side] == kNoIndex) {
      pair(mate, a.side, b.side);
    }
  }
}

}  // namespace

std::vector<Index> pair_contenders(const Soup& soup, const GroupedSides& grouped,
                                   PairingPolicy policy) {
  const std::vector<Index>& corner_face = grouped.corner_face;
  const EdgeBridges& bridges = grouped.bridges;
  std::vector<Index> mate(soup.num_corners(), kNoIndex);
  std::vector<std::size_t> singular;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index first = bridges.begin[e];
    const Index k = bridges.num_contenders(e);
    if (k == 2) {
      pair(mate, bridges.contenders[first], bridges.contenders[first + 1]);
    } else if (k > 2) {
      singular.push_back(e);
    }
  }
  if (singular.empty())
    return mate;

  std::vector<Index> sides;
  const auto combinatorial = [&](std::size_t e) {
    sides.assign(bridges.contenders.begin() + bridges.begin[e],
                 bridges.contenders.begin() + bridges.begin[e + 1]);
    pair_opposite_in_order(soup, bridges, sides, mate);
  };
  if (policy == PairingPolicy::combinatorial) {
    for (std::size_t e : singular)
      combinatorial(e);
    return mate;
  }

  // Geometric: angular orders of all singular edges.
  std::vector<Point> normals(soup.num_faces());
  for (std::size_t f = 0; f < soup.num_faces(); ++f)
    normals[f] = newell_normal(soup, f);
  std::vector<AngularContender> scratch;
  std::vector<OrderedSide> flat;
  std::vector<std::size_t> order_begin(singular.size() + 1, 0);
  std::vector<char> usable(singular.size());
  for (std::size_t s = 0; s < singular.size(); ++s) {
    const std::size_t e = singular[s];
    usable[s] = angular_order(
        soup, bridges, e, bridges.contenders.data() + bridges.begin[e],
        bridges.contenders.data() + bridges.begin[e + 1],
        [&](Index side) { return normals[corner_face[side]]; }, scratch);
    if (usable[s])
      for (const AngularContender& c : scratch)
        flat.push_back({c.side, c.along});
    order_begin[s + 1] = flat.size();
  }
  normals = std::vector<Point>();  // only the angular orders needed them
  const auto order_of = [&](std::size_t s) {
    return ContenderRange{flat.data() + order_begin[s], flat.data() + order_begin[s + 1]};
  };

  // Regions of space: face sides joined across every wedge.
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
      const bool opposite = runs_along(soup, bridges, a) != runs_along(soup, bridges, b);
      regions.unite(2 * fa, 2 * fb + (opposite ? 0 : 1));
      regions.unite(2 * fa + 1, 2 * fb + (opposite ? 1 : 0));
    }
  }
  for (std::size_t s = 0; s < singular.size(); ++s) {
    if (!usable[s])
      continue;
    const ContenderRange order = order_of(s);
    for (std::size_t t = 0; t < order.size(); ++t) {
      const OrderedSide& a = order[t];
      const OrderedSide& b = order[(t + 1) % order.size()];
      regions.unite(ccw_face_side(a, corner_face[a.side]), cw_face_side(b, corner_face[b.side]));
    }
  }

  std::vector<OrderedSide> cycle;
  for (std::size_t s = 0; s < singular.size(); ++s) {
    if (!usable[s]) {
      combinatorial(singular[s]);
      continue;
    }
    const ContenderRange order = order_of(s);
    const auto is_sheet = [&](const OrderedSide& c) {
      const Index f = corner_face[c.side];
      return regions.find(2 * f) == regions.find(2 * f + 1);
    };
    // (a) solids first: the sheets are taken out of the cycle.
    cycle.clear();
    for (const auto& c : order)
      if (!is_sheet(c))
        cycle.push_back(c);
    pair_behind_neighbours(cycle, mate);
    // (b) everything still unpaired.
    cycle.clear();
    for (const auto& c : order)
      if (mate[c.side] == kNoIndex)
        cycle.push_back(c);
    pair_behind_neighbours(cycle, mate);
    // (c) elimination, opposite-running only, in cyclic order.
    sides.clear();
    for (const auto& c : cycle)
      if (mate[c.side] == kNoIndex)
        sides.push_back(c.side);
    pair_opposite_in_order(soup, bridges, sides, mate);
  }
  return mate;
}

void sort_by_angle(const Soup& soup, const GroupedSides& grouped, std::size_t e,
                   std::vector<Index>& sides) {
  const std::vector<Index>& corner_face = grouped.corner_face;
  const EdgeBridges& bridges = grouped.bridges;
  std::vector<AngularContender> order;
  const bool usable = angular_order(
      soup, bridges, e, sides.data(), sides.data() + sides.size(),
      [&](Index side) { return newell_normal(soup, corner_face[side]); }, order);
  if (!usable) {
    std::sort(sides.begin(), sides.end());
    return;
  }
  for (std::size_t i = 0; i < order.size(); ++i)
    sides[i] = order[i].side;
}

}  // namespace meshbridge::detail
