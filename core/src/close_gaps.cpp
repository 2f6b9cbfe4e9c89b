// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/close_gaps.h"

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

// A static hash grid over a set of points: points sorted by cell key, looked up by binary search.
// Different cells may share a key; callers check distances exactly, so that only adds candidates.
class PointGrid {
 public:
  PointGrid(const std::vector<Point>& positions, std::vector<Index> points, double cell)
      : positions_(positions), cell_(cell) {
    entries_.reserve(points.size());
    for (Index v : points)
      entries_.push_back({key_of(positions[v]), v});
    std::sort(entries_.begin(), entries_.end());
  }

  double cell() const { return cell_; }

  // Calls visit(v) for every point in the cells that the box [p - r, p + r] touches.
  template <class Visit>
  void for_each_near(const Point& p, double r, Visit&& visit) const {
    std::int64_t lo[3], hi[3];
    for (int a = 0; a < 3; ++a) {
      lo[a] = cell_coordinate(p[a] - r, cell_);
      hi[a] = cell_coordinate(p[a] + r, cell_);
    }
    for (std::int64_t x = lo[0]; x <= hi[0]; ++x)
      for (std::int64_t y = lo[1]; y <= hi[1]; ++y)
        for (std::int64_t z = lo[2]; z <= hi[2]; ++z)
          visit_cell(cell_key(x, y, z), visit);
  }

 private:
  std::uint64_t key_of(const Point& p) const {
    return cell_key(cell_coordinate(p[0], cell_), cell_coordinate(p[1], cell_),
                    cell_coordinate(p[2], cell_));
  }
  template <class Visit>
  void visit_cell(std::uint64_t key, Visit& visit) const {
    auto it =
        std::lower_bound(entries_.begin(), entries_.end(), std::pair<std::uint64_t, Index>(key, 0));
    for (; it != entries_.end() && it->first == key; ++it)
      visit(it->second);
  }

  const std::vector<Point>& positions_;
  double cell_;
  std::vector<std::pair<std::uint64_t, Index>> entries_;
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

Weld weld_vertices(const Soup& soup, double tolerance) {
  Weld weld;
  const std::size_t n = soup.num_vertices();
  weld.survivor.resize(n);
  for (std::size_t v = 0; v < n; ++v)
    weld.survivor[v] = static_cast<Index>(v);
  std::vector<Index> all(n);
  for (std::size_t v = 0; v < n; ++v)
    all[v] = static_cast<Index>(v);
  // Large cells: a tolerance box rarely straddles a cell face, and cells still hold about one
  // vertex because the tolerance is far below the spacing of distinct vertices.
  const PointGrid grid(soup.positions, std::move(all), 64 * tolerance);
  std::unique_ptr<VertexFaces> around;
  std::vector<std::pair<double, Index>> candidates;
  const double tolerance2 = tolerance * tolerance;
  for (std::size_t v = 0; v < n; ++v) {
    const Point& p = soup.positions[v];
    candidates.clear();
    grid.for_each_near(p, tolerance, [&](Index u) {
      if (u >= v || weld.survivor[u] != u)
        return;
      const double d2 = (soup.positions[u] - p).sqrnorm();
      if (d2 <= tolerance2)
        candidates.push_back({d2, u});
    });
    if (candidates.empty())
      continue;
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
    if (!merged)
      ++weld.refused;
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

// Boundary vertices lying on boundary sides (within the tolerance, away from both ends).
std::vector<Insertion> find_t_junctions(const Soup& soup, double tolerance) {
  const std::vector<Index> sides = boundary_sides(soup);
  if (sides.empty())
    return {};
  const auto face_of_corner = [&soup](Index c) {
    return static_cast<Index>(std::upper_bound(soup.face_begin.begin(), soup.face_begin.end(), c) -
                              soup.face_begin.begin() - 1);
  };
  std::vector<Index> vertices;
  std::vector<double> lengths;
  for (Index c : sides) {
    const Index f = face_of_corner(c);
    const Index a = soup.corner_vertices[c];
    const Index b = soup.corner_vertices[soup.next_corner(c, f)];
    vertices.push_back(a);
    vertices.push_back(b);
    lengths.push_back((soup.positions[b] - soup.positions[a]).norm());
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  std::nth_element(lengths.begin(), lengths.begin() + lengths.size() / 2, lengths.end());
  const double cell = std::max(4 * tolerance, lengths[lengths.size() / 2]);
  const PointGrid grid(soup.positions, vertices, cell);

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
    // Samples every half cell along the side; with the tolerance at most a quarter cell, every
    // point within the tolerance of the side is in a cell next to a sample's cell.
    const std::size_t steps =
        static_cast<std::size_t>(std::ceil(std::sqrt(length2) / (0.5 * cell)));
    seen.clear();
    for (std::size_t k = 0; k <= steps; ++k) {
      const Point sample = pa + ab * (static_cast<double>(k) / static_cast<double>(steps));
      grid.for_each_near(sample, cell, [&](Index w) {
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
  double largest = 0;
  for (const Point& p : soup.positions)
    for (int a = 0; a < 3; ++a)
      largest = std::max(largest, std::abs(p[a]));
  return std::ldexp(largest, -21);
}

namespace detail {

bool close_gaps_if_any(const Soup& soup, const CloseGapsOptions& options, ClosedGaps& result) {
  if (std::isnan(options.tolerance) || options.tolerance == std::numeric_limits<double>::infinity())
    throw std::invalid_argument("close_gaps: the tolerance must be a finite number");
  result = ClosedGaps();
  CloseGapsReport& report = result.report;
  const double tolerance = options.tolerance < 0 ? default_weld_tolerance(soup) : options.tolerance;
  report.tolerance = tolerance;
  if (!(tolerance > 0) || soup.num_vertices() == 0)
    return false;

  const Weld weld = weld_vertices(soup, tolerance);
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
  const std::vector<Insertion> insertions =
      options.close_t_junctions ? find_t_junctions(base, tolerance) : std::vector<Insertion>();
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

}  // namespace meshbridge
