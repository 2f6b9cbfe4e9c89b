// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/close_gaps.h"

#include "close_gaps_detail.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

namespace meshbridge {

namespace {

// Integer cell coordinates of x at cell size `cell`, clamped so the cast is defined.
std::int64_t cell_coordinate(double x, double cell) {
  const double c = std::floor(x / cell);
  constexpr double limit = 4.0e18;
  return static_cast<std::int64_t>(std::max(-limit, std::min(limit, c)));
}

std::uint64_t mix(std::uint64_t x) {  // splitmix64 finaliser
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ULL;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebULL;
  x ^= x >> 31;
  return x;
}

std::uint64_t cell_key(std::int64_t x, std::int64_t y, std::int64_t z) {
  return mix(static_cast<std::uint64_t>(x) ^
             mix(static_cast<std::uint64_t>(y) ^ mix(static_cast<std::uint64_t>(z))));
}

// A static kd-tree over a set of points (leaves of up to 8), for "points near a segment"
// queries whose cost follows the number of boxes the segment passes near, not the side lengths.
class PointTree {
 public:
  PointTree(const std::vector<Point>& positions, std::vector<Index> points)
      : positions_(positions), points_(std::move(points)) {
    if (!points_.empty()) {
      nodes_.reserve(points_.size() / 2 + 1);
      nodes_.resize(1);
      build(0, 0, points_.size());
    }
  }

  // Calls visit(v) for every point whose node box, grown by r, the segment a-b meets (a superset
  // of the points within r of the segment; callers check distances exactly).
  template <class Visit>
  void for_each_near_segment(const Point& a, const Point& b, double r, Visit&& visit) const {
    if (nodes_.empty())
      return;
    std::vector<std::size_t> stack{0};
    while (!stack.empty()) {
      const Node& node = nodes_[stack.back()];
      stack.pop_back();
      if (!segment_meets_box(a, b, node.lo - Point(r, r, r), node.hi + Point(r, r, r)))
        continue;
      if (node.left == 0) {
        for (std::size_t i = node.first; i < node.last; ++i)
          visit(points_[i]);
      } else {
        stack.push_back(node.left);
        stack.push_back(node.left + 1);
      }
    }
  }

 private:
  struct Node {
    Point lo, hi;
    std::size_t first = 0, last = 0;
    std::size_t left = 0;  // children left and left + 1; 0 for a leaf
  };

  // Fills node `slot` (already allocated) for points_[first, last) and its subtree.
  void build(std::size_t slot, std::size_t first, std::size_t last) {
    Point lo = positions_[points_[first]], hi = lo;
    for (std::size_t i = first; i < last; ++i) {
      lo.minimize(positions_[points_[i]]);
      hi.maximize(positions_[points_[i]]);
    }
    nodes_[slot].lo = lo;
    nodes_[slot].hi = hi;
    nodes_[slot].first = first;
    nodes_[slot].last = last;
    if (last - first <= 8)
      return;
    const Point extent = hi - lo;
    const int axis = extent[0] >= extent[1] && extent[0] >= extent[2] ? 0
                     : extent[1] >= extent[2]                         ? 1
                                                                      : 2;
    const std::size_t middle = first + (last - first) / 2;
    std::nth_element(points_.begin() + first, points_.begin() + middle, points_.begin() + last,
                     [&](Index x, Index y) { return positions_[x][axis] < positions_[y][axis]; });
    const std::size_t children = nodes_.size();
    nodes_.resize(children + 2);
    nodes_[slot].left = children;
    build(children, first, middle);
    build(children + 1, middle, last);
  }

  // Slab test: does the segment a-b meet the box [lo, hi]?
  static bool segment_meets_box(const Point& a, const Point& b, const Point& lo, const Point& hi) {
    double t0 = 0, t1 = 1;
    for (int axis = 0; axis < 3; ++axis) {
      const double d = b[axis] - a[axis];
      if (d == 0) {
        if (a[axis] < lo[axis] || a[axis] > hi[axis])
          return false;
        continue;
      }
      double u0 = (lo[axis] - a[axis]) / d, u1 = (hi[axis] - a[axis]) / d;
      if (u0 > u1)
        std::swap(u0, u1);
      t0 = std::max(t0, u0);
      t1 = std::min(t1, u1);
      if (t0 > t1)
        return false;
    }
    return true;
  }

