// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/triangulate.h"

#include "meshbridge/polygon_triangles.h"

#include "geometry/newell_normal.h"
#include "working_soup.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace meshbridge::detail {

namespace {

//! Twice the signed area of (a, b, c) in the plane: > 0 when counter-clockwise.
double cross(double au, double av, double bu, double bv, double cu, double cv) {
  return (bu - au) * (cv - av) - (bv - av) * (cu - au);
}

//! Appends the triangles of the ring `p` (>= 3 corners) to `t.triangles`; with `strict`, also
//! their corners as positions in `p` to `t.positions`, and returns false (leaving the triangles
//! incomplete) instead of fanning where no ear is left or the last triangle does not turn the
//! ring's way. Returns true otherwise.
bool triangulate_ring(const Soup& soup, PolygonView p, Triangulation& t, bool strict = false) {
  const std::size_t n = p.size();
  const auto emit = [&](Index a, Index b, Index c) {
    t.triangles.push_back({p[a], p[b], p[c]});
    if (strict)
      t.positions.push_back({a, b, c});
  };
  const auto fan = [&](std::size_t first, std::size_t count) {  // the ring from `first` on
    Index a = static_cast<Index>(first), b = t.next[a];
    for (std::size_t k = 0; k + 2 < count; ++k) {
      emit(a, b, t.next[b]);
      b = t.next[b];
    }
  };
  t.previous.resize(n);
  t.next.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    t.previous[i] = static_cast<Index>((i + n - 1) % n);
    t.next[i] = static_cast<Index>((i + 1) % n);
  }
  // The plane of the two coordinates across the largest component of the Newell normal, turned
  // so that the polygon runs counter-clockwise there.
  const Point normal = newell_normal(soup, p);
  int drop = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(normal[k]) > std::abs(normal[drop]))
      drop = k;
  }
  // A fan from the first corner whose diagonals are no edges of the mesh yet (a flat polygon:
  // a sliver split at its sides' midpoints has no ear, and its fan must not double an edge).
  const auto free_fan = [&](std::size_t first, std::size_t count) {
    if (!t.taken.empty()) {
      Index apex = static_cast<Index>(first);
      for (std::size_t tried = 0; tried < count; ++tried, apex = t.next[apex]) {
        bool free = true;
        Index q = t.next[t.next[apex]];
        for (std::size_t k = 0; k + 3 < count && free; ++k, q = t.next[q])
          free = t.taken.count(edge_key(p[apex], p[q])) == 0;
        if (free) {
          first = apex;
          break;
        }
      }
      Index q = t.next[t.next[static_cast<Index>(first)]];
      for (std::size_t k = 0; k + 3 < count; ++k, q = t.next[q])
        t.taken.insert(edge_key(p[first], p[q]));
    }
    fan(first, count);
  };
  if (n == 3 || n > 4096 || !(std::abs(normal[drop]) > 0) || !std::isfinite(normal[drop])) {
    if (strict)
      return false;
    free_fan(0, n);
    return true;
  }
  int iu = (drop + 1) % 3, iv = (drop + 2) % 3;
  if (normal[drop] < 0)
    std::swap(iu, iv);
  t.u.resize(n);
  t.v.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    t.u[i] = soup.positions[p[i]][iu];
    t.v[i] = soup.positions[p[i]][iv];
  }
  // Convex, and not flat: a corner on the line of its neighbours (a vertex repair put at an
  // edge's midpoint) gives a triangle of no area, whose diagonal is that edge again; rounding
  // makes such a corner's cross product a few units in the last place of either sign.
  const auto is_convex = [&](Index a, Index b, Index c) {
    const double turn = cross(t.u[a], t.v[a], t.u[b], t.v[b], t.u[c], t.v[c]);
    const double ab = std::hypot(t.u[b] - t.u[a], t.v[b] - t.v[a]);
    const double bc = std::hypot(t.u[c] - t.u[b], t.v[c] - t.v[b]);
    return turn > 1e-12 * ab * bc;
  };
  // An ear: a convex corner whose triangle holds no other corner of the ring (on its sides
  // counts as inside, unless the corner is at one of its three points: a pinched polygon, or
  // the two ends of a keyhole's slit).
  const auto is_ear = [&](Index b) {
    const Index a = t.previous[b], c = t.next[b];
    if (!is_convex(a, b, c))
      return false;
    for (Index q = t.next[c]; q != a; q = t.next[q]) {
      const bool at_corner = (t.u[q] == t.u[a] && t.v[q] == t.v[a]) ||
                             (t.u[q] == t.u[b] && t.v[q] == t.v[b]) ||
                             (t.u[q] == t.u[c] && t.v[q] == t.v[c]);
      if (at_corner)
        continue;
      if (cross(t.u[a], t.v[a], t.u[b], t.v[b], t.u[q], t.v[q]) >= 0 &&
          cross(t.u[b], t.v[b], t.u[c], t.v[c], t.u[q], t.v[q]) >= 0 &&
          cross(t.u[c], t.v[c], t.u[a], t.v[a], t.u[q], t.v[q]) >= 0)
        return false;
    }
    return true;
  };
  // An ear whose diagonal is no edge of the mesh yet (when the mesh's edges are tracked).
  const auto is_free_ear = [&](Index b) {
    return is_ear(b) && t.taken.count(edge_key(p[t.previous[b]], p[t.next[b]])) == 0;
  };
  const auto find_ear = [&](Index start, std::size_t left, auto&& accept) {
    Index b = start;
    for (std::size_t tried = 0; tried < left; ++tried, b = t.next[b]) {
      if (accept(b))
        return b;
    }
    return kNoIndex;
  };
  // With 4 corners left and no free ear: the diagonal that is no edge yet, where neither of its
  // two triangles is turned over (one may be flat). A quad split at an edge's midpoint on both
  // sides of a sheet written twice has one ear only (the midpoint's corner is flat): taken by
  // the first side, the second side's ear would put a fourth triangle on that diagonal (a
  // singular edge; PrusaSlicer reads it as an open edge); the other diagonal gives a triangle
  // of no area instead, and every edge keeps two.
  const auto free_quad = [&](Index a) {
    const Index b = t.next[a], c = t.next[b], d = t.next[c];
    const auto not_turned = [&](Index x, Index y, Index z) {
      const double turn = cross(t.u[x], t.v[x], t.u[y], t.v[y], t.u[z], t.v[z]);
      const double xy = std::hypot(t.u[y] - t.u[x], t.v[y] - t.v[x]);
      const double yz = std::hypot(t.u[z] - t.u[y], t.v[z] - t.v[y]);
      return turn >= -1e-12 * xy * yz;
    };
    return t.taken.count(edge_key(p[a], p[c])) == 0 && not_turned(a, b, c) && not_turned(c, d, a);
  };
  Index start = 0;
  std::size_t left = n;
  while (left > 3) {
    Index b = t.taken.empty() ? kNoIndex : find_ear(start, left, is_free_ear);
    if (b == kNoIndex && left == 4 && !t.taken.empty() && !strict) {
      const Index a = find_ear(start, 2, free_quad);
      if (a != kNoIndex) {
        t.taken.insert(edge_key(p[a], p[t.next[t.next[a]]]));
        fan(a, 4);
        return true;
      }
    }
    if (b == kNoIndex)
      b = find_ear(start, left, is_ear);
    if (b == kNoIndex) {  // no ear: not a simple polygon in this plane
      if (strict)
        return false;
      free_fan(start, left);
      return true;
    }
    const Index a = t.previous[b], c = t.next[b];
    if (!t.taken.empty())
      t.taken.insert(edge_key(p[a], p[c]));
    emit(a, b, c);
    t.next[a] = c;
    t.previous[c] = a;
    start = a;
    --left;
  }
  if (strict && !is_convex(t.previous[start], start, t.next[start]))
    return false;
  emit(t.previous[start], start, t.next[start]);
  return true;
}

}  // namespace

