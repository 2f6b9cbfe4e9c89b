// SPDX-License-Identifier: GPL-3.0-or-later
// The weld of STL corners. Where the time goes: one random probe of a table much larger than the
// caches per corner. So each slot is 8 bytes (a key's hash and its vertex: the table half as
// large as one of whole keys; the key compared is the vertex's position, mostly in cache as a
// file lists the faces around a vertex close together), the
// slots of the next block of corners are prefetched while this block is looked up (no branch
// between loading and prefetching), and the table lives on zero pages from the kernel (no
// memset) backed by huge pages where granted (few TLB misses). With several threads, each part
// of the file gets a table of its own; the parts are then merged in file order so that every
// vertex keeps its one-thread number.

#include "io/position_weld.h"

#include "io/huge_pages.h"
#include "parallel_parts.h"

#include <sys/mman.h>
#include <algorithm>
#include <cmath>
#include <new>
#include <utility>
#include <vector>

namespace meshbridge::detail {

namespace {

//! One table entry: a key's hash and its vertex + 1 (0: the slot is empty). The key itself is
//! the vertex's (its position, or the part's key list): half the table of whole keys, and a
//! probe whose hash matches reads a position that a mesh file mostly used a moment ago.
struct Slot {
  std::uint32_t hash;
  std::uint32_t id;
};
static_assert(sizeof(Slot) == 8, "eight slots per cache line");

bool same_key(const FloatKey& a, const FloatKey& b) {  // not std::array's ==, which calls memcmp
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

//! An open-addressing (linear probing) table from FloatKey to vertex, at most 5/8 full. Lookups
//! take `key_of(v)`: the key of vertex v.
class WeldTable {
 public:
  explicit WeldTable(std::size_t expected_vertices) {
    std::size_t capacity = 1024;
    while (capacity * 5 < expected_vertices * 8)
      capacity *= 2;
    allocate(capacity);
  }
  ~WeldTable() { release(); }
  WeldTable(WeldTable&& other) noexcept
      : slots_(std::exchange(other.slots_, nullptr)),
        bytes_(other.bytes_),
        mask_(other.mask_),
        size_(other.size_) {}
  WeldTable(const WeldTable&) = delete;
  WeldTable& operator=(const WeldTable&) = delete;
  WeldTable& operator=(WeldTable&&) = delete;

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return mask_ + 1; }
  void prefetch(std::uint32_t hash) const { __builtin_prefetch(&slots_[hash & mask_]); }

  //! Calls `visit(vertex)` for the vertices in slots [first, last), in slot order.
  template <class Visit>
  void for_each_in_slots(std::size_t first, std::size_t last, Visit&& visit) const {
    for (std::size_t s = first; s < last; ++s) {
      if (slots_[s].id != 0)
        visit(slots_[s].id - 1);
    }
  }

  //! The vertex of `key`, or kNoIndex.
  template <class KeyOf>
  Index find(const FloatKey& key, std::uint32_t hash, const KeyOf& key_of) const {
    for (std::size_t s = hash & mask_;; s = (s + 1) & mask_) {
      const Slot& slot = slots_[s];
      if (slot.id == 0)
        return kNoIndex;
      if (slot.hash == hash && same_key(key_of(slot.id - 1), key))
        return slot.id - 1;
    }
  }
  //! The vertex of `key`; absent, it is added as vertex size() and `added` is set (the caller
  //! makes `key_of(size() - 1)` its key before the next lookup).
  template <class KeyOf>
  Index find_or_add(const FloatKey& key, std::uint32_t hash, bool& added, const KeyOf& key_of) {
    for (std::size_t s = hash & mask_;; s = (s + 1) & mask_) {
      Slot& slot = slots_[s];
      if (slot.id == 0) {
        const Index v = static_cast<Index>(size_);
        slot = Slot{hash, v + 1};
        added = true;
        if (++size_ * 8 > capacity() * 5)
          grow();
        return v;
      }
      if (slot.hash == hash && same_key(key_of(slot.id - 1), key))
        return slot.id - 1;
    }
  }
  //! Gives the memory back; the table is unusable afterwards.
  void release() {
    if (slots_ != nullptr)
      ::munmap(slots_, bytes_);
    slots_ = nullptr;
  }

 private:
  void allocate(std::size_t capacity) {
    constexpr std::size_t kHuge = std::size_t(2) << 20;
    bytes_ = (capacity * sizeof(Slot) + kHuge - 1) / kHuge * kHuge;
    void* map = ::mmap(nullptr, bytes_, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (map == MAP_FAILED)
      throw std::bad_alloc();
    ::madvise(map, bytes_, MADV_HUGEPAGE);  // a hint: refused, the table works all the same
    slots_ = static_cast<Slot*>(map);
    mask_ = capacity - 1;
  }

  void grow() {
    Slot* old = slots_;
    const std::size_t old_bytes = bytes_, old_capacity = capacity();
    allocate(2 * old_capacity);
    for (std::size_t i = 0; i < old_capacity; ++i) {
      if (old[i].id == 0)
        continue;
      std::size_t s = old[i].hash & mask_;
      while (slots_[s].id != 0)
        s = (s + 1) & mask_;
      slots_[s] = old[i];
    }
    ::munmap(old, old_bytes);
  }

  Slot* slots_ = nullptr;
  std::size_t bytes_ = 0;
  std::size_t mask_ = 0;
  std::size_t size_ = 0;
};

//! Corners [first, last) of the file welded on their own.
struct Part {
  std::size_t first = 0, last = 0;
  WeldTable table;
  std::vector<FloatKey> keys;         //!< the part's vertices in order of first appearance in it
  std::vector<Index> vertex;          //!< part vertex -> soup vertex (parts after the first)
  std::vector<std::uint8_t> earlier;  //!< part vertex -> the first earlier part that has it
  std::vector<Index> corners;         //!< corner -> part vertex (parts after the first)

  // A closed triangle mesh has about half as many vertices as triangles.
  Part(std::size_t first_corner, std::size_t last_corner)
      : first(first_corner), last(last_corner), table((last_corner - first_corner) / 6) {}
};

constexpr std::size_t kBlock = 48;  // corners looked up while the next block's slots arrive
static_assert(kBlock % 3 == 0, "a block holds whole triangles (CornerKeys)");

Point to_point(const FloatKey& key) {
  float xyz[3];
  std::memcpy(xyz, key.data(), 12);
  return Point(xyz[0], xyz[1], xyz[2]);
}

//! The key of a position made by to_point() (exact: float -> double -> float).
FloatKey key_of_point(const Point& p) {
  return float_key(static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]));
}

//! Welds the part's corners into its table, appending each corner's part vertex to `out`. The
//! part's new positions go to `positions` if given (the first part: its numbers are the soup's),
//! else to `part.keys`. Every corner probes the table: a small cache of recent positions in front
//! of it (one probe less for most corners) made the weld 1.5-2.4x slower on the 2-core machines of
//! bench/results.md, its hits and misses being unpredictable branches and its slots a second random
//! read.
void weld_part(const CornerKeys& corner_keys, Part& part, std::vector<Index>& out,
               std::vector<Point>* positions) {
  FloatKey keys[2][kBlock];
  std::uint32_t hashes[2][kBlock];
  Index vertices[kBlock];  // the block's, appended to `out` at once (one pass over `out`)
  const auto load = [&](std::size_t c, int b) {
    const std::size_t n = std::min(kBlock, part.last - c);
    corner_keys(c, n, keys[b]);
    for (std::size_t i = 0; i < n; ++i) {
      hashes[b][i] = float_key_hash(keys[b][i]);
      part.table.prefetch(hashes[b][i]);
    }
    return n;
  };
  if (positions == nullptr)
    reserve_huge(part.keys, (part.last - part.first) / 5 + 16);
  std::size_t c = part.first;
  std::size_t n = c < part.last ? load(c, 0) : 0;
  for (int b = 0; n > 0; b ^= 1) {
    const std::size_t next = c + n;
    const std::size_t following = next < part.last ? load(next, b ^ 1) : 0;
    for (std::size_t i = 0; i < n; ++i) {
      const FloatKey& key = keys[b][i];
      bool added = false;
      Index v;
      if (positions != nullptr) {
        v = part.table.find_or_add(key, hashes[b][i], added,
                                   [positions](Index u) { return key_of_point((*positions)[u]); });
        if (added)
          positions->push_back(to_point(key));
      } else {
        v = part.table.find_or_add(key, hashes[b][i], added,
                                   [&part](Index u) { return part.keys[u]; });
        if (added)
          part.keys.push_back(key);
      }
      vertices[i] = v;
    }
    out.insert(out.end(), vertices, vertices + n);
    c = next;
    n = following;
  }
}

//! For every vertex of parts[1..]: the first earlier part that has its position, and its vertex
//! there (in `earlier` and `vertex`; kNoIndex where no earlier part has it). Only reads the
//! tables, so the `threads` threads each take a share of every part's vertices. Where the two
//! tables have the same capacity (parts of equal size), a key's probe in the earlier table starts
//! at about the slot it has in its own: walking the later table in slot order then reads the
//! earlier one nearly in order too, instead of one random slot per vertex.
//! `positions` are the first part's vertices (the soup's so far).
void find_in_earlier_parts(std::vector<Part>& parts, const std::vector<Point>& positions,
                           unsigned threads) {
  for (std::size_t k = 1; k < parts.size(); ++k) {
    parts[k].vertex.assign(parts[k].keys.size(), kNoIndex);
    parts[k].earlier.assign(parts[k].keys.size(), 0);
  }
  // One earlier part at a time, all threads on it, then the next: a vertex an earlier part has
  // is never looked up (and written) again by another thread at once, whichever way the threads
  // share the vertices of each (slot ranges where the tables match in size, index ranges where
  // they do not).
  for (std::size_t k = 1; k < parts.size(); ++k) {
    Part& part = parts[k];
    for (std::size_t j = 0; j < k; ++j) {
      const WeldTable& table = parts[j].table;
      const std::vector<FloatKey>& earlier_keys = parts[j].keys;
      const auto look_up = [&](const FloatKey& key, Index l) {
        if (part.vertex[l] != kNoIndex)  // an earlier part has it
          return;
        const std::uint32_t hash = float_key_hash(key);
        const Index found =
            j == 0 ? table.find(key, hash, [&](Index u) { return key_of_point(positions[u]); })
                   : table.find(key, hash, [&](Index u) { return earlier_keys[u]; });
        if (found != kNoIndex) {
          part.vertex[l] = found;
          part.earlier[l] = static_cast<std::uint8_t>(j);
        }
      };
      run_parts(threads, [&](unsigned t) {
        if (table.capacity() == part.table.capacity()) {
          const std::size_t slots = part.table.capacity();
          part.table.for_each_in_slots(part_begin(slots, threads, t),
                                       part_begin(slots, threads, t + 1),
                                       [&](Index l) { look_up(part.keys[l], l); });
          return;
        }
        const std::size_t first = part_begin(part.keys.size(), threads, t);
        const std::size_t last = part_begin(part.keys.size(), threads, t + 1);
        constexpr std::size_t kAhead = 32;  // slots on their way
        for (std::size_t l = first; l < last; ++l) {
          if (l + kAhead < last)
            table.prefetch(float_key_hash(part.keys[l + kAhead]));
          look_up(part.keys[l], static_cast<Index>(l));
        }
      });
    }
  }
}

//! Numbers the vertices of parts[1..] in file order after find_in_earlier_parts(): a position an
//! earlier part has keeps that part's number, a new one gets the next; appends the new positions
//! to `positions`.
void number_later_parts(std::vector<Part>& parts, std::vector<Point>& positions) {
  for (std::size_t k = 1; k < parts.size(); ++k) {
    Part& part = parts[k];
    for (std::size_t l = 0; l < part.keys.size(); ++l) {
      Index& v = part.vertex[l];
      if (v == kNoIndex) {
        v = static_cast<Index>(positions.size());
        positions.push_back(to_point(part.keys[l]));
      } else if (part.earlier[l] != 0) {
        v = parts[part.earlier[l]].vertex[v];
      }
    }
  }
}

}  // namespace

