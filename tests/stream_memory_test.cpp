// Streaming's memory bound (issue 22; docs/performance.md "Streaming"): a
// streamed run holds blocks of lines, never the whole scene, so its peak
// resident memory does not grow with the scene's length. Measured on the
// process itself (its maximum resident set, from wait4), on scenes of 1000
// and 8000 rows of 1000 columns: in memory the longer one needs ~250 MiB more
// (measured 98 and 358 MiB), streamed in blocks of 32 lines it stays within a
// few tens of MiB of the short one (measured 80 and 106 MiB with GDAL's
// block cache held to 16 MiB).
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

#include "build_paths.h"
#include "test_util.h"

namespace ris {
namespace {

// Runs ris with the arguments; returns its peak resident set in MiB (-1 on
// failure).
double peak_rss_mib(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv;
    std::string exe = ris::test::ris_exe();
    argv.push_back(exe.data());
    std::vector<std::string> copy = args;
    for (std::string& a : copy) argv.push_back(a.data());
    argv.push_back(nullptr);
    setenv("GDAL_CACHEMAX", "16", 1);
    if (freopen("/dev/null", "w", stdout) == nullptr) _exit(126);
    execv(exe.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  rusage ru{};
  if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    return -1.0;
  }
  return double(ru.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

// Peak resident memory of streamed runs (blocks of 32 lines) on noise scenes
// of 1000 columns and 1000 and 8000 rows, with the radar's [track] ending in
// `track_extra`.
std::pair<double, double> streamed_peaks(const test::TempDir& dir, const std::string& track_extra) {
  const std::string radar = (dir / "radar.toml").string();
  test::write_file(radar, R"(mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
near_range = "5100 m"
far_range = "12000 m"
azimuth_beamwidth = "5 mrad"
[track]
altitude = "3000 m"
near_edge_distance = "4000 m"
)" + track_extra);
  double rss[2] = {0, 0};
  int k = 0;
  for (const char* rows : {"1000", "8000"}) {
    const std::string scene = (dir / (std::string("s") + rows + ".tif")).string();
    EXPECT_EQ(test::run_ris(std::string("scene fractal --generator noise --size 1000x") + rows +
                            " --cell-size 10 --relief 300 --category grass -o " + scene)
                  .exit_code,
              0);
    rss[k++] =
        peak_rss_mib({"simulate", "--quiet", "--scene", scene, "--radar", radar, "--backscatter",
                      std::string(ris::test::data_dir()) + "/backscatter/generic-terrain.toml",
                      "--block-lines", "32", "--out", (dir / (std::string("o") + rows)).string()});
    EXPECT_GT(rss[k - 1], 0.0) << rows << " rows: the run failed";
  }
  return {rss[0], rss[1]};
}

TEST(StreamMemory, PeakResidentMemoryDoesNotGrowWithTheScenesLength) {
  test::TempDir dir;
  const auto [short_mib, long_mib] = streamed_peaks(dir, "");
  const double rss[2] = {short_mib, long_mib};
  ASSERT_GT(rss[0], 0.0);
  ASSERT_GT(rss[1], 0.0);
  RecordProperty("peak_rss_mib_1000_rows", std::to_string(rss[0]));
  RecordProperty("peak_rss_mib_8000_rows", std::to_string(rss[1]));
  // 8 times the scene, 7 x 8 M cells more: an in-memory run grows by ~260 MiB.
  // What a streamed run keeps per line (the median's counts, per-line
  // statistics) is ~3 B per slant-range pixel: 7000 x 460 x 3 B = 10 MiB.
  EXPECT_LT(rss[1] - rss[0], 60.0) << rss[0] << " MiB -> " << rss[1] << " MiB";
  EXPECT_LT(rss[1], 200.0);
}

// The same for a track at 30 degrees (slar_stream_oblique.h): each block
// reads windows of the scene along its lines, and the scene maps come from
// the samples' values spilled to disk. Measured 98 and 124 MiB (the
// in-memory run of the long scene: 431 MiB). A line is longer on the longer
// scene (the scene's extent across the track grows with its length at 30
// degrees), so the blocks and the per-thread line scratch grow a little.
TEST(StreamMemory, ObliqueTrackPeakResidentMemoryDoesNotGrowWithTheScenesLength) {
  test::TempDir dir;
  const auto [short_mib, long_mib] = streamed_peaks(dir, "heading = \"30 deg\"\n");
  ASSERT_GT(short_mib, 0.0);
  ASSERT_GT(long_mib, 0.0);
  RecordProperty("peak_rss_mib_1000_rows", std::to_string(short_mib));
  RecordProperty("peak_rss_mib_8000_rows", std::to_string(long_mib));
  EXPECT_LT(long_mib - short_mib, 60.0) << short_mib << " MiB -> " << long_mib << " MiB";
  EXPECT_LT(long_mib, 200.0);
}

}  // namespace
}  // namespace ris
