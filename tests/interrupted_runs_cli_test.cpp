// End-to-end: runs stopped from outside leave nothing behind (issue 37).
// SIGINT, SIGTERM and SIGHUP in the middle of a run remove its unfinished
// outputs, say so and exit 128 + the signal; what a SIGKILL leaves is
// removed by the next run writing the same output; a write past the
// file-size limit (ulimit -f, SIGXFSZ) is an error naming the output.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <signal.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "build_paths.h"
#include "test_util.h"

namespace ris {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;
using test::q;

// Entries of `dir` whose names hold ".partial-" (unfinished outputs).
int partial_count(const fs::path& dir) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().filename().string().find(".partial-") != std::string::npos) ++n;
  }
  return n;
}

// A ris command started in the background by the shell, its pid and exit
// status in files: stopped from the test as a user's kill would.
class Background {
 public:
  Background(const test::TempDir& dir, const std::string& args) : dir_(dir.path()) {
    const std::string cmd = "(" + std::string(test::ris_exe()) + " " + args + " > " +
                            q(dir_ / "log.txt") + " 2>&1 & echo $! > " + q(dir_ / "pid.txt") +
                            "; wait $!; echo $? > " + q(dir_ / "rc.tmp") + "; mv " +
                            q(dir_ / "rc.tmp") + " " + q(dir_ / "rc.txt") + ") &";
    EXPECT_EQ(std::system(cmd.c_str()), 0);
    for (int i = 0; i < 500 && pid_ <= 0; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      pid_ = std::atoi(test::read_file(dir_ / "pid.txt").c_str());
    }
  }
  // Waits until `ready` holds (at most 120 s); false when the run ended first.
  template <typename Ready>
  bool wait_for(Ready ready) {
    for (int i = 0; i < 12000; ++i) {
      if (ready()) return true;
      if (fs::exists(dir_ / "rc.txt")) return false;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  }
  void signal(int sig) const { ::kill(pid_, sig); }
  // The exit status (after at most 120 s) and the output.
  int status() {
    for (int i = 0; i < 12000 && !fs::exists(dir_ / "rc.txt"); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return std::atoi(test::read_file(dir_ / "rc.txt").c_str());
  }
  std::string output() const { return test::read_file(dir_ / "log.txt"); }

 private:
  fs::path dir_;
  int pid_ = 0;
};

// A run long enough to be stopped in the middle: a fractal scene of 3,000^2
// cells written to `out` (its temporary file appears beside it at once).
std::string long_run(const fs::path& out) {
  return "scene fractal --size 3000 --quiet -o " + q(out);
}

TEST(InterruptedRuns, StopSignalsRemoveTheUnfinishedOutputs) {
  for (const int sig : {SIGTERM, SIGINT, SIGHUP}) {
    test::TempDir dir;
    const fs::path work = dir / "work";
    fs::create_directory(work);
    Background run(dir, long_run(work / "scene.tif"));
    ASSERT_TRUE(run.wait_for([&] { return partial_count(work) > 0; })) << run.output();
    run.signal(sig);
    EXPECT_EQ(run.status(), 128 + sig) << run.output();
    EXPECT_THAT(run.output(), HasSubstr("stopped by SIG"));
    EXPECT_THAT(run.output(), HasSubstr("removed the unfinished output"));
    EXPECT_EQ(partial_count(work), 0);
    EXPECT_FALSE(fs::exists(work / "scene.tif"));
  }
}

TEST(InterruptedRuns, WhatSigkillLeavesIsRemovedByTheNextRun) {
  test::TempDir dir;
  const fs::path work = dir / "work";
  fs::create_directory(work);
  Background run(dir, long_run(work / "scene.tif"));
  ASSERT_TRUE(run.wait_for([&] { return partial_count(work) > 0; })) << run.output();
  run.signal(SIGKILL);
  EXPECT_NE(run.status(), 0);
  ASSERT_GE(partial_count(work), 1);  // SIGKILL: nothing could run
  // The owner is gone: the next run writing the same output removes it,
  // and says so.
  const auto r = test::run_ris("scene fractal --size 64 --quiet -o " + q(work / "scene.tif"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("left unfinished by an earlier run"));
  EXPECT_EQ(partial_count(work), 0);
  EXPECT_TRUE(fs::exists(work / "scene.tif"));
}

TEST(InterruptedRuns, ALiveOwnersStagingIsKept) {
  test::TempDir dir;
  // A name of the current form whose pid is this test's own and whose start
  // time is not: a pid reused by another process. And one whose owner is
  // alive (this process, the earlier form without a start time).
  const std::string me = std::to_string(::getpid());
  fs::create_directory(dir / (".out.partial-" + me + "-1-0"));
  fs::create_directory(dir / (".out.partial-" + me + "-0"));
  const auto r = test::run_ris("simulate --quiet --products slant_range --out " + q(dir / "out"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_FALSE(fs::exists(dir / (".out.partial-" + me + "-1-0"))) << r.output;
  EXPECT_TRUE(fs::exists(dir / (".out.partial-" + me + "-0")));
}

TEST(InterruptedRuns, TheFileSizeLimitIsAnErrorNamingTheOutput) {
  test::TempDir dir;
  const fs::path work = dir / "work";
  fs::create_directory(work);
  // 64 blocks of 512 bytes: the scene's GeoTIFF passes it early.
  test::write_file(dir / "run.sh", "ulimit -f 64\n" + std::string(test::ris_exe()) + " " +
                                       long_run(work / "scene.tif") + " > " + q(dir / "log.txt") +
                                       " 2>&1\n");
  const int status = std::system(("sh " + q(dir / "run.sh")).c_str());
  const std::string out = test::read_file(dir / "log.txt");
  ASSERT_TRUE(WIFEXITED(status)) << out;
  EXPECT_NE(WEXITSTATUS(status), 0) << out;
  EXPECT_NE(WEXITSTATUS(status), 128 + SIGXFSZ) << out;  // not killed without a word
  EXPECT_THAT(out, HasSubstr("scene.tif"));
  EXPECT_THAT(out, HasSubstr("file-size limit"));
  EXPECT_EQ(partial_count(work), 0) << out;
  EXPECT_FALSE(fs::exists(work / "scene.tif"));
}

}  // namespace
}  // namespace ris
