#include "ris/util/memory_reuse.h"

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ris {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  // Never trim the heap's free top, and take no block from mmap (mallopt(3)):
  // an mmap()ed block goes back to the kernel on free and is faulted in
  // again, zeroed, on the next run; a 2000 x 2000 oblique run's 64 MB
  // terrain texels alone made page faults half of its time. (The mmap
  // threshold can be raised only to 32 MiB, so M_MMAP_MAX = 0 is what covers
  // larger blocks. If the heap cannot grow, glibc still falls back to mmap.)
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, -1);
  mallopt(M_MMAP_MAX, 0);
#endif
}

void share_freed_memory_between_threads(int arenas) {
#if defined(__GLIBC__)
  mallopt(M_ARENA_MAX, arenas);
#else
  (void)arenas;
#endif
}

}  // namespace ris
