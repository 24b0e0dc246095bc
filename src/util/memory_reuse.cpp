#include "ris/util/memory_reuse.h"

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace ris {

void keep_freed_memory_for_reuse() {
#if defined(__GLIBC__)
  // Blocks up to 1 GiB from the heap (not mmap), and never trim the heap's
  // free top (glibc mallopt(3)). Setting either fixes both, disabling glibc's
  // own adaptive thresholds.
  mallopt(M_MMAP_THRESHOLD, 1 << 30);
  mallopt(M_TRIM_THRESHOLD, -1);
#endif
}

}  // namespace ris
