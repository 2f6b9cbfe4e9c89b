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
// Pairs split at their midpoint are on output edges of their own and take no part.
template <class Visit>
std::size_t for_each_crowded_output_edge(const Soup& soup, const GroupedSides& grouped,
                                         const std::vector<Index>& corner_vertex,
                                         const SidePairing& pairing, Visit visit) {
  const std::vector<Index>& mate = pairing.mate;
  const std::vector<char>& midpoint = pairing.midpoint;
  const CornerFaces& corner_face = grouped.corner_face;
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
      if (!midpoint.empty() && midpoint[c])
        continue;
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

// Copies of one polygon (the same vertex cycle, either way round) have equal keys: the cycle from
// its smallest vertex, forward or backward, whichever is lexicographically smaller.
void copy_key(const Soup& soup, Index f, std::vector<Index>& key) {
  const PolygonView p = soup.polygon(f);
  const std::size_t k = p.size();
  const std::size_t start =
      static_cast<std::size_t>(std::min_element(p.begin(), p.end()) - p.begin());
  key.resize(2 * k);
  for (std::size_t i = 0; i < k; ++i) {
    key[i] = p[(start + i) % k];
    key[k + i] = p[(start + k - i) % k];
  }
  if (std::lexicographical_compare(key.begin() + k, key.end(), key.begin(), key.begin() + k))
    std::copy(key.begin() + k, key.end(), key.begin());
  key.resize(k);
}

// Crowded output edges whose pairs can trade partners so that copies of one polygon are glued
// back to back: pairs (s, m) and (t, n) become (s, t) and (m, n) when s and t are sides of copies
// of one polygon that run opposite ways as the faces will be written, and neither s nor t is
// already paired with a copy of its own polygon. (m and n then run opposite ways too: s and m
// do, t and n do, s and t do.) No side is unpaired; each exchange makes one more pair of copies.
// Returns the number of exchanges.
std::size_t pair_copies(const Soup& soup, const GroupedSides& grouped, const VertexSplit& split,
                        SidePairing& pairing, ManifoldEdgeCounts& counts, std::size_t& crowded) {
  std::vector<Index>& mate = pairing.mate;
  const CornerFaces& corner_face = grouped.corner_face;
  // Output vertex each side starts at, as the faces will be written.
  const auto start = [&](Index c) {
    const Index f = corner_face[c];
    return split.corner_vertex[pairing.flipped[f] ? soup.next_corner(c, f) : c];
  };
  std::vector<Index> key_a, key_b;
  const auto copies = [&](Index a, Index b) {
    copy_key(soup, corner_face[a], key_a);
    copy_key(soup, corner_face[b], key_b);
    return key_a == key_b;
  };
  std::vector<std::pair<std::vector<Index>, Index>> keyed;  // (copy key, side)
  std::size_t exchanges = 0;
  crowded = for_each_crowded_output_edge(
      soup, grouped, split.corner_vertex, pairing,
      [&](const std::vector<Index>& pairs, const std::vector<Index>&) {
        if (pairs.size() < 2)
          return;
        // The sides of the edge's pairs not yet paired with a copy, by copy key, then by side
        // (copies of one polygon are interchangeable; only they are told apart by index).
        keyed.clear();
        for (Index p : pairs) {
          if (copies(p, mate[p]))
            continue;
          for (Index side : {p, mate[p]}) {
            keyed.emplace_back(std::vector<Index>(), side);
            copy_key(soup, corner_face[side], keyed.back().first);
          }
        }
        std::sort(keyed.begin(), keyed.end());
        for (std::size_t i = 0; i < keyed.size();) {
          std::size_t j = i + 1;
          while (j < keyed.size() && keyed[j].first == keyed[i].first)
            ++j;
          // Within one polygon's copies: the k-th running one way with the k-th running the
          // other way.
          std::vector<Index> ways[2];
          const Index first_start = start(keyed[i].second);
          for (std::size_t t = i; t < j; ++t)
            ways[start(keyed[t].second) == first_start ? 0 : 1].push_back(keyed[t].second);
          for (std::size_t t = 0; t < std::min(ways[0].size(), ways[1].size()); ++t) {
            const Index s = ways[0][t], u = ways[1][t];
            const Index m = mate[s], n = mate[u];
            if (copies(s, m) || copies(u, n))
              continue;  // an earlier exchange on this edge already glued it to a copy
            for (Index side : {s, m, u, n}) {
              if (pairing.stitched[side])
                ++counts.unstitched;
              pairing.stitched[side] = 0;
            }
            mate[s] = u;
            mate[u] = s;
            mate[m] = n;
            mate[n] = m;
            counts.sides_paired_with_copies += 4;
            ++exchanges;
          }
          i = j;
        }
      });
  return exchanges;
}

enum class Crowding { cut, split_at_midpoint };

// One round: per output edge holding two or more pairs, all but one are taken off it (stitched
// ones first; among equals the one whose faces' keys are smallest is kept); a pair sharing its
// output edge with unpaired sides is taken off too. With Crowding::cut a pair taken off is cut;
// with Crowding::split_at_midpoint it stays a pair, and its two faces get a new vertex at the
// middle of the edge (emit_mesh()), so its sides run through that vertex and share no output
// edge with anything (DESIGN 8a, closed stays closed). Returns the number of pairs taken off.
std::size_t resolve_crowding_pairs(const Soup& soup, const GroupedSides& grouped,
                                   const std::vector<Index>& corner_vertex, SidePairing& pairing,
                                   Crowding how, ManifoldEdgeCounts& counts, std::size_t& crowded) {
  std::vector<Index>& mate = pairing.mate;
  const std::vector<char>& stitched = pairing.stitched;
  if (how == Crowding::split_at_midpoint && pairing.midpoint.empty())
    pairing.midpoint.assign(mate.size(), 0);
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
  std::size_t taken = 0;
  crowded = for_each_crowded_output_edge(
      soup, grouped, corner_vertex, pairing,
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
          ++taken;
          if (how == Crowding::split_at_midpoint) {
            pairing.midpoint[p] = pairing.midpoint[mate[p]] = 1;
            ++counts.edges_split_to_stay_manifold;
            continue;
          }
          (stitched[p] ? counts.unstitched : counts.pairs_cut) += 2;
          mate[mate[p]] = kNoIndex;
          mate[p] = kNoIndex;
        }
      });
  return taken;
}

