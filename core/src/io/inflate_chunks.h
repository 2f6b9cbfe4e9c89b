// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A deflated zip part inflated in chunks by Intel ISA-L's igzip (Debian libisal-dev), each chunk
// handed on as soon as it is out: no buffer for the whole text, so no fresh pages for the kernel
// to clear, and the text is read while it is still in the cache. With two threads the next
// chunks are inflated while the reader reads one. ISA-L inflates the 3MF model parts of
// bench/results.md in about 0.6x of libdeflate's CPU time (section 17).

#include <cstddef>
#include <cstdint>
#include <functional>

namespace meshbridge::detail {

//! Writable bytes before every chunk's first byte: a reader may put there the unread end of the
//! previous chunk (an element the chunk border cut), to read it whole with the new chunk.
constexpr std::size_t kChunkHeadroom = 4096;

//! Reads one chunk of inflated text: `size` bytes at `data` (kChunkHeadroom writable bytes
//! before it), `last` for the final one (which may be empty); false to stop.
using ChunkReader = std::function<bool(char* data, std::size_t size, bool last)>;

//! True when MeshBridge was built with ISA-L (else inflate_in_chunks() returns false at once).
bool can_inflate_in_chunks();

//! Inflates the raw deflate stream `compressed` (`size` bytes), which must give exactly
//! `inflated_size` bytes of CRC-32 `crc`, handing them to `reader` in chunks of 256 KiB, in
//! order. On a thread of its own when worker_threads() > 1, `reader` on the calling thread.
//! False when the stream is broken, its size or CRC differ, or `reader` returned false or
//! threw: a reader must not keep what it read unless this returns true.
bool inflate_in_chunks(const unsigned char* compressed, std::size_t size,
                       std::uint64_t inflated_size, std::uint32_t crc, const ChunkReader& reader);

}  // namespace meshbridge::detail
