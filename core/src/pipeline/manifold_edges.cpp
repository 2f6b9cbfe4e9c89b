// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/manifold_edges.h"

#include "pipeline/angular_order.h"
#include "pipeline/fans.h"

#include <algorithm>
#include <tuple>

namespace meshbridge::detail {

namespace {

// One round of making every output edge manifold. Only sides on singular edges or unpaired
// sides of 2-sided edges can land on one output edge with others (a fan winding twice around a
// vertex). Per such output edge: two opposite unpaired sides are paired (the output glues them
// anyway); extra pairs are cut, stitched ones first, keeping one pair; a pair sharing its edge
// with unpaired sides is cut; unpaired sides that still share one are separated by detaching
// their faces (the last resort). Returns true if anything changed (fans must be recomputed).
bool resolve_collisions(const Soup& soup, const GroupedSides& grouped,
                        const std::vector<Index>& corner_vertex, SidePairing& pairing,
                        ManifoldEdgeCounts& counts, std::vector<Index>& detach) {
  const std::vector<Index>& corner_face = grouped.corner_face;
  const EdgeBridges& bridges = grouped.bridges;
  const std::vector<char>& flipped = pairing.flipped;
  const std::vector<char>& glued = pairing.stitched;
  std::vector<Index>& mate = pairing.mate;
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
    std::vector<Index> key;
    detail::face_key(soup, corner_face[side], key);
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
          detach.push_back(corner_face[open[t]]);
      }
    }
  }
  return changed;
}

}  // namespace

ManifoldEdgeCounts make_output_edges_manifold(const Soup& soup, const GroupedSides& grouped,
                                              SidePairing& pairing, VertexSplit& split) {
  ManifoldEdgeCounts counts;
  std::vector<Index> detach;
  // Each round pairs, cuts or detaches something, and nothing is undone: this ends.
  while (resolve_collisions(soup, grouped, split.corner_vertex, pairing, counts, detach)) {
    counts.rounds += 1;
    std::sort(detach.begin(), detach.end());
    detach.erase(std::unique(detach.begin(), detach.end()), detach.end());
    for (Index f : detach) {
      for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
        if (pairing.mate[c] != kNoIndex) {
          pairing.mate[pairing.mate[c]] = kNoIndex;
          pairing.mate[c] = kNoIndex;
        }
      }
    }
    counts.faces_detached += detach.size();
    detach.clear();
    split = split_fans(soup, grouped.corner_face, pairing.mate);
  }
  return counts;
}

}  // namespace meshbridge::detail
