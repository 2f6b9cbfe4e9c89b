// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/manifold_edges.h"

#include "pipeline/angular_order.h"
#include "pipeline/fans.h"

#include <algorithm>
#include <stdexcept>
#include <tuple>

namespace meshbridge::detail {

namespace {

// Output edges shared by more than one side, other than by one pair: calls visit(pairs, open)
// per such crowded output edge
// with its paired sides (the smaller side of each pair) and its unpaired sides. Only sides on
// singular edges or unpaired sides of 2-sided edges can land on one output edge with others.
template <class Visit>
std::size_t for_each_crowded_output_edge(const Soup& soup, const GroupedSides& grouped,
                                         const std::vector<Index>& corner_vertex,
                                         const std::vector<Index>& mate, Visit visit) {
  const std::vector<Index>& corner_face = grouped.corner_face;
  const EdgeBridges& bridges = grouped.bridges;
  std::vector<std::tuple<Index, Index, Index>> keyed;  // (out low, out high, side)
  std::vector<Index> pairs, open;
  std::size_t crowded = 0;
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    const Index k = bridges.num_contenders(e);
    if (k < 2 || (k == 2 && mate[bridges.contenders[bridges.begin[e]]] != kNoIndex))
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
      pairs.clear();
      open.clear();
      for (std::size_t t = i; t < j; ++t) {
        const Index c = std::get<2>(keyed[t]);
        if (mate[c] == kNoIndex) {
          open.push_back(c);
        } else if (c < mate[c]) {
          pairs.push_back(c);
        }
      }
      if (j - i >= 2 && !(pairs.size() == 1 && open.empty())) {
        ++crowded;
        visit(pairs, open);
      }
      i = j;
    }
  }
  return crowded;
}

// One round of cuts: per output edge holding two or more pairs, all but one are cut (stitched
// ones first; among equals the one whose faces' keys are smallest is kept); a pair sharing its
// output edge with unpaired sides is cut. Returns the number of pairs cut.
std::size_t cut_crowding_pairs(const Soup& soup, const GroupedSides& grouped,
                               const std::vector<Index>& corner_vertex, SidePairing& pairing,
                               ManifoldEdgeCounts& counts, std::size_t& crowded) {
  std::vector<Index>& mate = pairing.mate;
  const std::vector<char>& stitched = pairing.stitched;
  // Choices are made by face keys, which do not depend on face order or polygon start.
  const auto key_of = [&](Index side) {
    std::vector<Index> key;
    face_key(soup, grouped.corner_face[side], key);
    return key;
  };
  const auto pair_key = [&](Index side) {
    auto a = key_of(side), b = key_of(mate[side]);
    return a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  };
  std::size_t cut = 0;
  crowded = for_each_crowded_output_edge(
      soup, grouped, corner_vertex, mate,
      [&](const std::vector<Index>& pairs, const std::vector<Index>& open) {
        if (pairs.empty() || (pairs.size() == 1 && open.empty()))
          return;
        Index keep = kNoIndex;  // kept only if no unpaired side shares the edge
        if (open.empty()) {
          for (Index p : pairs) {
            const bool better = keep == kNoIndex || (stitched[keep] && !stitched[p]) ||
                                (stitched[keep] == stitched[p] && pair_key(p) < pair_key(keep));
            if (better)
              keep = p;
          }
        }
        for (Index p : pairs) {
          if (p == keep)
            continue;
          (stitched[p] ? counts.unstitched : counts.pairs_cut) += 2;
          mate[mate[p]] = kNoIndex;
          mate[p] = kNoIndex;
          ++cut;
        }
      });
  return cut;
}

}  // namespace

ManifoldEdgeCounts make_output_edges_manifold(const Soup& soup, const GroupedSides& grouped,
                                              SidePairing& pairing, VertexSplit& split) {
  ManifoldEdgeCounts counts;
  // 1. Cuts. Each round cuts at least one pair and none is made, so there are at most as many
  //    rounds as pairs (one or two in practice); cutting only ever splits fans.
  const std::size_t most_rounds = pairing.mate.size() / 2 + 1;
  std::size_t crowded = 0;
  while (cut_crowding_pairs(soup, grouped, split.corner_vertex, pairing, counts, crowded) > 0) {
    if (++counts.rounds > most_rounds)
      throw std::logic_error("make_output_edges_manifold: cutting did not end");
    split = split_fans(soup, grouped.corner_face, pairing.mate);
  }
  // 2. What is left on a crowded output edge is unpaired sides only. Two of them running
  //    opposite ways are glued, as the output would glue them anyway: they already start and
  //    end at the same output vertices, so their corners are in the same fans and gluing them
  //    changes no fan (no new crowding). Two running the same way, or three or more, cannot
  //    share an output edge: every pair runs opposite ways, so every fan is consistently
  //    oriented and its two open ends are one side out of the vertex and one side into it.
  if (crowded == 0)
    return counts;  // the last round saw no crowded output edge
  std::vector<Index>& mate = pairing.mate;
  const auto start = [&](Index c) {
    const Index f = grouped.corner_face[c];
    return split.corner_vertex[pairing.flipped[f] ? soup.next_corner(c, f) : c];
  };
  for_each_crowded_output_edge(
      soup, grouped, split.corner_vertex, mate,
      [&](const std::vector<Index>& pairs, const std::vector<Index>& open) {
        if (!pairs.empty() || open.size() != 2 || start(open[0]) == start(open[1])) {
          throw std::logic_error(
              "make_output_edges_manifold: unpaired sides running the same way share an output "
              "edge");
        }
        mate[open[0]] = open[1];
        mate[open[1]] = open[0];
        counts.implicitly_stitched += 2;
      });
  return counts;
}

}  // namespace meshbridge::detail
