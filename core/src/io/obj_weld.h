// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An OBJ file written per face vertex (each face repeating its own corners, DESIGN 8a soups)
// welded while it is read: each `v` record goes into a table of the distinct positions, so that
// the soup of every corner's own vertex (3 vertices a triangle, 24 bytes each) is never built
// and welded after. The result is the one weld_repeated_vertices() gives (repeated_vertices.h):
// where it would not weld, or the file is not a plain soup, the positions as read are put back
// and the usual weld runs.

#include "io/obj_parts.h"
#include "meshbridge/soup.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace meshbridge::detail {

//! The vertices of an OBJ file (or of one part of it) as the ids of their distinct positions,
//! numbered in order of first appearance. Where the time goes: one random probe per vertex into a
//! table a few MB large; vertices are added in batches, their slots prefetched, and each slot
//! holds its position, so that a probe reads one cache line.
class PositionTable {
 public:
  //! Whether the file looks written per face vertex (about one `v` record per face corner: from
  //! half as many to twice as many), so that welding while reading pays. An indexed mesh has far
  //! fewer (a closed triangle mesh about one per 6 corners), a point cloud far more.
  static bool pays_for(const RecordCounts& counts) {
    return counts.vertices >= 3 && 2 * counts.vertices >= counts.corners &&
           counts.vertices <= 2 * counts.corners;
  }

  void reserve(std::size_t vertices);
  //! Whether `p` can be added: a -0 coordinate cannot (the table takes the bits of a coordinate
  //! as its value, and -0 = +0 would weld two different bit patterns).
  static bool takes(const Point& p) {
    return !(p[0] == 0 && std::signbit(p[0])) && !(p[1] == 0 && std::signbit(p[1])) &&
           !(p[2] == 0 && std::signbit(p[2]));
  }
  //! Adds the next vertex, at `p` (takes(p)).
  void add(const Point& p) {
    if (slots_.empty())
      rehash(kBatch * 256);
    const std::uint64_t hash = position_hash(p);
    __builtin_prefetch(&slots_[hash & (slots_.size() - 1)]);
    pending_[pending_count_] = {p, hash};
    if (++pending_count_ == kBatch)
      flush();
  }
  std::size_t vertices() const { return ids_.size() + pending_count_; }
  //! Appends the vertices of `other` (the part of the file after these), their ids turned into
  //! this table's.
  void append(PositionTable& other);
  //! Appends the position of each vertex, as read, to `positions`, and empties the table.
  void put_back(std::vector<Point>& positions);

  //! With every vertex of the file added and `soup`'s corners holding file vertex numbers
  //! (0-based, unchecked): the soup weld_repeated_vertices() would make, if it welds (returns
  //! the vertices removed); else `soup` with its positions as read (returns 0) for the usual
  //! weld and checks. Colours are never in such a file (a coloured `v` stops the weld).
  std::size_t finish(Soup& soup);

 private:
  static std::uint64_t position_hash(const Point& p) {
    std::uint64_t b[3];
    std::memcpy(b, p.data(), sizeof b);
    std::uint64_t x =
        b[0] * 0x9e3779b97f4a7c15ULL + b[1] * 0xc2b2ae3d27d4eb4fULL + b[2] * 0x165667b19e3779f9ULL;
    x ^= x >> 30;  // the splitmix64 finaliser (hash_mix.h)
    x *= 0xbf58476d1ce4e5b9ULL;
    x ^= x >> 27;
    x *= 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
  }
  //! The id of `p`'s position, a new one if none.
  Index insert(const Point& p, std::uint64_t hash);
  //! Inserts the pending vertices.
  void flush();
  //! Makes the table `size` slots (a power of 2) large.
  void rehash(std::size_t size);

  struct alignas(32) Slot {
    double xyz[3];
    std::uint32_t hash;  //!< the high half of the position's hash
    std::uint32_t id;    //!< the position's id + 1, 0 for an empty slot
  };
  struct Pending {
    Point p;
    std::uint64_t hash;
  };
  static constexpr std::size_t kBatch = 16;  // vertices whose slots are on their way

  std::vector<Point> positions_;  // the distinct positions, in order of first appearance
  std::vector<Index> ids_;        // each vertex's position
  std::vector<Slot> slots_;       // open addressing, at most 3/4 full
  Pending pending_[kBatch];
  std::size_t pending_count_ = 0;
};

}  // namespace meshbridge::detail
