// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Hands the heap's free pages back to the operating system. glibc keeps freed blocks below its
// (adaptive) mmap threshold in the heap, still resident; after a repair has freed its working
// arrays, what the command allocates next (the output file's buffers, the re-read of an STL)
// would otherwise land beside those pages instead of in them, and the process would hold both.
// The command-line tool's choice, after each repair; the library leaves its callers' heap alone.
// A no-op with other C libraries.

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace meshbridge::cli {

inline void release_free_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace meshbridge::cli
