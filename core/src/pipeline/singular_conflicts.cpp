// SPDX-License-Identifier: GPL-3.0-or-later
#include "pipeline/singular_conflicts.h"

#include "pipeline/angular_order.h"
#include "pipeline/grouping.h"
#include "pipeline/side_pairing.h"

#include <algorithm>
#include <tuple>
#include <unordered_map>

namespace meshbridge::detail {

namespace {

// A pair made at a singular edge, between the blocks (faces oriented through two-sided edges)
// `low` and `high`, which it wants `reversed` relative to each other.
struct Link {
  Index low, high;
  char reversed;
  Index edge;  // its edge in the bridges
  Index side;  // one of its sides (the smaller)
};

void cut(std::vector<Index>& mate, Index c) {
  mate[mate[c]] = kNoIndex;
  mate[c] = kNoIndex;
}

// The blocks of one component (faces oriented through two-sided edges) and a turn of each; what
// a choice of turns leaves open at the component's singular edges: per edge, the difference
// between its sides running along and against it (at most that many pairs can be made there).
class BlockFlips {
 public:
  // Reads the blocks of `faces` from `blocks` (joined through two-sided edges only).
  BlockFlips(const Soup& soup, const CornerFaces& corner_face, const EdgeBridges& bridges,
             const std::vector<Index>& edge_of_side, const std::vector<Index>& faces,
             ParityUnionFind& blocks) {
    for (Index f : faces) {
      char flip = 0;
      const Index root = blocks.find(f, flip);
      face_[f] = {root, flip};
    }
    std::vector<Index> edges;
    for (Index f : faces) {
      for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
        if (bridges.num_contenders(edge_of_side[c]) > 2)
          edges.push_back(edge_of_side[c]);
      }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    // Blocks numbered as the edges (by vertex pair) first meet them.
    std::unordered_map<Index, Index> number;
    entry_begin_.push_back(0);
    std::vector<Index> sides;
    for (Index e : edges) {
      sides.assign(bridges.contenders.begin() + bridges.begin[e],
                   bridges.contenders.begin() + bridges.begin[e + 1]);
      sort_by_face_key(soup, corner_face, sides);  // not by corner: by face order
      for (Index d : sides) {
        const auto face = face_.find(corner_face[d]);
        if (face == face_.end())
          continue;  // another component's side
        const auto [it, added] =
            number.emplace(face->second.first, static_cast<Index>(root_.size()));
        if (added)
          root_.push_back(face->second.first);
        entry_block_.push_back(it->second);
        entry_along_.push_back(runs_along(soup, corner_face, d) != (face->second.second != 0));
      }
      entry_begin_.push_back(static_cast<Index>(entry_block_.size()));
    }
    for (const auto& [face, block] : face_) {
      if (number.emplace(block.first, static_cast<Index>(root_.size())).second)
        root_.push_back(block.first);
    }
    for (auto& [face, block] : face_)
      block.first = number[block.first];
    block_edges_.resize(root_.size());
    for (Index e = 0; e + 1 < entry_begin_.size(); ++e) {
      for (Index i = entry_begin_[e]; i < entry_begin_[e + 1]; ++i) {
        std::vector<Index>& list = block_edges_[entry_block_[i]];
        if (list.empty() || list.back() != e)
          list.push_back(e);
      }
    }
  }

  // The turns the blocks' roots have in `blocks` now.
  void take(ParityUnionFind& blocks) {
    turn_.assign(root_.size(), 0);
    for (std::size_t b = 0; b < root_.size(); ++b)
      blocks.find(root_[b], turn_[b]);
  }

  // Turns single blocks, in their order, while one leaves fewer sides open; a few passes.
  void improve() {
    for (int pass = 0; pass < 16; ++pass) {
      bool changed = false;
      for (Index b = 0; b < root_.size(); ++b) {
        long before = 0, after = 0;
        for (Index e : block_edges_[b])
          before += open_sides(e);
        turn_[b] ^= 1;
        for (Index e : block_edges_[b])
          after += open_sides(e);
        if (after < before)
          changed = true;
        else
          turn_[b] ^= 1;
      }
      if (!changed)
        break;
    }
  }

  char face_flip(Index f) const {
    const auto& block = face_.at(f);
    return static_cast<char>(block.second ^ turn_[block.first]);
  }

 private:
  long open_sides(Index e) const {
    long balance = 0;
    for (Index i = entry_begin_[e]; i < entry_begin_[e + 1]; ++i)
      balance += (entry_along_[i] != (turn_[entry_block_[i]] != 0)) ? 1 : -1;
    return balance < 0 ? -balance : balance;
  }

