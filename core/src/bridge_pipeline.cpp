// SPDX-License-Identifier: GPL-3.0-or-later
#include "bridge_pipeline.h"

#include "contender_pairing.h"
#include "orientation.h"
#include "union_find.h"

#include <algorithm>
#include <cmath>
#include <tuple>

namespace meshbridge::detail {

namespace {

// Disjoint sets of faces that also know, per face, whether the whole set was reversed since.
class ParityUnionFind {
 public:
  explicit ParityUnionFind(std::size_t n) : parent_(n), parity_(n, 0), size_(n, 1) {
    for (std::size_t i = 0; i < n; ++i)
      parent_[i] = static_cast<Index>(i);
  }
  //! Root of x; `flip` receives the accumulated reversal of x.
  Index find(Index x, char& flip) {
    // First pass: root and total parity; second pass: compress.
    Index root = x;
    char total = 0;
    while (parent_[root] != root) {
      total ^= parity_[root];
      root = parent_[root];
    }
    flip = static_cast<char>(total ^ parity_[root]);
    char below_root = total;  // parity of x relative to root, excluding the root's own
    while (parent_[x] != root && x != root) {
      const Index next = parent_[x];
      const char own = parity_[x];
      parent_[x] = root;
      parity_[x] = below_root;
      below_root ^= own;
      x = next;
    }
    return root;
  }
  //! Joins the sets of roots a and b, reversing b's set first if `reverse_b`.
  void unite_roots(Index a, Index b, bool reverse_b) {
    parity_[b] = static_cast<char>(parity_[b] ^ (reverse_b ? 1 : 0) ^ parity_[a]);
    parent_[b] = a;
    size_[a] += size_[b];
  }
  Index size(Index root) const { return size_[root]; }

 private:
  std::vector<Index> parent_;
  std::vector<char> parity_;
  std::vector<Index> size_;
};

// Glues unpaired sides of one edge back in pairs where the result stays consistently oriented,
// reversing a whole (smaller) component when that makes two sides run opposite ways.
std::size_t stitch(const Soup& soup, const std::vector<Index>& corner_face,
                   const EdgeBridges& bridges, std::vector<Index>& mate, std::vector<char>& flipped,
                   std::vector<char>& glued) {
  // Only edges with two or more unpaired sides can be stitched.
  std::vector<std::size_t> candidates;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    if (bridges.num_contenders(e) < 2)
      continue;
    Index open_sides = 0;
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i) {
      open_sides += mate[bridges.contenders[i]] == kNoIndex ? 1 : 0;
    }
    if (open_sides >= 2)
      candidates.push_back(e);
  }
  if (candidates.empty())
    return 0;

  const std::size_t num_faces = soup.num_faces();
  ParityUnionFind components(num_faces);
  char unused = 0;
  for (Index c = 0; c < mate.size(); ++c) {
    const Index m = mate[c];
    if (m == kNoIndex || m < c)
      continue;
    const Index a = components.find(corner_face[c], unused);
    const Index b = components.find(corner_face[m], unused);
    if (a != b)
      components.unite_roots(std::min(a, b), std::max(a, b), false);
  }
  std::size_t stitched = 0;
  std::vector<Index> open;
  for (std::size_t e : candidates) {
    open.clear();
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i) {
      if (mate[bridges.contenders[i]] == kNoIndex)
        open.push_back(bridges.contenders[i]);
    }
    // Angular order, so that what is glued does not depend on the order of faces.
    sort_by_angle(soup, corner_face, bridges, e, open);
    for (std::size_t i = 0; i < open.size(); ++i) {
      const Index s = open[i];
      if (mate[s] != kNoIndex)
        continue;
      for (std::size_t j = i + 1; j < open.size(); ++j) {
        const Index t = open[j];
        if (mate[t] != kNoIndex)
          continue;
        char flip_s = 0, flip_t = 0;
        const Index root_s = components.find(corner_face[s], flip_s);
        const Index root_t = components.find(corner_face[t], flip_t);
        const bool along_s = runs_along(soup, bridges, s) != (flipped[corner_face[s]] ^ flip_s);
        const bool along_t = runs_along(soup, bridges, t) != (flipped[corner_face[t]] ^ flip_t);
        if (root_s == root_t) {
          if (along_s == along_t)
            continue;
        } else {
          // Keep the larger component as it is (ties: the one with the smaller root).
          const bool keep_s =
              components.size(root_s) > components.size(root_t) ||
              (components.size(root_s) == components.size(root_t) && root_s < root_t);
          const Index keep = keep_s ? root_s : root_t;
          const Index other = keep_s ? root_t : root_s;
          components.unite_roots(keep, other, along_s == along_t);
        }
        mate[s] = t;
        mate[t] = s;
        glued[s] = glued[t] = 1;
        stitched += 2;
        break;
      }
    }
  }
  for (Index f = 0; f < num_faces; ++f) {
    char flip = 0;
    components.find(f, flip);
    flipped[f] ^= flip;
  }
  return stitched;
}

