// Runs independent tasks (writing one product file each) on a few threads at
// once: each task takes the next one not yet started, so a long task (a big
// compressed GeoTIFF) overlaps the short ones. The first exception a task
// throws is rethrown once every thread has stopped; tasks not yet started
// are then skipped.
//
// Example:
//   std::vector<std::function<void()>> tasks = {[&] { write_a(); }, [&] { write_b(); }};
//   ris::run_concurrently(tasks, 2);
#pragma once

#include <functional>
#include <vector>

namespace ris {

// threads <= 0: one per hardware thread; never more threads than tasks.
void run_concurrently(const std::vector<std::function<void()>>& tasks, int threads = 0);

}  // namespace ris
