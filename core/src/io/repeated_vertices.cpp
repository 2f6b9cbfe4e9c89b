// SPDX-License-Identifier: GPL-3.0-or-later
// The weld of a per-face-vertex soup. Where the time went (a 1M-triangle soup, shuffled): one
// random probe per vertex of a table far larger than the caches, then a random read of the
// position it held, one more random probe per polygon side for the edge count, and, as much again,
// the kernel zeroing the 150 MB of those tables. Now the used vertices are put into buckets of
// about 1000 by the top bits of their position's hash (two sequential passes), each bucket is
// welded in a table that stays in the L1 cache (its positions prefetched in bucket order), and the
// edge count sorts the sides by their lower vertex (of the welded, far fewer, vertices) in the
// buckets' memory: about 40 MB in all. Same result: a group's survivor is its first vertex.

#include "io/repeated_vertices.h"

#include "hash_mix.h"
#include "io/huge_pages.h"
#include "parallel_parts.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <memory>
#include <utility>
#include <vector>

namespace meshbridge::detail {

namespace {

std::uint64_t bits(double x) {
  if (x == 0)
    x = 0;  // -0 and +0 are one position
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

//! Only spreads the positions over buckets and slots (equal positions are compared whole): the
//! three coordinates' products with odd constants added (independent multiplications), one mix.
std::uint64_t position_hash(const Point& p) {
  return mix(bits(p[0]) * 0x9e3779b97f4a7c15ULL + bits(p[1]) * 0xc2b2ae3d27d4eb4fULL +
             bits(p[2]) * 0x165667b19e3779f9ULL);
}

//! A used vertex in its hash bucket.
struct Record {
  Index vertex;
  std::uint32_t hash;  //!< the low half of position_hash(): the bucket's table slot
};

//! An array of `n` elements left uninitialised (each is written before it is read), on huge pages
//! where granted.
template <class T>
std::unique_ptr<T[]> uninitialised(std::size_t n) {
  std::unique_ptr<T[]> data(new T[std::max<std::size_t>(n, 1)]);
  advise_huge_pages(data.get(), n * sizeof(T));
  return data;
}

constexpr std::size_t kBucketVertices = 1024;  // a bucket's table: 8 KiB, in the L1 cache
constexpr std::uint32_t kAhead = 32;           // records whose positions are on their way
constexpr std::size_t kLeastThreaded = std::size_t(1) << 16;  // fewer vertices: one thread

//! Where mark[v] == v (a used vertex), mark[v] becomes the first used vertex u <= v at v's
//! position with same(u, v) (vertices a < b at one position weld if same(a, b)); kNoIndex
//! (unused) stays. `used` vertices are marked. The records' memory is returned for reuse.
template <class Same>
std::unique_ptr<Record[]> mark_first_at_position(const Soup& soup, std::vector<Index>& mark,
                                                 std::size_t used, const Same& same) {
  const std::size_t n = soup.num_vertices();
  int bucket_bits = 0;
  while ((used >> bucket_bits) > kBucketVertices && bucket_bits < 20)
    ++bucket_bits;
  const auto bucket = [bucket_bits](std::uint64_t hash) {
    return bucket_bits == 0 ? std::size_t(0) : static_cast<std::size_t>(hash >> (64 - bucket_bits));
  };
  const std::size_t buckets = std::size_t(1) << bucket_bits;
  // Thread t counts and places the used vertices of its share of [0, n): its records follow those
  // of the threads before it in each bucket, so every bucket is in vertex order.
  const unsigned threads = used < kLeastThreaded ? 1u : std::clamp(worker_threads(), 1u, 8u);
  std::vector<std::size_t> at(threads * buckets, 0);  // thread t's next record in bucket b
  run_parts(threads, [&](unsigned t) {
    std::size_t* count = at.data() + t * buckets;
    for (std::size_t v = part_begin(n, threads, t); v < part_begin(n, threads, t + 1); ++v) {
      if (mark[v] != kNoIndex)
        ++count[bucket(position_hash(soup.positions[v]))];
    }
  });
  std::vector<std::size_t> begin(buckets + 1, 0);
  std::size_t largest = 0;
  for (std::size_t b = 0; b < buckets; ++b) {
    std::size_t next = begin[b];
    for (unsigned t = 0; t < threads; ++t)
      next += std::exchange(at[t * buckets + b], next);
    begin[b + 1] = next;
    largest = std::max(largest, next - begin[b]);
  }
  // The records of a bucket in vertex order: the first of a group first.
  auto records = uninitialised<Record>(used);
  run_parts(threads, [&](unsigned t) {
    std::size_t* next = at.data() + t * buckets;
    for (std::size_t v = part_begin(n, threads, t); v < part_begin(n, threads, t + 1); ++v) {
      if (mark[v] == kNoIndex)
        continue;
      const std::uint64_t hash = position_hash(soup.positions[v]);
      records[next[bucket(hash)]++] =
          Record{static_cast<Index>(v), static_cast<std::uint32_t>(hash)};
    }
  });
  std::size_t capacity = 16;
  while (capacity < 2 * largest)
    capacity *= 2;
  const Point* positions = soup.positions.data();
  // Each thread welds a share of the buckets in a table of its own.
  run_parts(threads, [&](unsigned t) {
    const std::uint32_t empty = static_cast<std::uint32_t>(-1);
    std::vector<std::uint32_t> table(capacity, empty);  // record - begin of the bucket
    for (std::size_t b = part_begin(buckets, threads, t); b < part_begin(buckets, threads, t + 1);
         ++b) {
      const Record* first = records.get() + begin[b];
      const std::uint32_t size = static_cast<std::uint32_t>(begin[b + 1] - begin[b]);
      std::size_t mask = 15;
      while (mask + 1 < 2 * std::size_t(size))
        mask = 2 * mask + 1;
      std::fill(table.begin(), table.begin() + static_cast<std::ptrdiff_t>(mask + 1), empty);
      for (std::uint32_t i = 0; i < std::min(kAhead, size); ++i)
        __builtin_prefetch(&positions[first[i].vertex]);
      for (std::uint32_t i = 0; i < size; ++i) {
        if (i + kAhead < size)
          __builtin_prefetch(&positions[first[i + kAhead].vertex]);
        const Record& r = first[i];
        const Point& p = positions[r.vertex];
        for (std::size_t slot = r.hash & mask;; slot = (slot + 1) & mask) {
          if (table[slot] == empty) {
            table[slot] = i;
            break;
          }
          const Record& q = first[table[slot]];
          if (q.hash != r.hash)
            continue;
          const Point& o = positions[q.vertex];
          if (o[0] == p[0] && o[1] == p[1] && o[2] == p[2] && same(q.vertex, r.vertex)) {
            mark[r.vertex] = q.vertex;
            break;
          }
        }
      }
    }
  });
  return records;
}

//! Whether at least half of the polygon sides (between different vertices: corner c at vertex
//! `vertex_of(c)`, `vertices` of them) share their edge with another side. `scratch` holds at least
//! as many Index as `soup` has corners.
template <class VertexOf>
bool most_sides_shared(const Soup& soup, const VertexOf& vertex_of, std::size_t vertices,
                       Index* scratch) {
  // The sides by their lower vertex, then the higher vertices of each lower one sorted.
  std::vector<Index> begin(vertices + 1, 0);
  const auto for_each_side = [&](auto&& side) {
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      const Index first = soup.face_begin[f], last = soup.face_begin[f + 1];
      if (first >= last)
        continue;
      const Index start = vertex_of(first);
      Index a = start;
      for (Index c = first; c < last; ++c) {
        const Index b = c + 1 == last ? start : vertex_of(c + 1);
        if (a != b)
          side(std::min(a, b), std::max(a, b));
        a = b;
      }
    }
  };
  for_each_side([&](Index low, Index) { ++begin[low + 1]; });
  for (std::size_t v = 0; v < vertices; ++v)
    begin[v + 1] += begin[v];
  const std::size_t sides = begin[vertices];
  Index* high = scratch;
  {
    std::vector<Index> end(begin.begin(), begin.end() - 1);
    for_each_side([&](Index low, Index h) { high[end[low]++] = h; });
  }
  std::size_t shared = 0;
  for (std::size_t v = 0; v < vertices; ++v) {
    Index* first = high + begin[v];
    Index* last = high + begin[v + 1];
    std::sort(first, last);
    for (Index* run = first; run != last;) {
      Index* next = run + 1;
      while (next != last && *next == *run)
        ++next;
      shared += next - run >= 2 ? static_cast<std::size_t>(next - run) : 0;
      run = next;
    }
  }
  return 2 * shared >= sides;
}

}  // namespace

bool most_sides_shared_when_welded(const Soup& soup, const Index* welded, std::size_t vertices) {
  const auto vertex_of = [&](Index c) { return welded[soup.corner_vertices[c]]; };
  const std::unique_ptr<Index[]> scratch = uninitialised<Index>(soup.num_corners());
  return most_sides_shared(soup, vertex_of, vertices, scratch.get());
}

std::size_t weld_repeated_vertices(Soup& soup, MeshAttributes* attributes) {
  const std::size_t n = soup.num_vertices();
  if (soup.num_faces() < 2)
    return 0;
  // Each vertex used by one corner at most, else the file indexes its vertices. A used vertex v
  // is marked v, an unused one kNoIndex.
  std::vector<Index> new_index(n, kNoIndex);
  for (Index v : soup.corner_vertices) {
    if (v >= n || new_index[v] != kNoIndex)
      return 0;
    new_index[v] = v;
  }
  const bool colors = attributes != nullptr && !attributes->vertex_colors.empty();
  const auto same_color = [&](Index a, Index b) {
    if (!colors)
      return true;
    const bool has_a =
        MeshAttributes::has_color(attributes->vertex_colors, attributes->vertex_color_missing, a);
    const bool has_b =
        MeshAttributes::has_color(attributes->vertex_colors, attributes->vertex_color_missing, b);
    return has_a == has_b && attributes->vertex_colors[a] == attributes->vertex_colors[b];
  };
  // Each used vertex marked with its survivor: the first at its position.
  const std::unique_ptr<Record[]> scratch =
      mark_first_at_position(soup, new_index, soup.num_corners(), same_color);
  // The survivors (and unused vertices) numbered in order; a welded vertex takes its survivor's
  // number, which comes before it.
  std::size_t removed = 0;
  Index next = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (new_index[v] == kNoIndex || new_index[v] == v) {
      new_index[v] = next++;
    } else {
      new_index[v] = new_index[new_index[v]];
      ++removed;
    }
  }
  if (removed == 0)
    return 0;
  // A per-face-vertex file of a surface: welded, most sides share their edge with another side
  // (every side of a closed mesh). Faces that would meet only at vertices (a repaired mesh whose
  // split vertices each carry one face: the two triangles of a bowtie) are a file's own choice:
  // left as they are. The records' memory (two Index a corner) holds the sides.
  static_assert(sizeof(Record) >= sizeof(Index), "a record holds a side");
  const auto welded = [&](Index c) { return new_index[soup.corner_vertices[c]]; };
  if (!most_sides_shared(soup, welded, next, reinterpret_cast<Index*>(scratch.get())))
    return 0;
  // Survivors move down to their number (never above where they are).
  Index moved = 0;
  for (std::size_t v = 0; v < n; ++v) {
    if (new_index[v] != moved)
      continue;  // welded into an earlier vertex
    soup.positions[moved] = soup.positions[v];
    if (colors) {
      attributes->vertex_colors[moved] = attributes->vertex_colors[v];
      if (!attributes->vertex_color_missing.empty())
        attributes->vertex_color_missing[moved] = attributes->vertex_color_missing[v];
    }
    ++moved;
  }
  soup.positions.resize(next);
  if (colors) {
    attributes->vertex_colors.resize(next);
    if (!attributes->vertex_color_missing.empty())
      attributes->vertex_color_missing.resize(next);
  }
  for (Index& v : soup.corner_vertices)
    v = new_index[v];
  return removed;
}

}  // namespace meshbridge::detail