// Reverses whole components: closed ones so that their signed volume is positive, open ones (and
// closed ones of no volume, such as two faces glued back to back) so that fewer of their faces
// end up reversed. "No volume": |volume| <= 1e-9 times the sum of its terms' magnitudes, below
// which the sign is rounding noise.
void choose_component_orientation(const Soup& soup, const std::vector<Index>& corner_face,
                                  const std::vector<Index>& mate, std::vector<char>& flipped) {
  const std::size_t num_faces = soup.num_faces();
  UnionFind components(num_faces);
  for (Index c = 0; c < mate.size(); ++c) {
    if (mate[c] != kNoIndex)
      components.unite(corner_face[c], corner_face[mate[c]]);
  }
  std::vector<char> open(num_faces, 0);
  std::vector<double> volume(num_faces, 0.0), magnitude(num_faces, 0.0);
  std::vector<Index> faces(num_faces, 0), reversed(num_faces, 0);
  for (Index f = 0; f < num_faces; ++f) {
    const Index r = components.find(f);
    ++faces[r];
    reversed[r] += flipped[f];
    const PolygonView polygon = soup.polygon(f);
    double v = 0;
    const Point& p0 = soup.positions[polygon[0]];
    for (std::size_t i = 1; i + 1 < polygon.size(); ++i) {
      const double term = OpenMesh::dot(
          p0, OpenMesh::cross(soup.positions[polygon[i]], soup.positions[polygon[i + 1]]));
      v += term;
      magnitude[r] += std::abs(term);
    }
    volume[r] += flipped[f] ? -v : v;
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      if (mate[c] == kNoIndex)
        open[r] = 1;
    }
  }
  std::vector<char> reverse(num_faces, 0);
  for (Index r = 0; r < num_faces; ++r) {
    if (faces[r] == 0)
      continue;
    const bool flat = std::abs(volume[r]) <= 1e-9 * magnitude[r];
    reverse[r] = (open[r] || flat) ? (2 * reversed[r] > faces[r]) : (volume[r] < 0);
  }
  for (Index f = 0; f < num_faces; ++f)
    flipped[f] ^= reverse[components.find(f)];
}

// The output polygons: working faces with split vertices, reversed where flipped.
IndexedMesh emit_mesh(const WorkingSoup& working, const std::vector<Index>& corner_vertex,
                      std::vector<Index> vertex_origin, const std::vector<char>& flipped) {
  const Soup& soup = working.soup();
  IndexedMesh mesh;
  mesh.vertex_origin = std::move(vertex_origin);
  mesh.soup.positions.resize(mesh.vertex_origin.size());
  for (std::size_t v = 0; v < mesh.vertex_origin.size(); ++v) {
    mesh.soup.positions[v] = soup.positions[mesh.vertex_origin[v]];
  }
  mesh.soup.corner_vertices.resize(soup.num_corners());
  mesh.soup.face_begin = soup.face_begin;
  mesh.corner_origin.resize(soup.num_corners());
  mesh.face_origin.resize(soup.num_faces());
  for (Index f = 0; f < soup.num_faces(); ++f) {
    mesh.face_origin[f] = working.face_origin(f);
    const Index first = soup.face_begin[f];
    const Index last = soup.face_begin[f + 1];
    for (Index c = first; c < last; ++c) {
      // Reversal keeps the first corner: c0 c1 ... ck-1 -> c0 ck-1 ... c1.
      const Index source = (flipped[f] && c != first) ? first + (last - c) : c;
      mesh.soup.corner_vertices[c] = corner_vertex[source];
      mesh.corner_origin[c] = working.corner_origin(source);
    }
  }
  return mesh;
}

