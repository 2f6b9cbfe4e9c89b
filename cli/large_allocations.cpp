// SPDX-License-Identifier: GPL-3.0-or-later
// The command-line tool's global operator new: every block of 2 MiB or more starts on a 2 MiB
// boundary and is offered 2 MiB pages (transparent huge pages in "madvise" mode, Debian's default)
// before it is first touched; only its last partial 2 MiB stays on small pages, so nothing is
// rounded up in memory.
//
// Why: a check or repair of a 1M-triangle file fills a few hundred MB of fresh arrays (the
// grouping of the sides, the pairing, the fans, the output); on 4 KiB pages that is tens of
// thousands of page faults, and on a virtual machine each fault costs far more than the work on
// the page (measured: about half the CPU time of `meshbridge check` on a clean 1M torus went to
// faulting in and clearing pages). With 2 MiB pages it is a few hundred faults. Starting blocks
// on a 2 MiB boundary matters: unaligned, the head and tail of each block (up to 2 MiB each)
// stayed on small pages, and those still made three quarters of check's page faults.
//
// Only a hint: where the kernel refuses (THP "never", or not available) memory works the same.
// The library itself does not replace operator new; embedding applications choose their own
// allocator. Blocks come from malloc or posix_memalign and are released with free (the default
// operator delete), so nothing else changes.

// Not under AddressSanitizer: its operator delete checks that each block came from its own
// operator new (alloc-dealloc-mismatch), and the hint is only about speed.
#if defined(__SANITIZE_ADDRESS__)
#define MESHBRIDGE_REPLACE_OPERATOR_NEW 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MESHBRIDGE_REPLACE_OPERATOR_NEW 0
#endif
#endif
#ifndef MESHBRIDGE_REPLACE_OPERATOR_NEW
#define MESHBRIDGE_REPLACE_OPERATOR_NEW 1
#endif

#if MESHBRIDGE_REPLACE_OPERATOR_NEW

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>

namespace {

constexpr std::size_t kHugePage = std::size_t(2) << 20;

void* allocate(std::size_t bytes) {
  if (bytes < kHugePage)
    return std::malloc(bytes == 0 ? 1 : bytes);
  // Aligned to 2 MiB, so that no part of the block's start falls on small pages. posix_memalign,
  // not aligned_alloc: C11's aligned_alloc wants the size a multiple of the alignment (and
  // AddressSanitizer enforces that).
  void* block = nullptr;
  if (::posix_memalign(&block, kHugePage, bytes) != 0)
    block = nullptr;
  if (block != nullptr) {
    const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(block);
    const std::uintptr_t last = (begin + bytes) & ~(kHugePage - 1);
    if (last > begin)
      ::madvise(block, last - begin, MADV_HUGEPAGE);
  }
  return block;
}

}  // namespace

// The other replaceable forms (nothrow, arrays) call this one in libstdc++; the aligned forms
// keep their own allocation (none of the large arrays is over-aligned).
void* operator new(std::size_t bytes) {
  void* block = allocate(bytes);
  if (block == nullptr)
    throw std::bad_alloc();
  return block;
}

void* operator new[](std::size_t bytes) {
  void* block = allocate(bytes);
  if (block == nullptr)
    throw std::bad_alloc();
  return block;
}

void* operator new(std::size_t bytes, const std::nothrow_t&) noexcept {
  return allocate(bytes);
}

void* operator new[](std::size_t bytes, const std::nothrow_t&) noexcept {
  return allocate(bytes);
}

#endif  // MESHBRIDGE_REPLACE_OPERATOR_NEW