  const std::vector<Point>& positions_;
  std::vector<Index> points_;
  std::vector<Node> nodes_;
};

// A growing hash grid of points (open addressing over cell keys, one chain of points per cell):
// welding inserts only surviving vertices, so many copies of one position cost one entry.
class SurvivorGrid {
 public:
  // Room for `points` points, numbered below `vertices`.
  SurvivorGrid(std::size_t points, std::size_t vertices, double cell)
      : cell_(cell), next_(vertices, kNoIndex) {
    std::size_t capacity = 16;
    while (capacity < 2 * points)
      capacity *= 2;
    keys_.assign(capacity, 0);
    heads_.assign(capacity, kNoIndex);
  }

  void insert(const Point& p, Index v) {
    const std::size_t slot = find_slot(key_of(p));
    keys_[slot] = key_of(p) | 1;
    next_[v] = heads_[slot];
    heads_[slot] = v;
  }

  template <class Visit>
  void for_each_near(const Point& p, double r, Visit&& visit) const {
    std::int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = cell_coordinate(p[a] - r, cell_);
      hi[a] = cell_coordinate(p[a] + r, cell_);
    }
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z) {
          const std::size_t slot = find_slot(cell_key(x, y, z));
          if (keys_[slot] == 0)
            continue;  // empty cell
          for (Index v = heads_[slot]; v != kNoIndex; v = next_[v])
            visit(v);
        }
  }

 private:
  std::uint64_t key_of(const Point& p) const {
    return cell_key(cell_coordinate(p[0], cell_), cell_coordinate(p[1], cell_),
                    cell_coordinate(p[2], cell_));
  }
  // The slot holding `key`, or the empty slot where it would go (key 0 marks empty slots; keys
  // are made odd, and cells that share a key share a chain, which distance checks sort out).
  std::size_t find_slot(std::uint64_t key) const {
    key |= 1;
    const std::size_t mask = keys_.size() - 1;
    std::size_t slot = key & mask;
    while (keys_[slot] != 0 && keys_[slot] != key)
      slot = (slot + 1) & mask;
    return slot;
  }

  double cell_;
  std::vector<std::uint64_t> keys_;
  std::vector<Index> heads_;
  std::vector<Index> next_;
};

// Polygons around each vertex (CSR).
struct VertexFaces {
  std::vector<Index> begin;
  std::vector<Index> faces;
  explicit VertexFaces(const Soup& soup) : begin(soup.num_vertices() + 1, 0) {
    for (Index v : soup.corner_vertices)
      ++begin[v + 1];
    for (std::size_t v = 0; v < soup.num_vertices(); ++v)
      begin[v + 1] += begin[v];
    faces.resize(soup.num_corners());
    std::vector<Index> next(begin.begin(), begin.end() - 1);
    for (Index f = 0; f < soup.num_faces(); ++f)
      for (Index v : soup.polygon(f))
        faces[next[v]++] = f;
  }
};

struct Weld {
  std::vector<Index> survivor;  // #V: the vertex each vertex welds into (itself if it survives)
  std::size_t welded = 0;
  std::size_t refused = 0;
  double largest = 0;
};

std::vector<Index> boundary_sides(const Soup& soup);