// One round of making every output edge manifold. Only sides on singular edges or unpaired
// sides of 2-sided edges can land on one output edge with others (a fan winding twice around a
// vertex). Per such output edge: two opposite unpaired sides are paired (the output glues them
// anyway); extra pairs are cut, stitched ones first, keeping one pair; a pair sharing its edge
// with unpaired sides is cut; unpaired sides that still share one are separated by detaching
// their faces (the last resort). Returns true if anything changed (fans must be recomputed).
struct CollisionCounts {
  std::size_t implicitly_stitched = 0;
  std::size_t unstitched = 0;
  std::size_t pairs_cut = 0;  // sides
  std::vector<Index> detach;
};

bool resolve_collisions(const Soup& soup, const std::vector<Index>& corner_face,
                        const EdgeBridges& bridges, const std::vector<Index>& corner_vertex,
                        const std::vector<char>& flipped, const std::vector<char>& glued,
                        std::vector<Index>& mate, CollisionCounts& counts) {
  // Output vertex a side starts at, after its face is reversed or not.
  const auto start = [&](Index c) {
    const Index f = corner_face[c];
    return corner_vertex[flipped[f] ? soup.next_corner(c, f) : c];
  };
  const auto unpair = [&](Index a) {
    const Index b = mate[a];
    mate[a] = kNoIndex;
    mate[b] = kNoIndex;
    if (glued[a]) {
      counts.unstitched += 2;
    } else {
      counts.pairs_cut += 2;
    }
  };
  // Choices below are made by the faces' sorted vertex lists, which do not depend on the order
  // of faces or on where a polygon starts.
  const auto face_key = [&](Index side) {
    const PolygonView p = soup.polygon(corner_face[side]);
    std::vector<Index> key(p.begin(), p.end());
    std::sort(key.begin(), key.end());
    return key;
  };
  const auto pair_key = [&](Index side) {
    auto a = face_key(side), b = face_key(mate[side]);
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  };
  bool changed = false;
  std::vector<std::tuple<Index, Index, Index>> keyed;  // (out low, out high, side)
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index k = bridges.num_contenders(e);
    if (k < 2)
      continue;
    if (k == 2 && mate[bridges.contenders[bridges.begin[e]]] != kNoIndex)
      continue;
    keyed.clear();
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i) {
      const Index c = bridges.contenders[i];
      const Index a = corner_vertex[c];
      const Index b = corner_vertex[soup.next_corner(c, corner_face[c])];
      keyed.emplace_back(std::min(a, b), std::max(a, b), c);
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t i = 0; i < keyed.size();) {
      std::size_t j = i + 1;
      while (j < keyed.size() && std::get<0>(keyed[j]) == std::get<0>(keyed[i]) &&
             std::get<1>(keyed[j]) == std::get<1>(keyed[i]))
        ++j;
      const std::size_t size = j - i;
      std::vector<Index> pairs, open;  // pairs: the smaller side of each
      for (std::size_t t = i; t < j; ++t) {
        const Index c = std::get<2>(keyed[t]);
        if (mate[c] == kNoIndex) {
          open.push_back(c);
        } else if (c < mate[c]) {
          pairs.push_back(c);
        }
      }
      i = j;
      if (size < 2 || (size == 2 && pairs.size() == 1))
        continue;
      changed = true;
      if (size == 2 && start(open[0]) != start(open[1])) {
        mate[open[0]] = open[1];
        mate[open[1]] = open[0];
        counts.implicitly_stitched += 2;
      } else if (!pairs.empty() && (pairs.size() >= 2 || !open.empty())) {
        // Keep one pair that pairing made (not stitching) if there is more than one pair.
        Index keep = kNoIndex;
        if (pairs.size() >= 2) {
          for (Index p : pairs) {
            const bool better = keep == kNoIndex || (glued[keep] && !glued[p]) ||
                                (glued[keep] == glued[p] && pair_key(p) < pair_key(keep));
            if (better)
              keep = p;
          }
        }
        for (Index p : pairs) {
          if (p != keep)
            unpair(p);
        }
      } else {
        std::sort(open.begin(), open.end(),
                  [&](Index a, Index b) { return face_key(a) < face_key(b); });
        for (std::size_t t = 1; t < open.size(); ++t)
          counts.detach.push_back(corner_face[open[t]]);
      }
    }
  }
  return changed;
}

}  // namespace

