// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/ply_binary_blocks.h"

#include "io/ply_sources.h"
#include "parallel_parts.h"

#include <atomic>
#include <cstdint>

namespace meshbridge::detail {

namespace {

// Fewer items than this per part cost more to start a thread for than they save.
constexpr std::size_t kLeastPart = 8192;

unsigned parts_for(std::size_t count, unsigned threads) {
  return static_cast<unsigned>(
      std::clamp<std::size_t>(count / kLeastPart, 1, std::max(threads, 1u)));
}

}  // namespace

void read_ply_fixed_vertices(const unsigned char* data, std::size_t stride,
                             const std::size_t offset[3], PlyScalar type, bool swap,
                             std::vector<Point>& positions, unsigned threads) {
  const std::size_t count = positions.size();
  const unsigned n = parts_for(count, threads);
  run_parts(n, [&](unsigned k) {
    const std::size_t last = part_begin(count, n, k + 1);
    const unsigned char* p = data + stride * part_begin(count, n, k);
    for (std::size_t v = part_begin(count, n, k); v < last; ++v, p += stride) {
      Point& point = positions[v];
      for (int c = 0; c < 3; ++c) {
        point[c] = type == PlyScalar::f32 ? double(load<float>(p + offset[c], swap))
                                          : load<double>(p + offset[c], swap);
      }
    }
  });
}

std::size_t read_ply_uniform_faces(const unsigned char* data, std::size_t bytes, std::size_t count,
                                   PlyScalar index_type, bool swap, Soup& soup, unsigned threads) {
  if (count == 0 || bytes == 0)
    return 0;
  const std::size_t arity = data[0];
  const std::size_t record = 1 + 4 * arity;
  if (arity < 3 || count > bytes / record)
    return 0;
  const std::size_t first_corner = soup.corner_vertices.size();
  const std::size_t first_face = soup.num_faces();
  if (first_corner + arity * count >= kNoIndex)
    return 0;
  soup.corner_vertices.resize(first_corner + arity * count);
  soup.face_begin.resize(first_face + count + 1);
  std::atomic<bool> uniform{true};
  const unsigned n = parts_for(count, threads);
  run_parts(n, [&](unsigned k) {
    const std::size_t last = part_begin(count, n, k + 1);
    std::size_t f = part_begin(count, n, k);
    const unsigned char* p = data + record * f;
    Index* out = soup.corner_vertices.data() + first_corner + arity * f;
    Index* begin = soup.face_begin.data() + first_face + 1;
    for (; f < last; ++f, p += record) {
      if (p[0] != arity) {
        uniform = false;
        return;
      }
      bool valid = true;
      for (std::size_t c = 0; c < arity; ++c) {
        const std::uint32_t bits = load<std::uint32_t>(p + 1 + 4 * c, swap);
        // i32: negative is invalid; u32: only kNoIndex (0xFFFFFFFF) is.
        valid &= index_type == PlyScalar::i32 ? bits < 0x80000000u : bits != kNoIndex;
        *out++ = bits;
      }
      if (!valid) {
        uniform = false;
        return;
      }
      begin[f] = static_cast<Index>(first_corner + arity * (f + 1));
    }
  });
  if (!uniform) {
    soup.corner_vertices.resize(first_corner);
    soup.face_begin.resize(first_face + 1);
    return 0;
  }
  return record * count;
}

}  // namespace meshbridge::detail
