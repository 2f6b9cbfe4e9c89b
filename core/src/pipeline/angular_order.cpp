// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/angular_order.h"

#include <algorithm>
#include <cmath>
#include "geometry/newell_normal.h"

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

// Normal (b - a) x (x - a) of triangle (a, b, x), or false if x is flat against the line a-b.
bool triangle_normal(const Point& a, const Point& b, const Point& x, Point& n) {
  const Point ab = b - a;
  const Point ax = x - a;
  n = OpenMesh::cross(ab, ax);
  const double longest = std::max({ab.sqrnorm(), ax.sqrnorm(), (x - b).sqrnorm()});
  // |n| = |ab| * distance of x from the line.
  return n.sqrnorm() > kFlatAngle * kFlatAngle * ab.sqrnorm() * longest;
}

}  // namespace

Point local_normal(const Soup& soup, const CornerFaces& corner_face, Index c) {
  const Index f = corner_face[c];
  const Index first = soup.face_begin[f];
  const Index last = soup.face_begin[f + 1];
  const auto& cv = soup.corner_vertices;
  const auto& p = soup.positions;
  const Index next = c + 1 == last ? first : c + 1;
  const Index after_next = next + 1 == last ? first : next + 1;
  const Point& a = p[cv[c]];
  const Point& b = p[cv[next]];
  Point n;
  if (last - first == 3)
    return triangle_normal(a, b, p[cv[after_next]], n) ? n : Point(0, 0, 0);
  const Index previous = c == first ? last - 1 : c - 1;
  const Point newell = newell_normal(soup, f);
  Point sum(0, 0, 0);
  for (Index x : {after_next, previous}) {
    if (triangle_normal(a, b, p[cv[x]], n) && OpenMesh::dot(n, newell) > 0)
      sum += n / n.norm();
  }
  return sum.sqrnorm() > 0 ? sum : newell;
}