void avoid_existing_edges(const Soup& soup, Triangulation& t) {
  t.taken.clear();
  bool polygons = false;
  for (std::size_t f = 0; f < soup.num_faces() && !polygons; ++f)
    polygons = soup.arity(f) > 3;
  if (!polygons)
    return;
  t.taken.reserve(soup.num_corners());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    for (std::size_t i = 0; i < p.size(); ++i)
      t.taken.insert(edge_key(p[i], p[(i + 1) % p.size()]));
  }
}

bool triangulate_keyhole(const Soup& soup, const std::vector<Index>& vertices, Triangulation& t) {
  t.triangles.clear();
  t.positions.clear();
  // Consecutive repeats collapse (cyclically), as simple_loops() collapses them.
  std::vector<Index> kept;  // positions in `vertices`
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (kept.empty() || vertices[kept.back()] != vertices[i])
      kept.push_back(static_cast<Index>(i));
  }
  while (kept.size() > 1 && vertices[kept.back()] == vertices[kept.front()])
    kept.pop_back();
  if (kept.size() < 8)  // the smallest keyhole: a triangle in a triangle, and the slit twice
    return false;
  t.ring.resize(kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i)
    t.ring[i] = vertices[kept[i]];
  std::vector<Index> ids(kept.size());
  for (std::size_t i = 0; i < ids.size(); ++i)
    ids[i] = static_cast<Index>(i);
  std::vector<std::pair<Index, Index>> slits;
  const auto loops = simple_loops(
      std::move(ids), [&](Index i) { return t.ring[i]; }, &slits);
  if (slits.empty() || loops.size() < 2)
    return false;
  const PolygonView ring{t.ring.data(), t.ring.data() + t.ring.size()};
  if (!triangulate_ring(soup, ring, t, true)) {
    t.triangles.clear();
    t.positions.clear();
    return false;
  }
  // In the ring's plane (t.u, t.v: the whole polygon runs counter-clockwise), exactly one loop
  // turns that way (the outline) and the others the other way (the holes): the polygon winds
  // once round the points between them and not at all round a hole's, so triangles that all
  // turn that way (the ears do) cover the ring between them once and leave the holes open.
  std::size_t turning_way = 0;
  for (const std::vector<Index>& loop : loops) {
    double area = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Index a = loop[i], b = loop[(i + 1) % loop.size()];
      area += t.u[a] * t.v[b] - t.u[b] * t.v[a];
    }
    turning_way += area > 0 ? 1 : 0;
  }
  if (turning_way != 1) {
    t.triangles.clear();
    t.positions.clear();
    return false;
  }
  for (auto& triangle : t.positions) {
    for (Index& i : triangle)
      i = kept[i];
  }
  return true;
}