// Endpoints of boundary sides, sorted.
std::vector<Index> boundary_vertices(const Soup& soup, const std::vector<Index>& sides) {
  std::vector<Index> vertices;
  for (Index c : sides) {
    const Index f =
        static_cast<Index>(std::upper_bound(soup.face_begin.begin(), soup.face_begin.end(), c) -
                           soup.face_begin.begin() - 1);
    vertices.push_back(soup.corner_vertices[c]);
    vertices.push_back(soup.corner_vertices[soup.next_corner(c, f)]);
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  return vertices;
}

// Welds boundary vertices only: a crack is where sides are open, and an edge that already has
// two sides needs nothing (a closed mesh with near vertices stays exactly as it is).
Weld weld_vertices(const Soup& soup, double tolerance, const std::vector<Index>& boundary) {
  Weld weld;
  const std::size_t n = soup.num_vertices();
  weld.survivor.resize(n);
  for (std::size_t v = 0; v < n; ++v)
    weld.survivor[v] = static_cast<Index>(v);
  const std::vector<Index> open = boundary_vertices(soup, boundary);
  if (open.empty())
    return weld;
  // Large cells: a tolerance box rarely straddles a cell face, and cells still hold about one
  // vertex because the tolerance is far below the spacing of distinct vertices.
  SurvivorGrid grid(open.size(), n, 64 * tolerance);
  std::unique_ptr<VertexFaces> around;
  std::vector<std::pair<double, Index>> candidates;
  const double tolerance2 = tolerance * tolerance;
  for (const Index v : open) {
    const Point& p = soup.positions[v];
    candidates.clear();
    grid.for_each_near(p, tolerance, [&](Index u) {
      const double d2 = (soup.positions[u] - p).sqrnorm();
      // Beyond 1e154 the square overflows (and past 1.3e154 the tolerance's does too): an
      // infinite d2 is never a weld, so no move is larger than the tolerance it claims.
      if (d2 > 0 && d2 <= tolerance2 && std::isfinite(d2))
        candidates.push_back({d2, u});
    });
    if (candidates.empty()) {
      grid.insert(p, static_cast<Index>(v));
      continue;
    }
    if (!around)
      around = std::make_unique<VertexFaces>(soup);
    std::sort(candidates.begin(), candidates.end());
    bool merged = false;
    for (const auto& [d2, r] : candidates) {
      // Refuse r if a polygon of v already holds r or a vertex welded into r.
      bool shares = false;
      for (Index i = around->begin[v]; i < around->begin[v + 1] && !shares; ++i) {
        for (Index u : soup.polygon(around->faces[i])) {
          if (u != v && weld.survivor[u] == r) {
            shares = true;
            break;
          }
        }
      }
      if (shares)
        continue;
      weld.survivor[v] = r;
      ++weld.welded;
      weld.largest = std::max(weld.largest, std::sqrt(d2));
      merged = true;
      break;
    }
    if (!merged) {
      ++weld.refused;
      grid.insert(p, static_cast<Index>(v));
    }
  }
  return weld;
}

// Boundary sides (edges with exactly one side) of `soup`, as corners. Vertices whose edges all
// have an even number of sides (every vertex of a closed or evenly singular mesh) are ruled out
// first by an XOR of edge hashes, so closed input costs one pass over the corners.
std::vector<Index> boundary_sides(const Soup& soup) {
  std::vector<std::uint64_t> parity(soup.num_vertices(), 0);
  for (Index f = 0; f < soup.num_faces(); ++f) {
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      const Index a = soup.corner_vertices[c];
      const Index b = soup.corner_vertices[soup.next_corner(c, f)];
      const std::uint64_t h =
          mix((static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b));
      parity[a] ^= h;
      parity[b] ^= h;
    }
  }
  std::vector<std::pair<std::uint64_t, Index>> sides;  // (vertex pair, corner)
  for (Index f = 0; f < soup.num_faces(); ++f) {
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      const Index a = soup.corner_vertices[c];
      const Index b = soup.corner_vertices[soup.next_corner(c, f)];
      if (parity[a] != 0 && parity[b] != 0 && a != b)
        sides.push_back({(static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b), c});
    }
  }
  std::sort(sides.begin(), sides.end());
  std::vector<Index> boundary;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    while (j < sides.size() && sides[j].first == sides[i].first)
      ++j;
    if (j - i == 1)
      boundary.push_back(sides[i].second);
    i = j;
  }
  std::sort(boundary.begin(), boundary.end());
  return boundary;
}

