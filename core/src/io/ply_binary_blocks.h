// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The two shapes that almost every binary PLY body has, read as blocks of fixed size and cut
// into parts for several threads: vertices whose x, y, z are all float or all double, and faces
// that are all n-gons of one n (`list uchar int|uint vertex_indices`, nothing else).

#include "io/ply_header.h"
#include "meshbridge/soup.h"

#include <cstddef>
#include <vector>

namespace meshbridge::detail {

//! Fills `positions` (already sized to the element's count) from records of `stride` bytes at
//! `data`, coordinate c at byte `offset[c]` of its record, of `type` f32 or f64, byte-swapped
//! if `swap`. The caller checked that count * stride bytes are in the file.
void read_ply_fixed_vertices(const unsigned char* data, std::size_t stride,
                             const std::size_t offset[3], PlyScalar type, bool swap,
                             std::vector<Point>& positions, unsigned threads);

//! Appends `count` face records at `data` (`bytes` of the file left) to `soup` if every record
//! has the count of the first one, n >= 3, and every index is a valid vertex index (0 <= i <
//! kNoIndex); `index_type` is i32 or u32. Returns the bytes read, or 0 with `soup` unchanged if
//! the records are not all like that (the caller then reads them one by one and names the
//! first record that is wrong, as always).
std::size_t read_ply_uniform_faces(const unsigned char* data, std::size_t bytes, std::size_t count,
                                   PlyScalar index_type, bool swap, Soup& soup, unsigned threads);

}  // namespace meshbridge::detail
