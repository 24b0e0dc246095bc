#include "ris/util/concurrent_tasks.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>

namespace ris {
namespace {

TEST(ConcurrentTasks, RunsEveryTaskOnce) {
  for (int threads : {0, 1, 2, 5}) {
    std::vector<std::atomic<int>> runs(17);
    std::vector<std::function<void()>> tasks;
    for (std::size_t i = 0; i < runs.size(); ++i) tasks.emplace_back([&runs, i] { ++runs[i]; });
    run_concurrently(tasks, threads);
    for (const auto& r : runs) EXPECT_EQ(r.load(), 1) << threads;
  }
  run_concurrently({});  // nothing to do
}

TEST(ConcurrentTasks, RethrowsTheFirstErrorAfterEveryThreadStopped) {
  std::atomic<int> done{0};
  std::vector<std::function<void()>> tasks = {
      [&] { ++done; }, [] { throw std::runtime_error("disk full"); }, [&] { ++done; }};
  try {
    run_concurrently(tasks, 2);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "disk full");
  }
  EXPECT_LE(done.load(), 2);
}

}  // namespace
}  // namespace ris