struct Insertion {
  Index corner;  // the split side starts at this corner
  double t;      // position along the side, in (0, 1)
  Index vertex;
};

// Boundary vertices lying on boundary `sides` (within the tolerance, away from both ends).
std::vector<Insertion> find_t_junctions(const Soup& soup, double tolerance,
                                        const std::vector<Index>& sides) {
  if (sides.empty())
    return {};
  const auto face_of_corner = [&soup](Index c) {
    return static_cast<Index>(std::upper_bound(soup.face_begin.begin(), soup.face_begin.end(), c) -
                              soup.face_begin.begin() - 1);
  };
  const PointTree tree(soup.positions, boundary_vertices(soup, sides));

  std::vector<Insertion> insertions;
  std::vector<Index> seen;
  for (Index c : sides) {
    const Index f = face_of_corner(c);
    const Index a = soup.corner_vertices[c];
    const Index b = soup.corner_vertices[soup.next_corner(c, f)];
    const Point pa = soup.positions[a];
    const Point ab = soup.positions[b] - pa;
    const double length2 = ab.sqrnorm();
    if (!(length2 > 4 * tolerance * tolerance))
      continue;
    seen.clear();
    tree.for_each_near_segment(pa, soup.positions[b], tolerance, [&](Index w) {
      if (w == a || w == b)
        return;
      const Point aw = soup.positions[w] - pa;
      const double t = (aw | ab) / length2;
      if (!(t > 0 && t < 1))
        return;
      if ((aw - ab * t).sqrnorm() > tolerance * tolerance)
        return;
      // Within the tolerance of an end, the gap is a weld's business, not a T-junction's.
      if (aw.sqrnorm() <= tolerance * tolerance ||
          (soup.positions[w] - soup.positions[b]).sqrnorm() <= tolerance * tolerance)
        return;
      if (std::find(seen.begin(), seen.end(), w) != seen.end())
        return;
      seen.push_back(w);
      for (Index u : soup.polygon(f))
        if (u == w)
          return;  // would repeat a corner of the polygon
      insertions.push_back({c, t, w});
    });
  }
  std::sort(insertions.begin(), insertions.end(), [](const Insertion& x, const Insertion& y) {
    return x.corner != y.corner ? x.corner < y.corner : x.t < y.t;
  });
  // One vertex goes into a polygon once, at its first side.
  std::vector<Insertion> kept;
  for (std::size_t i = 0; i < insertions.size(); ++i) {
    const Index f = face_of_corner(insertions[i].corner);
    bool duplicate = false;
    for (std::size_t j = kept.size(); j-- > 0 && face_of_corner(kept[j].corner) == f;)
      duplicate = duplicate || kept[j].vertex == insertions[i].vertex;
    if (!duplicate)
      kept.push_back(insertions[i]);
  }
  return kept;
}

}  // namespace

double default_weld_tolerance(const Soup& soup) {
  // Vertices that no face uses take no part in welding: a stray one far away (an OBJ `v` line
  // nothing refers to) must not widen the tolerance for the rest.
  std::vector<char> used(soup.num_vertices(), 0);
  for (const Index v : soup.corner_vertices) {
    if (v < used.size())
      used[v] = 1;
  }
  double largest = 0;
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    if (!used[v])
      continue;
    for (int a = 0; a < 3; ++a)
      largest = std::max(largest, std::abs(soup.positions[v][a]));
  }
  return std::ldexp(largest, -21);
}