  std::unordered_map<Index, std::pair<Index, char>> face_;  // block (root, then number), flip
  std::vector<Index> root_;                                 // per block
  std::vector<char> turn_;                                  // per block
  std::vector<std::vector<Index>> block_edges_;             // per block: its edges (local)
  std::vector<Index> entry_begin_;                          // per local edge
  std::vector<Index> entry_block_;                          // per entry: its side's block
  std::vector<char> entry_along_;  // per entry: runs along, in its block's orientation
};

}  // namespace

std::vector<Index> edge_of_sides(const Soup& soup, const EdgeBridges& bridges) {
  std::vector<Index> edge(soup.num_corners(), kNoIndex);
  for (std::size_t e = 0; e < bridges.num_edges(); ++e) {
    for (Index i = bridges.begin[e]; i < bridges.begin[e + 1]; ++i)
      edge[bridges.contenders[i]] = static_cast<Index>(e);
  }
  return edge;
}

Index yield_singular_pairs(const Soup& soup, const CornerFaces& corner_face,
                           const EdgeBridges& bridges, const std::vector<Index>& edge_of_side,
                           const std::vector<Index>& faces, ParityUnionFind& blocks,
                           std::vector<Index>& mate, std::vector<char>& flipped) {
  // Joins the faces of side c and side m so that the pair runs opposite ways; false if they are
  // joined already the other way.
  const auto join = [&](Index c, Index m) {
    char flip_c = 0, flip_m = 0;
    const Index root_c = blocks.find(corner_face[c], flip_c);
    const Index root_m = blocks.find(corner_face[m], flip_m);
    const bool reverse = (flip_c ^ flip_m ^ (same_way(soup, c, m) ? 1 : 0)) != 0;
    if (root_c == root_m)
      return !reverse;
    blocks.unite_roots(root_c, root_m, reverse);
    return true;
  };
  // 1. Blocks: the faces joined through two-sided edges.
  std::vector<Index> singular;  // the smaller side of each pair at a singular edge
  for (Index f : faces) {
    for (Index c = soup.face_begin[f]; c < soup.face_begin[f + 1]; ++c) {
      const Index m = mate[c];
      if (m == kNoIndex || m < c)
        continue;
      if (bridges.num_contenders(edge_of_side[c]) > 2)
        singular.push_back(c);
      else if (!join(c, m))
        return kNoIndex;
    }
  }
  std::vector<Index> partner(singular.size());
  for (std::size_t i = 0; i < singular.size(); ++i)
    partner[i] = mate[singular[i]];
  BlockFlips flips(soup, corner_face, bridges, edge_of_side, faces, blocks);

  // 2. The singular pairs, as links between blocks (a pair within a block either runs with it
  //    or must yield whatever the blocks do).
  std::vector<Link> links;
  for (std::size_t i = 0; i < singular.size(); ++i) {
    const Index c = singular[i], m = partner[i];
    char flip_c = 0, flip_m = 0;
    const Index root_c = blocks.find(corner_face[c], flip_c);
    const Index root_m = blocks.find(corner_face[m], flip_m);
    if (root_c == root_m)
      continue;
    const char reversed = static_cast<char>(flip_c ^ flip_m ^ (same_way(soup, c, m) ? 1 : 0));
    links.push_back(
        {std::min(root_c, root_m), std::max(root_c, root_m), reversed, edge_of_side[c], c});
  }
  // 3. Groups of links (same blocks, same relative orientation), admitted largest first: a
  //    group that contradicts what is admitted is left out.
  std::sort(links.begin(), links.end(), [](const Link& a, const Link& b) {
    return std::tie(a.low, a.high, a.reversed, a.edge) <
           std::tie(b.low, b.high, b.reversed, b.edge);
  });
  struct Group {
    std::size_t begin, end;
  };
  std::vector<Group> groups;
  for (std::size_t i = 0; i < links.size();) {
    std::size_t j = i + 1;
    while (j < links.size() && links[j].low == links[i].low && links[j].high == links[i].high &&
           links[j].reversed == links[i].reversed)
      ++j;
    groups.push_back({i, j});
    i = j;
  }
  // Within a group links are sorted by edge, so its first edge is links[begin].edge; edges are
  // numbered by vertex pair, never by face order.
  // Two groups can share their first edge (two pairs of one edge): then the faces of their
  // pairs there decide, by face key.
  std::vector<Index> key_a, key_b;
  const auto pair_keys = [&](const Link& link, std::vector<Index>& key) {
    std::vector<Index> other;
    face_key(soup, corner_face[link.side], key);
    face_key(soup, corner_face[mate[link.side]], other);
    if (other < key)
      key.swap(other);
    key.push_back(kNoIndex);
    key.insert(key.end(), other.begin(), other.end());
  };
  std::sort(groups.begin(), groups.end(), [&](const Group& a, const Group& b) {
    const std::size_t size_a = a.end - a.begin, size_b = b.end - b.begin;
    if (size_a != size_b)
      return size_a > size_b;
    const Link& first_a = links[a.begin];
    const Link& first_b = links[b.begin];
    if (first_a.edge != first_b.edge)
      return first_a.edge < first_b.edge;
    pair_keys(first_a, key_a);
    pair_keys(first_b, key_b);
    return key_a < key_b;
  });
  for (const Group& group : groups) {
    const Link& first = links[group.begin];
    join(first.side, mate[first.side]);
  }
  // 4. Single blocks turned while that leaves fewer sides open at singular edges.
  flips.take(blocks);
  flips.improve();
  // 5. Every face as its block is now oriented; the singular pairs that run the same way yield.
  for (Index f : faces)
    flipped[f] = flips.face_flip(f);
  Index sides_cut = 0;
  for (std::size_t i = 0; i < singular.size(); ++i) {
    const Index c = singular[i], m = partner[i];
    if ((flipped[corner_face[c]] ^ flipped[corner_face[m]] ^ (same_way(soup, c, m) ? 1 : 0)) != 0) {
      cut(mate, c);
      sides_cut += 2;
    }
  }
  return sides_cut;
}

}  // namespace meshbridge::detail
