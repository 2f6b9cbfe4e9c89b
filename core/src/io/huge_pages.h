// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Large arrays that a reader fills once: asking the kernel for 2 MiB pages where it grants them
// (transparent huge pages in "madvise" mode), so filling 100 MB takes 50 page faults, not 25,000,
// and random access into it misses the TLB far less.

#include "meshbridge/soup.h"

#include <sys/mman.h>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace meshbridge::detail {

//! Hints that the whole 2 MiB pages inside [data, data + bytes) be huge pages. Call it before
//! the memory is first touched; only a hint (refused or not, the memory works the same).
inline void advise_huge_pages(const void* data, std::size_t bytes) {
  constexpr std::uintptr_t kHuge = std::uintptr_t(2) << 20;
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(data) + kHuge - 1) & ~(kHuge - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kHuge - 1);
  if (last > first)
    ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

//! Reserves `n` elements and hints huge pages for the part not yet touched.
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

//! Reserves a soup's three arrays for the counts a file declares (or a reader estimates), on huge
//! pages where granted.
inline void reserve_huge(Soup& soup, std::size_t vertices, std::size_t faces, std::size_t corners) {
  reserve_huge(soup.positions, vertices);
  reserve_huge(soup.face_begin, faces + 1);
  reserve_huge(soup.corner_vertices, corners);
}

}  // namespace meshbridge::detail
