// SPDX-License-Identifier: GPL-3.0-or-later
#include "meshbridge/close_gaps.h"

#include "close_gaps_detail.h"
#include "geometry/point_tree.h"
#include "hash_mix.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

namespace meshbridge {

namespace {

using detail::mix;
using detail::PointTree;

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
  std::size_t refused = 0;   // near pairs sharing a polygon
  std::size_t too_long = 0;  // near pairs farther apart than a quarter of an edge at either
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

// Each vertex's own tolerance and the shortest edge at it (DESIGN 8a, gaps). Automatic: 2^-21
// times the extent of the vertex's connected component (the largest side of its bounding box:
// CAD rounding is relative to the part, not to where it sits), and at least 2^-21 times its own
// largest coordinate when the coordinates were stored as 32-bit floats (8 units in the last
// place: what the format itself rounds); never the file's largest coordinate, so a far stray
// facet or a model far from the origin widens nothing. A weld or a T-junction closing moves a
// vertex by at most a quarter of the shortest non-zero edge at it, so no feature collapses.
class VertexScales {
 public:
  VertexScales(const Soup& soup, const CloseGapsOptions& options, double fixed)
      : tolerance_(soup.num_vertices(), fixed),
        shortest_(soup.num_vertices(), std::numeric_limits<double>::infinity()) {
    const std::size_t n = soup.num_vertices();
    for (Index f = 0; f < soup.num_faces(); ++f) {
      for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
        const Index a = soup.corner_vertices[c], b = soup.corner_vertices[soup.next_corner(c, f)];
        const double length = (soup.positions[a] - soup.positions[b]).norm();
        if (length > 0) {
          shortest_[a] = std::min(shortest_[a], length);
          shortest_[b] = std::min(shortest_[b], length);
        }
      }
    }
    if (fixed >= 0)
      return;
    // Components through shared vertices (union-find, path halving), then their boxes.
    std::vector<Index> parent(n);
    for (std::size_t v = 0; v < n; ++v)
      parent[v] = static_cast<Index>(v);
    const auto root = [&parent](Index v) {
      while (parent[v] != v)
        v = parent[v] = parent[parent[v]];
      return v;
    };
    for (Index f = 0; f < soup.num_faces(); ++f) {
      const Index first = root(soup.corner_vertices[soup.face_begin[f]]);
      for (Index c = soup.face_begin[f] + 1; c < soup.face_begin[f + 1]; ++c) {
        const Index r = root(soup.corner_vertices[c]);
        if (r != first)
          parent[r] = first;
      }
    }
    const double inf = std::numeric_limits<double>::infinity();
    std::vector<Point> lo(n, Point(inf, inf, inf)), hi(n, Point(-inf, -inf, -inf));
    for (std::size_t v = 0; v < n; ++v) {
      const Index r = root(static_cast<Index>(v));
      lo[r].minimize(soup.positions[v]);
      hi[r].maximize(soup.positions[v]);
    }
    for (std::size_t v = 0; v < n; ++v) {
      const Index r = root(static_cast<Index>(v));
      const Point extent = hi[r] - lo[r];
      double scale = std::max({extent[0], extent[1], extent[2]});
      if (options.float_coordinates) {
        for (int a = 0; a < 3; ++a)
          scale = std::max(scale, std::abs(soup.positions[v][a]));
      }
      tolerance_[v] = std::isfinite(scale) ? std::ldexp(scale, -21) : 0.0;
    }
  }

  // The distance two vertices may be welded across, or a vertex moved onto a side: the smaller
  // of their tolerances.
  double tolerance(Index v, Index u) const { return std::min(tolerance_[v], tolerance_[u]); }
  double tolerance(Index v) const { return tolerance_[v]; }
  // A quarter of the shortest non-zero edge at v (infinite if none).
  double longest_move(Index v) const { return shortest_[v] / 4; }