void triangulate_polygon(const Soup& soup, std::size_t f, Triangulation& t) {
  t.triangles.clear();
  t.positions.clear();
  const PolygonView p = soup.polygon(f);
  if (p.size() <= 3 || !has_repeated_vertex(p)) {
    triangulate_ring(soup, p, t);
    return;
  }
  if (triangulate_keyhole(soup, std::vector<Index>(p.begin(), p.end()), t))
    return;
  const auto loops =
      simple_loops(std::vector<Index>(p.begin(), p.end()), [](Index v) { return v; });
  if (loops.empty()) {
    triangulate_ring(soup, p, t);
    return;
  }
  for (const std::vector<Index>& loop : loops) {
    t.ring = loop;
    triangulate_ring(soup, PolygonView{t.ring.data(), t.ring.data() + t.ring.size()}, t);
  }
}

std::size_t polygon_triangle_count(const Soup& soup, std::size_t f) {
  const PolygonView polygon = soup.polygon(f);
  const std::size_t n = polygon.size();
  if (n <= 3 || !has_repeated_vertex(polygon))
    return n >= 3 ? n - 2 : 0;
  Triangulation t;
  if (triangulate_keyhole(soup, std::vector<Index>(polygon.begin(), polygon.end()), t))
    return t.triangles.size();
  const auto loops =
      simple_loops(std::vector<Index>(polygon.begin(), polygon.end()), [](Index v) { return v; });
  if (loops.empty())
    return n - 2;
  std::size_t triangles = 0;
  for (const std::vector<Index>& loop : loops)
    triangles += loop.size() - 2;
  return triangles;
}

}  // namespace meshbridge::detail

namespace meshbridge {

PolygonTriangles triangles_as_written(const Soup& soup) {
  PolygonTriangles out;
  out.first.reserve(soup.num_faces() + 1);
  out.corners.reserve(soup.num_faces());
  detail::Triangulation t;
  detail::avoid_existing_edges(soup, t);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    out.first.push_back(static_cast<Index>(out.corners.size()));
    const PolygonView p = soup.polygon(f);
    if (p.size() == 3) {
      out.corners.push_back({0, 1, 2});
      continue;
    }
    detail::triangulate_polygon(soup, f, t);
    const auto position = [&p](Index v) {
      return static_cast<std::uint32_t>(std::find(p.begin(), p.end(), v) - p.begin());
    };
    if (!t.positions.empty()) {  // a keyhole polygon: a slit's ends are two corners each
      for (const auto& [a, b, c] : t.positions)
        out.corners.push_back({a, b, c});
      continue;
    }
    for (const auto& [a, b, c] : t.triangles)
      out.corners.push_back({position(a), position(b), position(c)});
  }
  out.first.push_back(static_cast<Index>(out.corners.size()));
  return out;
}

Soup as_triangles(const Soup& soup) {
  const PolygonTriangles cut = triangles_as_written(soup);
  Soup out;
  out.positions = soup.positions;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const PolygonView p = soup.polygon(f);
    for (Index i = cut.first[f]; i < cut.first[f + 1]; ++i) {
      const auto& t = cut.corners[i];
      out.add_polygon({p[t[0]], p[t[1]], p[t[2]]});
    }
  }
  return out;
}

}  // namespace meshbridge
