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

// For a long-running process whose runs happen on different threads (the
// HTTP server's workers, `ris serve`): every thread takes memory from at most
// `arenas` malloc arenas, so a buffer freed after one run is reused by the
// next whichever thread runs it. Without this each thread's own arena keeps
// a copy of a run's working set and the resident memory grows with the
// number of threads that ever ran one. Call before starting threads.
void share_freed_memory_between_threads(int arenas);

}  // namespace ris