std::vector<Index> split_fans(const Soup& soup, const std::vector<Index>& corner_face,
                              const std::vector<Index>& mate, std::vector<Index>& vertex_origin) {
  const std::size_t num_corners = soup.num_corners();
  const auto& cv = soup.corner_vertices;
  UnionFind fans(num_corners);
  for (Index c = 0; c < num_corners; ++c) {
    const Index m = mate[c];
    if (m == kNoIndex || m < c)
      continue;
    const Index c_next = soup.next_corner(c, corner_face[c]);
    const Index m_next = soup.next_corner(m, corner_face[m]);
    if (cv[m] == cv[c]) {
      fans.unite(c, m);
      fans.unite(c_next, m_next);
    } else {
      fans.unite(c, m_next);
      fans.unite(c_next, m);
    }
  }
  const std::size_t num_vertices = soup.num_vertices();
  vertex_origin.resize(num_vertices);
  for (std::size_t v = 0; v < num_vertices; ++v)
    vertex_origin[v] = static_cast<Index>(v);
  // A fan's root is its first corner: fans are numbered in corner order, the first fan of each
  // vertex keeps the vertex, the others get copies appended.
  std::vector<char> taken(num_vertices, 0);
  return std::move(fans).take_labels([&](Index root) {
    const Index v = cv[root];
    if (!taken[v]) {
      taken[v] = 1;
      return v;
    }
    vertex_origin.push_back(v);
    return static_cast<Index>(vertex_origin.size() - 1);
  });
}

PipelineResult run_pipeline(const WorkingSoup& working, const PipelineOptions& options) {
  std::vector<Index> corner_face = corner_faces(working.soup());
  EdgeBridges bridges = group_sides(working.soup(), corner_face);
  return run_pipeline(working, std::move(corner_face), std::move(bridges), options);
}

PipelineResult run_pipeline(const WorkingSoup& working, std::vector<Index> corner_face_in,
                            EdgeBridges bridges_in, const PipelineOptions& options) {
  const Soup& soup = working.soup();
  PipelineResult result;
  result.corner_face = std::move(corner_face_in);
  result.bridges = std::move(bridges_in);
  const auto& corner_face = result.corner_face;
  const auto& bridges = result.bridges;
  auto& mate = result.mate;
  auto& flipped = result.flipped;

  mate = pair_contenders(soup, corner_face, bridges, options.pairing);
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    if (bridges.num_contenders(e) <= 2)
      continue;
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i) {
      if (mate[bridges.contenders[i]] == kNoIndex)
        ++result.sides_cut;
    }
  }

  if (options.orient) {
    const OrientationCounts counts =
        orient_consistently(soup, corner_face, options.cut_nonorientable, mate, flipped);
    result.nonorientable_components = counts.nonorientable_components;
    result.sides_cut_for_orientation = counts.sides_cut;
  } else {
    flipped.assign(soup.num_faces(), 0);
    result.sides_cut_for_orientation = cut_inconsistent_pairs(soup, mate);
  }
  std::vector<char> glued(soup.num_corners(), 0);
  if (options.stitch)
    result.sides_stitched = stitch(soup, corner_face, bridges, mate, flipped, glued);
  if (options.orient)
    choose_component_orientation(soup, corner_face, mate, flipped);

  std::vector<Index> vertex_origin;
  std::vector<Index> corner_vertex = split_fans(soup, corner_face, mate, vertex_origin);
  // Each round pairs, cuts or detaches something, and nothing is undone: this ends.
  CollisionCounts collisions;
  bool resolved_any = false;
  while (resolve_collisions(soup, corner_face, bridges, corner_vertex, flipped, glued, mate,
                            collisions)) {
    resolved_any = true;
    std::sort(collisions.detach.begin(), collisions.detach.end());
    collisions.detach.erase(std::unique(collisions.detach.begin(), collisions.detach.end()),
                            collisions.detach.end());
    for (Index f : collisions.detach) {
      for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
        if (mate[c] != kNoIndex) {
          mate[mate[c]] = kNoIndex;
          mate[c] = kNoIndex;
        }
      }
    }
    result.faces_detached += collisions.detach.size();
    collisions.detach.clear();
    corner_vertex = split_fans(soup, corner_face, mate, vertex_origin);
  }
  result.sides_stitched += collisions.implicitly_stitched;
  result.sides_stitched -= collisions.unstitched;
  result.sides_cut_to_stay_manifold = collisions.pairs_cut;
  // Cuts can leave a closed part of a component that was open: orient again (fans do not
  // depend on orientation).
  if (resolved_any && options.orient)
    choose_component_orientation(soup, corner_face, mate, flipped);
  result.vertices_split = vertex_origin.size() - soup.num_vertices();
  for (char f : flipped)
    result.faces_flipped += f;
  result.mesh = emit_mesh(working, corner_vertex, std::move(vertex_origin), flipped);
  return result;
}

}  // namespace meshbridge::detail
