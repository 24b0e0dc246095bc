#include "ris/util/memory_reuse.h"

#include <cstdlib>  // defines __GLIBC__ on glibc

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ris {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  // Blocks up to 32 MiB (glibc's largest allowed threshold: HEAP_MAX_SIZE / 2
  // on 64-bit) from the heap, not mmap, and never trim the heap's free top
  // (mallopt(3)). Setting either fixes both, disabling glibc's own adaptive
  // thresholds. Larger blocks are still mmap()ed and returned on free.
  mallopt(M_MMAP_THRESHOLD, 32 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, -1);
#endif
}

}  // namespace ris