void weld_triangle_corners(std::size_t corners, const CornerKeys& corner_keys, Soup& soup,
                           unsigned threads) {
  const std::size_t triangles = corners / 3;
  // A part shorter than this costs more to start and merge than it saves.
  constexpr std::size_t kLeastPart = 3 * 8192;
  const unsigned n = static_cast<unsigned>(
      std::clamp<std::size_t>(corners / kLeastPart, 1, std::max(threads, 1u)));
  // The first part appends its corners' vertices to the soup; the others' are written in place
  // after the merge below.
  reserve_huge(soup.corner_vertices, corners);
  // A closed triangle mesh has about half as many vertices as triangles, a part border a few more.
  reserve_huge(soup.positions, corners / 5 + 16);
  std::vector<Part> parts;
  parts.reserve(n);
  for (unsigned k = 0; k < n; ++k)
    parts.emplace_back(3 * part_begin(triangles, n, k), 3 * part_begin(triangles, n, k + 1));
  run_parts(n, [&](unsigned k) {
    Part& part = parts[k];
    if (k == 0) {
      weld_part(corner_keys, part, soup.corner_vertices, &soup.positions);
      return;
    }
    reserve_huge(part.corners, part.last - part.first);
    weld_part(corner_keys, part, part.corners, nullptr);
  });
  find_in_earlier_parts(parts, soup.positions, n);
  number_later_parts(parts, soup.positions);
  for (Part& part : parts) {
    part.table.release();
    std::vector<FloatKey>().swap(part.keys);
  }
  // Corner c of the file is soup corner c: triangle f begins at corner 3f. With several parts,
  // the corners of the parts after the first and the face starts are written side by side.
  soup.face_begin.clear();
  reserve_huge(soup.face_begin, triangles + 1);
  if (n == 1) {
    for (std::size_t f = 0; f <= triangles; ++f)
      soup.face_begin.push_back(static_cast<Index>(3 * f));
    return;
  }
  soup.corner_vertices.resize(corners);
  soup.face_begin.resize(triangles + 1);
  const std::size_t later = parts[0].last;
  run_parts(n, [&](unsigned t) {
    std::size_t k = 1;
    const std::size_t last = later + part_begin(corners - later, n, t + 1);
    for (std::size_t c = later + part_begin(corners - later, n, t); c < last; ++c) {
      while (c >= parts[k].last)
        ++k;
      soup.corner_vertices[c] = parts[k].vertex[parts[k].corners[c - parts[k].first]];
    }
    const std::size_t last_face = part_begin(triangles + 1, n, t + 1);
    for (std::size_t f = part_begin(triangles + 1, n, t); f < last_face; ++f)
      soup.face_begin[f] = static_cast<Index>(3 * f);
  });
}

void restore_negative_zeros(Soup& soup, const CornerFloats& corner_floats) {
  std::vector<bool> seen(soup.num_vertices(), false);
  float xyz[3];
  for (std::size_t c = 0; c < soup.corner_vertices.size(); ++c) {
    const Index v = soup.corner_vertices[c];
    if (seen[v])
      continue;
    seen[v] = true;
    corner_floats(c, xyz);
    for (int k = 0; k < 3; ++k) {
      if (xyz[k] == 0 && std::signbit(xyz[k]))
        soup.positions[v][k] = -0.0;
    }
  }
}

}  // namespace meshbridge::detail