// Rounds until no pair crowds an output edge, resolving it as `how` says, then the unpaired sides
// left on one output edge glued (see make_output_edges_manifold()).
ManifoldEdgeCounts resolve_crowding(const Soup& soup, const GroupedSides& grouped,
                                    SidePairing& pairing, VertexSplit& split, Crowding how) {
  ManifoldEdgeCounts counts;
  // 1. Where copies of one polygon can trade partners (pair_copies) they do, and nothing else
  //    changes in that round; otherwise extra pairs are cut, or split at their midpoint (which
  //    takes them off the crowded edges for good). An exchange keeps the number of pairs and
  //    adds a pair of copies; a cut or a split takes a pair away: so 2 x pairs + pairs not of
  //    copies falls in every round, and there are at most 3 x pairs rounds (one or two in
  //    practice).
  const std::size_t most_rounds = 3 * (pairing.mate.size() / 2) + 1;
  std::size_t crowded = 0;
  for (;;) {
    std::size_t changed = pair_copies(soup, grouped, split, pairing, counts, crowded);
    if (crowded == 0)
      return counts;  // no output edge is shared
    if (changed == 0) {
      changed =
          resolve_crowding_pairs(soup, grouped, split.corner_vertex, pairing, how, counts, crowded);
    }
    if (changed == 0)
      break;
    if (++counts.rounds > most_rounds)
      throw std::logic_error("make_output_edges_manifold: the rounds did not end");
    split = split_fans(soup, grouped.corner_face, pairing.mate);
  }
  // 2. What is left on a crowded output edge is unpaired sides only. Two of them running
  //    opposite ways are glued, as the output would glue them anyway: they already start and
  //    end at the same output vertices, so their corners are in the same fans and gluing them
  //    changes no fan (no new crowding). Two running the same way, or three or more, cannot
  //    share an output edge: every pair runs opposite ways, so every fan is consistently
  //    oriented and its two open ends are one side out of the vertex and one side into it.
  std::vector<Index>& mate = pairing.mate;
  const auto start = [&](Index c) {
    const Index f = grouped.corner_face[c];
    return split.corner_vertex[pairing.flipped[f] ? soup.next_corner(c, f) : c];
  };
  for_each_crowded_output_edge(
      soup, grouped, split.corner_vertex, pairing,
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

}  // namespace

ManifoldEdgeCounts make_output_edges_manifold(const Soup& soup, const GroupedSides& grouped,
                                              SidePairing& pairing, VertexSplit& split) {
  std::size_t crowded =
      for_each_crowded_output_edge(soup, grouped, split.corner_vertex, pairing,
                                   [](const std::vector<Index>&, const std::vector<Index>&) {});
  if (crowded == 0)
    return ManifoldEdgeCounts();
  // First as the fans suggest: cut, and glue again what then lands on one output edge (three
  // tetrahedra on one edge come apart, each closed). If that leaves open a side that was paired,
  // start again and split pairs at their midpoint instead: nothing opens (DESIGN 8a).
  const std::vector<Index> mate_before = pairing.mate;
  const std::vector<char> stitched_before = pairing.stitched;
  VertexSplit split_before = split;
  ManifoldEdgeCounts counts = resolve_crowding(soup, grouped, pairing, split, Crowding::cut);
  bool opened = false;
  for (std::size_t c = 0; c < mate_before.size() && !opened; ++c)
    opened = mate_before[c] != kNoIndex && pairing.mate[c] == kNoIndex;
  if (!opened)
    return counts;
  pairing.mate = mate_before;
  pairing.stitched = stitched_before;
  split = std::move(split_before);
  return resolve_crowding(soup, grouped, pairing, split, Crowding::split_at_midpoint);
}

}  // namespace meshbridge::detail
