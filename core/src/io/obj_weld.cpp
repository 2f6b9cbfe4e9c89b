// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/obj_weld.h"

#include "io/huge_pages.h"
#include "io/repeated_vertices.h"

#include <cstring>
#include <memory>

namespace meshbridge::detail {

namespace {

constexpr std::size_t kFirstSlots = std::size_t(1) << 12;
constexpr std::size_t kMostReserved = std::size_t(1) << 20;  // 32 MB

}  // namespace

void PositionTable::reserve(std::size_t vertices) {
  reserve_huge(ids_, vertices);
  // Slots for a closed surface's positions (about one per 6 corners) at the start: a table that
  // grows writes all its slots again each time.
  std::size_t slots = kFirstSlots;
  while (slots < vertices / 8 && slots < kMostReserved)
    slots *= 2;
  if (slots > slots_.size())
    rehash(slots);
  // The positions on 2 MiB pages too: the stages after reading look them up at random where the
  // faces are shuffled.
  reserve_huge(positions_, slots_.size() / 4 * 3);
}

Index PositionTable::insert(const Point& p, std::uint64_t hash) {
  const std::uint32_t high = static_cast<std::uint32_t>(hash >> 32);
  const std::size_t mask = slots_.size() - 1;
  for (std::size_t slot = static_cast<std::size_t>(hash) & mask;; slot = (slot + 1) & mask) {
    Slot& s = slots_[slot];
    if (s.id == 0) {
      const Index id = static_cast<Index>(positions_.size());
      s = Slot{{p[0], p[1], p[2]}, high, id + 1};
      positions_.push_back(p);
      return id;
    }
    if (s.hash == high && s.xyz[0] == p[0] && s.xyz[1] == p[1] && s.xyz[2] == p[2])
      return s.id - 1;
  }
}

void PositionTable::flush() {
  for (std::size_t k = 0; k < pending_count_; ++k)
    ids_.push_back(insert(pending_[k].p, pending_[k].hash));
  pending_count_ = 0;
  if (4 * (positions_.size() + kBatch) > 3 * slots_.size())
    rehash(2 *
           slots_.size());  // room for the next batch, whose slots are prefetched from this table
}

void PositionTable::rehash(std::size_t size) {
  std::vector<Slot> slots;
  reserve_huge(slots, size);
  slots.resize(size, Slot{{0, 0, 0}, 0, 0});
  const std::size_t mask = slots.size() - 1;
  for (std::size_t id = 0; id < positions_.size(); ++id) {
    const Point& p = positions_[id];
    const std::uint64_t hash = position_hash(p);
    std::size_t slot = static_cast<std::size_t>(hash) & mask;
    while (slots[slot].id != 0)
      slot = (slot + 1) & mask;
    slots[slot] = Slot{
        {p[0], p[1], p[2]}, static_cast<std::uint32_t>(hash >> 32), static_cast<Index>(id) + 1};
  }
  slots_ = std::move(slots);
}

void PositionTable::append(PositionTable& other) {
  flush();
  other.flush();
  const std::vector<Point>& theirs = other.positions_;
  std::vector<Index> id(theirs.size());
  constexpr std::size_t kAhead = 16;  // positions whose slots are on their way
  for (std::size_t k = 0; k < theirs.size(); ++k) {
    if (4 * (positions_.size() + 1) > 3 * slots_.size())
      rehash(2 * slots_.size());
    if (k + kAhead < theirs.size())
      __builtin_prefetch(&slots_[position_hash(theirs[k + kAhead]) & (slots_.size() - 1)]);
    id[k] = insert(theirs[k], position_hash(theirs[k]));
  }
  ids_.reserve(ids_.size() + other.ids_.size());
  for (const Index k : other.ids_)
    ids_.push_back(id[k]);
}

void PositionTable::put_back(std::vector<Point>& positions) {
  flush();
  const std::size_t first = positions.size();
  positions.resize(first + ids_.size());
  for (std::size_t v = 0; v < ids_.size(); ++v)
    positions[first + v] = positions_[ids_[v]];
  *this = PositionTable();
}

std::size_t PositionTable::finish(Soup& soup) {
  flush();
  const std::size_t n = ids_.size();
  // As weld_repeated_vertices(): no weld of fewer than 2 faces, of a file where some vertex is
  // used by two corners (indexed), or where it removes nothing. Here, also none where some
  // vertex is used by no corner or a corner is out of range (left to the usual weld and checks).
  bool welds = soup.num_faces() >= 2 && soup.num_corners() == n && positions_.size() < n;
  if (welds) {
    std::vector<std::uint64_t> used((n + 63) / 64, 0);
    for (const Index v : soup.corner_vertices) {
      if (v >= n || (used[v / 64] >> (v % 64) & 1) != 0) {
        welds = false;
        break;
      }
      used[v / 64] |= std::uint64_t(1) << (v % 64);
    }
  }
  // Every vertex used by one corner: a group's first vertex is its position's first appearance,
  // and the survivors are numbered in that order, as the ids are.
  if (welds && most_sides_shared_when_welded(soup, ids_.data(), positions_.size())) {
    for (Index& v : soup.corner_vertices)
      v = ids_[v];
    soup.positions = std::move(positions_);
    *this = PositionTable();
    return n - soup.positions.size();
  }
  soup.positions.clear();
  put_back(soup.positions);
  return 0;
}

}  // namespace meshbridge::detail
