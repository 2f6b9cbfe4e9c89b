// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/inflate_chunks.h"

#include "parallel_parts.h"

#ifdef MESHBRIDGE_WITH_ISAL
#include <isa-l/crc.h>
#include <isa-l/igzip_lib.h>
#endif

#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace meshbridge::detail {

#ifdef MESHBRIDGE_WITH_ISAL

namespace {

// 256 KiB a chunk: faster than 1 or 4 MiB (the text is read from the cache); 4 chunks in the
// ring, so the inflater runs ahead while the reader is slower on a chunk.
constexpr std::size_t kChunk = std::size_t(1) << 18;
constexpr std::size_t kSlots = 4;

// ISA-L's state (about 35 KiB) and the stream being inflated.
class Inflater {
 public:
  // `crc`: ISA-L computes the CRC-32 as it inflates (else the caller does, is_whole() says).
  Inflater(const unsigned char* compressed, std::size_t size, std::uint64_t inflated_size, bool crc)
      : state_(new inflate_state), inflated_size_(inflated_size) {
    isal_inflate_init(state_.get());
    // The CRC-32 of zip (and gzip) as it inflates, or none (raw deflate).
    state_->crc_flag = crc ? ISAL_GZIP_NO_HDR : ISAL_DEFLATE;
    state_->next_in = const_cast<unsigned char*>(compressed);
    state_->avail_in = static_cast<std::uint32_t>(size);
  }
  // Inflates the next chunk into `out` (kChunk bytes): its size, and `last` when the stream
  // ended in it; false when the stream is broken or longer than it said.
  bool next(unsigned char* out, std::size_t& size, bool& last) {
    state_->next_out = out;
    state_->avail_out = static_cast<std::uint32_t>(kChunk);
    const std::uint32_t before = state_->total_out;
    if (isal_inflate(state_.get()) != ISAL_DECOMP_OK)
      return false;
    size = kChunk - state_->avail_out;
    last = state_->block_state == ISAL_BLOCK_FINISH;
    out_ += size;
    // No progress before the end: the input ran out (a truncated stream).
    if (size == 0 && !last && state_->total_out == before)
      return false;
    return out_ <= inflated_size_;
  }
  //! True when the whole stream came out, of CRC-32 `crc` (`computed`: the caller's CRC of it,
  //! where ISA-L computed none).
  bool is_whole(std::uint32_t crc, std::uint32_t computed) const {
    return out_ == inflated_size_ &&
           (state_->crc_flag == ISAL_DEFLATE ? computed : state_->crc) == crc;
  }

 private:
  std::unique_ptr<inflate_state> state_;
  std::uint64_t inflated_size_;
  std::uint64_t out_ = 0;
};

// One chunk's buffer: the headroom, then the chunk.
struct Slot {
  std::unique_ptr<char[]> bytes{new char[kChunkHeadroom + kChunk]};
  char* data() { return bytes.get() + kChunkHeadroom; }
  std::size_t size = 0;
  bool last = false;
};

bool inflate_on_one_thread(Inflater& inflater, std::uint32_t crc, const ChunkReader& reader) {
  Slot slot;
  for (bool last = false; !last;) {
    if (!inflater.next(reinterpret_cast<unsigned char*>(slot.data()), slot.size, last) ||
        !reader(slot.data(), slot.size, last)) {
      return false;
    }
  }
  return inflater.is_whole(crc, 0);
}

// The inflater on a thread of its own, filling a ring of slots; the reader on this one, which
// also computes the CRC-32 of each chunk before it reads it (the inflater is the slower of the
// two: 1M-triangle parts, 3 % of its time).
bool inflate_on_two_threads(Inflater& inflater, std::uint32_t crc, const ChunkReader& reader) {
  std::vector<Slot> slots(kSlots);
  std::mutex mutex;
  std::condition_variable changed;
  std::size_t filled = 0, read = 0;  // chunks inflated, chunks read
  bool broken = false, stop = false, ended = false;
  std::thread thread([&] {
    for (std::size_t k = 0;; ++k) {
      {
        std::unique_lock<std::mutex> lock(mutex);
        changed.wait(lock, [&] { return stop || k - read < kSlots; });
        if (stop)
          return;
      }
      Slot& slot = slots[k % kSlots];
      bool last = false;
      const bool ok = inflater.next(reinterpret_cast<unsigned char*>(slot.data()), slot.size, last);
      slot.last = last;
      std::lock_guard<std::mutex> lock(mutex);
      if (!ok)
        broken = true;
      else
        filled = k + 1;
      ended = !ok || last;
      changed.notify_all();
      if (ended)
        return;
    }
  });
  bool ok = true;
  std::uint32_t computed = 0;
  for (std::size_t k = 0; ok; ++k) {
    {
      std::unique_lock<std::mutex> lock(mutex);
      changed.wait(lock, [&] { return filled > k || broken; });
      if (filled <= k)
        break;  // broken
    }
    Slot& slot = slots[k % kSlots];
    computed =
        crc32_gzip_refl(computed, reinterpret_cast<const unsigned char*>(slot.data()), slot.size);
    try {
      ok = reader(slot.data(), slot.size, slot.last);
    } catch (...) {
      ok = false;
    }
    const bool last = slot.last;
    {
      std::lock_guard<std::mutex> lock(mutex);
      read = k + 1;
      stop = !ok;
      changed.notify_all();
    }
    if (last)
      break;
  }
  thread.join();
  return ok && !broken && inflater.is_whole(crc, computed);
}

}  // namespace

bool can_inflate_in_chunks() {
  return true;
}

bool inflate_in_chunks(const unsigned char* compressed, std::size_t size,
                       std::uint64_t inflated_size, std::uint32_t crc, const ChunkReader& reader) {
  if (size > 0xffffffffu)
    return false;  // ISA-L counts input in 32 bits
  const bool two_threads = worker_threads() > 1;
  Inflater inflater(compressed, size, inflated_size, !two_threads);
  return two_threads ? inflate_on_two_threads(inflater, crc, reader)
                     : inflate_on_one_thread(inflater, crc, reader);
}

#else

bool can_inflate_in_chunks() {
  return false;
}

bool inflate_in_chunks(const unsigned char*, std::size_t, std::uint64_t, std::uint32_t,
                       const ChunkReader&) {
  return false;
}

#endif

}  // namespace meshbridge::detail