namespace detail {

bool close_gaps_if_any(const Soup& soup, const CloseGapsOptions& options, ClosedGaps& result,
                       const std::vector<Index>* known_boundary) {
  if (std::isnan(options.tolerance) || options.tolerance == std::numeric_limits<double>::infinity())
    throw std::invalid_argument("close_gaps: the tolerance must be a finite number");
  result = ClosedGaps();
  CloseGapsReport& report = result.report;
  const double tolerance = options.tolerance < 0 ? default_weld_tolerance(soup) : options.tolerance;
  report.tolerance = tolerance;
  if (!(tolerance > 0) || soup.num_vertices() == 0)
    return false;
  const std::vector<Index> found = known_boundary ? std::vector<Index>() : boundary_sides(soup);
  const std::vector<Index>& boundary = known_boundary ? *known_boundary : found;
  if (boundary.empty())  // only boundary sides and their vertices take part
    return false;

  const Weld weld = weld_vertices(soup, tolerance, boundary);
  report.vertices_welded = weld.welded;
  report.welds_refused = weld.refused;
  report.largest_weld_distance = weld.largest;
  Soup welded;
  if (weld.welded != 0) {
    // Survivors keep their order.
    std::vector<Index> new_index(soup.num_vertices(), kNoIndex);
    welded.reserve(soup.num_vertices() - weld.welded, soup.num_faces(), soup.num_corners());
    for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
      if (weld.survivor[v] != v)
        continue;
      new_index[v] = welded.add_vertex(soup.positions[v]);
      result.vertex_origin.push_back(static_cast<Index>(v));
    }
    welded.corner_vertices.resize(soup.num_corners());
    for (std::size_t c = 0; c < soup.num_corners(); ++c)
      welded.corner_vertices[c] = new_index[weld.survivor[soup.corner_vertices[c]]];
    welded.face_begin = soup.face_begin;
  }
  const Soup& base = weld.welded != 0 ? welded : soup;
  std::vector<Insertion> insertions;
  if (options.close_t_junctions)
    insertions =
        find_t_junctions(base, tolerance, weld.welded != 0 ? boundary_sides(base) : boundary);
  report.t_junctions_closed = insertions.size();
  if (!report.changed())
    return false;
  if (weld.welded == 0) {
    result.vertex_origin.resize(soup.num_vertices());
    for (std::size_t v = 0; v < soup.num_vertices(); ++v)
      result.vertex_origin[v] = static_cast<Index>(v);
  }

  Soup& out = result.soup;
  out.positions = weld.welded != 0 ? std::move(welded.positions) : soup.positions;
  out.reserve(0, base.num_faces(), base.num_corners() + insertions.size());
  result.corner_origin.reserve(base.num_corners() + insertions.size());
  std::size_t next = 0;
  for (Index f = 0; f < base.num_faces(); ++f) {
    for (Index c = base.face_begin[f]; c < base.face_begin[f + 1]; ++c) {
      out.corner_vertices.push_back(base.corner_vertices[c]);
      result.corner_origin.push_back(c);
      bool first = true;
      for (; next < insertions.size() && insertions[next].corner == c; ++next) {
        out.corner_vertices.push_back(insertions[next].vertex);
        result.corner_origin.push_back(c);
        report.sides_split += first ? 1 : 0;
        first = false;
      }
    }
    out.face_begin.push_back(static_cast<Index>(out.corner_vertices.size()));
  }
  return true;
}

}  // namespace detail

ClosedGaps close_gaps(const Soup& soup, const CloseGapsOptions& options) {
  ClosedGaps result;
  if (!detail::close_gaps_if_any(soup, options, result)) {
    // Unchanged: the soup itself, with identity origins.
    result.soup = soup;
    result.vertex_origin.resize(soup.num_vertices());
    for (std::size_t v = 0; v < soup.num_vertices(); ++v)
      result.vertex_origin[v] = static_cast<Index>(v);
    result.corner_origin.resize(soup.num_corners());
    for (std::size_t c = 0; c < soup.num_corners(); ++c)
      result.corner_origin[c] = static_cast<Index>(c);
  }
  return result;
}

CloseGapsReport preview_close_gaps(const Soup& soup, const CloseGapsOptions& options,
                                   const DefectReport* detected) {
  ClosedGaps result;
  // No degenerate polygon: detection grouped the soup's own sides, so its boundary edges are the
  // boundary sides gap closing would look for.
  const std::vector<Index> none;
  const bool closed =
      detected != nullptr && detected->degenerate_faces.empty() && detected->boundary_edges.empty();
  detail::close_gaps_if_any(soup, options, result, closed ? &none : nullptr);
  return result.report;
}

}  // namespace meshbridge