bool AngularSorter::sort(const Soup& soup, const GroupedSides& grouped, std::size_t e,
                         const Index* first, const Index* last, std::vector<OrderedSide>& order,
                         std::vector<Index>& undirected) {
  const EdgeBridges& bridges = grouped.bridges;
  order.clear();
  undirected.clear();
  const auto [v0, v1] = bridges.edge_vertices(e, soup, grouped.corner_face);
  Point axis = soup.positions[v1] - soup.positions[v0];
  const double length = axis.norm();
  if (!(length > 0)) {
    undirected.assign(first, last);
    sort_by_face_key(soup, grouped.corner_face, undirected);
    return false;
  }
  axis /= length;
  // A frame (e1, e2) perpendicular to the axis.
  const int least = std::abs(axis[0]) <= std::abs(axis[1])
                        ? (std::abs(axis[0]) <= std::abs(axis[2]) ? 0 : 2)
                        : (std::abs(axis[1]) <= std::abs(axis[2]) ? 1 : 2);
  Point helper(0, 0, 0);
  helper[least] = 1;
  const Point e1 = OpenMesh::cross(axis, helper).normalized();
  const Point e2 = OpenMesh::cross(axis, e1);

  scratch_.clear();
  for (const Index* it = first; it != last; ++it) {
    const Index side = *it;
    const Point n = local_normal(soup, grouped.corner_face, side);
    const bool along = runs_along(soup, grouped.corner_face, side);
    Point d = OpenMesh::cross(n, axis);
    if (!along)
      d = -d;
    const double dn = d.sqrnorm();
    if (!(dn > kFlatAngle * kFlatAngle * n.sqrnorm()) || !(dn > 0)) {
      undirected.push_back(side);
      continue;
    }
    scratch_.push_back({pseudo_angle(OpenMesh::dot(d, e1), OpenMesh::dot(d, e2)), along, side});
  }
  if (undirected.size() > 1)
    sort_by_face_key(soup, grouped.corner_face, undirected);
  const std::size_t k = scratch_.size();
  if (k == 0)
    return true;
  std::sort(scratch_.begin(), scratch_.end(),
            [](const Angled& a, const Angled& b) { return a.angle < b.angle; });
  // Start the cycle after the widest gap, so no run of ties straddles the cut.
  std::size_t widest = k - 1;
  double widest_gap = scratch_.front().angle + kFullTurn - scratch_.back().angle;
  for (std::size_t i = 0; i + 1 < k; ++i) {
    const double gap = scratch_[i + 1].angle - scratch_[i].angle;
    if (gap > widest_gap) {
      widest_gap = gap;
      widest = i;
    }
  }
  const std::size_t start = (widest + 1) % k;
  for (std::size_t i = 0; i < start; ++i)
    scratch_[i].angle += kFullTurn;
  std::rotate(scratch_.begin(), scratch_.begin() + start, scratch_.end());
  // Within a run of ties (coincident faces, or faces that leave the edge the same way): along-
  // running sides first, then against-running ones; among those by face key (sorted vertex
  // list), so the order does not depend on face order; copies of one face (equal keys) by
  // increasing corner if along-running, by decreasing corner if against, so coincident copies
  // nest (the outermost pair of the cycle is made of the first copies) and never interleave.
  for (std::size_t i = 0; i < k;) {
    std::size_t j = i + 1;
    while (j < k && scratch_[j].angle - scratch_[j - 1].angle <= kTieAngle)
      ++j;
    if (j - i > 1) {
      // Keys of the run in one flat buffer (no allocation per side).
      key_flat_.clear();
      key_begin_.clear();
      for (std::size_t t = i; t < j; ++t) {
        key_begin_.push_back(key_flat_.size());
        face_key(soup, grouped.corner_face[scratch_[t].side], key_);
        key_flat_.insert(key_flat_.end(), key_.begin(), key_.end());
      }
      key_begin_.push_back(key_flat_.size());
      run_.resize(j - i);
      for (std::size_t t = 0; t < j - i; ++t)
        run_[t] = t;
      const Angled* base = scratch_.data() + i;
      bool one_key = true;  // copies of one face only: the keys need not be compared
      for (std::size_t t = 1; t < j - i && one_key; ++t) {
        one_key = std::equal(key_flat_.data() + key_begin_[t], key_flat_.data() + key_begin_[t + 1],
                             key_flat_.data(), key_flat_.data() + key_begin_[1]);
      }
      if (one_key) {
        std::sort(scratch_.begin() + i, scratch_.begin() + j, [](const Angled& a, const Angled& b) {
          if (a.along != b.along)
            return a.along;
          return a.along ? a.side < b.side : a.side > b.side;
        });
        i = j;
        continue;
      }
      std::sort(run_.begin(), run_.end(), [&](std::size_t x, std::size_t y) {
        const Angled& a = base[x];
        const Angled& b = base[y];
        if (a.along != b.along)
          return a.along;
        const Index* kx = key_flat_.data() + key_begin_[x];
        const Index* ky = key_flat_.data() + key_begin_[y];
        const Index* kx_end = key_flat_.data() + key_begin_[x + 1];
        const Index* ky_end = key_flat_.data() + key_begin_[y + 1];
        if (!std::equal(kx, kx_end, ky, ky_end))
          return std::lexicographical_compare(kx, kx_end, ky, ky_end);
        return a.along ? a.side < b.side : a.side > b.side;
      });
      sorted_run_.clear();
      for (std::size_t t : run_)
        sorted_run_.push_back(base[t]);
      std::copy(sorted_run_.begin(), sorted_run_.end(), scratch_.begin() + i);
    }
    i = j;
  }
  order.reserve(k);
  for (const Angled& a : scratch_)
    order.push_back({a.side, a.along});
  return true;
}

void face_key(const Soup& soup, Index f, std::vector<Index>& key) {
  const PolygonView p = soup.polygon(f);
  const std::size_t k = p.size();
  key.assign(p.begin(), p.end());
  std::sort(key.begin(), key.end());
  const std::size_t start =
      static_cast<std::size_t>(std::min_element(p.begin(), p.end()) - p.begin());
  for (std::size_t i = 0; i < k; ++i)
    key.push_back(p[(start + i) % k]);
}

void sort_by_face_key(const Soup& soup, const CornerFaces& corner_face, std::vector<Index>& sides) {
  std::vector<std::pair<std::vector<Index>, Index>> keyed;
  keyed.reserve(sides.size());
  for (Index side : sides) {
    keyed.emplace_back(std::vector<Index>(), side);
    face_key(soup, corner_face[side], keyed.back().first);
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t i = 0; i < sides.size(); ++i)
    sides[i] = keyed[i].second;
}

void sort_by_angle(const Soup& soup, const GroupedSides& grouped, std::size_t e,
                   std::vector<Index>& sides) {
  AngularSorter sorter;
  std::vector<OrderedSide> order;
  std::vector<Index> undirected;
  sorter.sort(soup, grouped, e, sides.data(), sides.data() + sides.size(), order, undirected);
  sides.clear();
  for (const OrderedSide& o : order)
    sides.push_back(o.side);
  sides.insert(sides.end(), undirected.begin(), undirected.end());
}

}  // namespace meshbridge::detail