 private:
  std::vector<double> tolerance_;
  std::vector<double> shortest_;
};

// Welds boundary vertices only: a crack is where sides are open, and an edge that already has
// two sides needs nothing (a closed mesh with near vertices stays exactly as it is).
Weld weld_vertices(const Soup& soup, const VertexScales& scales,
                   const std::vector<Index>& boundary) {
  Weld weld;
  const std::size_t n = soup.num_vertices();
  weld.survivor.resize(n);
  for (std::size_t v = 0; v < n; ++v)
    weld.survivor[v] = static_cast<Index>(v);
  const std::vector<Index> open = boundary_vertices(soup, boundary);
  if (open.empty())
    return weld;
  // Every boundary vertex in a kd-tree; a vertex welds into an earlier one (by index) that
  // survives, so the result follows the index order alone.
  const PointTree tree(soup.positions, open);
  std::unique_ptr<VertexFaces> around;
  std::vector<std::pair<double, Index>> candidates;
  for (const Index v : open) {
    const Point& p = soup.positions[v];
    const double radius = scales.tolerance(v);
    if (!(radius > 0))
      continue;
    candidates.clear();
    tree.for_each_near_segment(p, p, radius, [&](Index u) {
      if (u >= v || weld.survivor[u] != u)
        return;
      const double d2 = (soup.positions[u] - p).sqrnorm();
      const double t = scales.tolerance(v, u);
      // Beyond 1e154 the square overflows (and past 1.3e154 the tolerance's does too): an
      // infinite d2 is never a weld, so no move is larger than the tolerance it claims.
      if (d2 > 0 && d2 <= t * t && std::isfinite(d2))
        candidates.push_back({d2, u});
    });
    if (candidates.empty())
      continue;
    if (!around)
      around = std::make_unique<VertexFaces>(soup);
    std::sort(candidates.begin(), candidates.end());
    bool merged = false, too_long = false;
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
      const double d = std::sqrt(d2);
      if (d > scales.longest_move(v) || d > scales.longest_move(r)) {
        too_long = true;  // would collapse a feature: an edge at v or r is not much longer
        continue;
      }
      weld.survivor[v] = r;
      ++weld.welded;
      weld.largest = std::max(weld.largest, d);
      merged = true;
      break;
    }
    if (!merged)
      ++(too_long ? weld.too_long : weld.refused);
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

// Boundary vertices lying on boundary `sides` (within the tolerance, away from both ends, and
// no farther from the side than a quarter of the side or of the shortest edge at the vertex).
// `refused` counts the vertices within the tolerance that the last rule kept off a side.
std::vector<Insertion> find_t_junctions(const Soup& soup, const VertexScales& scales,
                                        const std::vector<Index>& sides, std::size_t& refused) {
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
    const double side_tolerance = scales.tolerance(a, b);
    if (!(side_tolerance > 0) || !(length2 > 4 * side_tolerance * side_tolerance))
      continue;
    seen.clear();
    tree.for_each_near_segment(pa, soup.positions[b], side_tolerance, [&](Index w) {
      if (w == a || w == b)
        return;
      const double tolerance = std::min(side_tolerance, scales.tolerance(w));
      const double tolerance2 = tolerance * tolerance;
      const Point aw = soup.positions[w] - pa;
      const double t = (aw | ab) / length2;
      if (!(t > 0 && t < 1))
        return;
      const double gap2 = (aw - ab * t).sqrnorm();
      if (gap2 > tolerance2)
        return;
      // Within the tolerance of an end, the gap is a weld's business, not a T-junction's.
      if (aw.sqrnorm() <= tolerance2 ||
          (soup.positions[w] - soup.positions[b]).sqrnorm() <= tolerance2)
        return;
      if (std::find(seen.begin(), seen.end(), w) != seen.end())
        return;
      seen.push_back(w);
      for (Index u : soup.polygon(f))
        if (u == w)
          return;  // would repeat a corner of the polygon
      const double longest = std::min(scales.longest_move(w), std::sqrt(length2) / 4);
      if (std::sqrt(gap2) > longest) {
        ++refused;  // the gap is a feature of the model's own size, not a crack
        return;
      }
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

double default_weld_tolerance(const Soup& soup, bool float_coordinates) {
  // Vertices that no face uses take no part in welding.
  std::vector<char> used(soup.num_vertices(), 0);
  for (const Index v : soup.corner_vertices) {
    if (v < used.size())
      used[v] = 1;
  }
  CloseGapsOptions options;
  options.float_coordinates = float_coordinates;
  const VertexScales scales(soup, options, -1);
  double largest = 0;
  for (std::size_t v = 0; v < soup.num_vertices(); ++v) {
    if (used[v])
      largest = std::max(largest, scales.tolerance(static_cast<Index>(v)));
  }
  return largest;
}

namespace detail {

bool close_gaps_if_any(const Soup& soup, const CloseGapsOptions& options, ClosedGaps& result,
                       const std::vector<Index>* known_boundary) {
  if (std::isnan(options.tolerance) || options.tolerance == std::numeric_limits<double>::infinity())
    throw std::invalid_argument("close_gaps: the tolerance must be a finite number");
  result = ClosedGaps();
  CloseGapsReport& report = result.report;
  const double fixed = options.tolerance < 0 ? -1.0 : options.tolerance;
  report.automatic = fixed < 0;
  report.tolerance = std::max(fixed, 0.0);
  if (fixed == 0 || soup.num_vertices() == 0)
    return false;
  const std::vector<Index> found = known_boundary ? std::vector<Index>() : boundary_sides(soup);
  const std::vector<Index>& boundary = known_boundary ? *known_boundary : found;
  if (boundary.empty())  // only boundary sides and their vertices take part
    return false;
  const VertexScales scales(soup, options, fixed);
  // The tolerance reported: the given one, or the largest automatic one of a boundary vertex.
  if (fixed > 0) {
    report.tolerance = fixed;
  } else {
    for (Index v : boundary_vertices(soup, boundary))
      report.tolerance = std::max(report.tolerance, scales.tolerance(v));
  }
  if (!(report.tolerance > 0))
    return false;

  const Weld weld = weld_vertices(soup, scales, boundary);
  report.vertices_welded = weld.welded;
  report.welds_refused = weld.refused;
  report.welds_too_long = weld.too_long;
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
  if (options.close_t_junctions) {
    if (weld.welded != 0) {
      const VertexScales welded_scales(base, options, fixed);
      insertions =
          find_t_junctions(base, welded_scales, boundary_sides(base), report.t_junctions_too_wide);
    } else {
      insertions = find_t_junctions(base, scales, boundary, report.t_junctions_too_wide);
    }
  }
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
  // No degenerate or keyhole polygon: detection grouped the soup's own sides, so its boundary
  // edges are the boundary sides gap closing would look for.
  const std::vector<Index> none;
  const bool closed = detected != nullptr && detected->degenerate_faces.empty() &&
                      detected->keyhole_polygons_triangulated == 0 &&
                      detected->boundary_edges.empty();
  detail::close_gaps_if_any(soup, options, result, closed ? &none : nullptr);
  return result.report;
}

}  // namespace meshbridge
