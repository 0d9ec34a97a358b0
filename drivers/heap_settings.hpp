#pragma once
// glibc malloc settings for the driver: keep the large blocks of a Newton iteration (matrix
// and vector storage, the direct solver's workspace) in the heap and reuse them, instead of
// mapping fresh pages from the kernel for each and returning them at free (glibc's default
// maps blocks from 128 KiB on and trims the heap beyond 128 KiB of free top). On 2D Hertz
// level 3 (1 rank) this took the page faults from 38.6 k to 29.7 k and the CPU time down by
// ~5 % (docs/performance.md, "2D speed and the demo on 2 ranks"). Blocks from 64 MiB
// on are still mapped (and returned to the kernel when freed); at most 512 MiB of free heap
// is kept. A user who tunes malloc (GLIBC_TUNABLES set) keeps their settings.

#include <malloc.h>

#include <cstdlib>

namespace grout {

inline void keep_large_blocks_in_heap() {
  if (std::getenv("GLIBC_TUNABLES")) return;
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
}

}  // namespace grout
