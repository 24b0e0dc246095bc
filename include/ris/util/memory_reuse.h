// Keeps freed memory in the process for reuse (glibc malloc tuning), so that
// repeated simulations (the benchmark, an interactive session) do not hand
// their large buffers back to the kernel and fault them in again, zeroed,
// page by page on the next run: on this machine's virtual CPUs the page
// faults cost as much as a third of a 1000 x 1000 scene's simulation.
//
// Every block is then taken from the heap instead of a fresh mmap(), and the
// heap is not trimmed; the peak resident memory is what it would be anyway
// (the largest run's working set: freed blocks are reused, not added to).
// Call once, early in main(). Elsewhere than glibc it does nothing.
//
// Example:
//   int main() { ris::keep_freed_memory_for_reuse(); ... }
#pragma once

namespace ris {

void keep_freed_memory_for_reuse();

}  // namespace ris
