#include "ris/sim/slar_stream.h"
#include "build_paths.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "ris/perf/bench_setup.h"
#include "ris/scene/scene_io.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/run.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"
#include "stream_fixtures.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// A fractal scene with a no-data hole, a no-data edge strip, a tower (shadow
// and layover) and two categories.
Scene test_scene() {
  Scene s = test::rugged_test_scene();
  for (int r = 40; r < 60; ++r)
    for (int c = 10; c < 50; ++c) s.category[s.index(r, c)] = 3;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!s.valid[i]) s.category[i] = kNoDataCategory;
  return s;
}

RadarParams test_radar(const Scene& s, double heading_deg, bool auto_reference) {
  RadarParams r = test::stream_test_radar(s, heading_deg);
  r.reference.automatic = auto_reference;
  if (!auto_reference) {
    r.reference.mean_power_w = 1e-12;
    r.reference.greytone = 100.0;
  }
  return r;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The test scene written as a GeoTIFF in a temporary folder (the folder
// also takes the outputs).
struct SceneFile {
  Scene scene;
  test::TempDir dir;
  fs::path path = dir / "scene.tif";
  explicit SceneFile(Scene s = test_scene()) : scene(std::move(s)) {
    write_scene_geotiff(scene, path);
  }
};

// A larger scene for tracks off the axes (300 x 420 cells of 10 m): a block
// of lines reads several windows, and pass 1m several bands of rows and
// column tiles. A no-data hole and edge column, a tower, two categories.
Scene oblique_test_scene() {
  Scene s = make_bench_scene(300, 420, 10.0, 11);
  for (int r = 100; r < 130; ++r)
    for (int c = 200; c < 240; ++c) s.valid[s.index(r, c)] = 0;
  for (int r = 0; r < s.rows; ++r) s.valid[s.index(r, 0)] = 0;
  for (int r = 150; r < 156; ++r)
    for (int c = 300; c < 306; ++c) s.elevation_m[s.index(r, c)] = 150.0f;
  for (int r = 40; r < 200; ++r)
    for (int c = 10; c < 150; ++c) s.category[s.index(r, c)] = 3;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!s.valid[i]) s.category[i] = kNoDataCategory;
  return s;
}

// Every file of two output folders, byte for byte.
void expect_same_folders(const fs::path& a, const fs::path& b, const std::string& what) {
  const std::vector<std::string> na = files_in(a), nb = files_in(b);
  EXPECT_EQ(na, nb) << what;
  // Every product of write_slar_products: geocoded_grey.png only within
  // max_png_pixels (the folders are compared name by name above).
  EXPECT_TRUE(na.size() == 11u || na.size() == 12u) << what;
  for (const std::string& name : na) {
    if (!fs::exists(b / name)) continue;
    EXPECT_TRUE(test::read_file(a / name) == test::read_file(b / name)) << what << ": " << name;
  }
}

// The test: streamed and in-memory runs give identical bytes, for
// every axis-aligned heading (lines along rows or columns, either way; both
// look sides), block
// sizes that do and do not divide the line count, 1 and 2 threads, and both
// greytone references (the auto one takes the streamed exact median).
TEST(SlarStream, StreamedEqualsInMemoryByteForByte) {
  const SceneFile f;
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const int saved = omp_get_max_threads();
  for (double heading : {0.0, 90.0, 180.0, 270.0}) {
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const bool auto_ref = heading != 90.0;
      const RadarParams radar = test_radar(f.scene, heading, auto_ref);
      const SlarRunInfo info{f.path.string(), "r.toml", "test", 7, threads};
      const std::string tag = fmt::format("heading {} threads {}", heading, threads);
      const fs::path mem = f.dir / ("mem-" + tag);
      const SlarSimulation sim = simulate_slar(read, radar, src);
      // Pictures as GeoTIFFs (too large for PNG) in one case.
      SlarRunInfo info_tif = info;
      info_tif.max_png_pixels = heading == 180.0 ? 1000 : kMaxPngPixels;
      write_slar_products(mem, read, sim, render_slar(sim, info.seed), info_tif);
      EXPECT_EQ(fs::exists(mem / "ground_range.tif"), heading == 180.0);
      for (int block : {7, 16, 1000}) {
        SlarStreamOptions o;
        o.block_lines = block;
        o.quiet = true;
        const fs::path out = f.dir / fmt::format("stream-{}-{}", tag, block);
        const SlarStreamSummary sum = simulate_slar_streamed(f.path, radar, src, info_tif, out, o);
        EXPECT_EQ(sum.block_lines, std::min(block, sim.image.lines));
        expect_same_folders(mem, out, tag + fmt::format(" block {}", block));
        fs::remove_all(out);
      }
      fs::remove_all(mem);
    }
  }
  omp_set_num_threads(saved);
}

// The in-memory run's products of sim, then the streamed run of the same
// radar in blocks of 7, 16 and all lines on `threads` threads: every file
// the same bytes.
void expect_streams_as_in_memory(const SceneFile& f, const Scene& read, const SlarSimulation& sim,
                                 const RadarParams& radar, const Sigma0Source& src, int threads,
                                 const std::string& tag) {
  const SlarRunInfo info{f.path.string(), "r.toml", "test", 5, threads};
  const fs::path mem = f.dir / ("mem-" + tag);
  write_slar_products(mem, read, sim, render_slar(sim, info.seed), info);
  for (int block : {7, 16, sim.image.lines}) {
    SlarStreamOptions o;
    o.block_lines = block;
    o.quiet = true;
    const fs::path out = f.dir / fmt::format("stream-{}-{}", tag, block);
    const SlarStreamSummary sum = simulate_slar_streamed(f.path, radar, src, info, out, o);
    EXPECT_EQ(sum.block_lines, block);
    expect_same_folders(mem, out, tag + fmt::format(" block {}", block));
    fs::remove_all(out);
  }
  fs::remove_all(mem);
}

// Tracks at any heading stream (off the axes: slar_stream_oblique.h, its
// scene maps in pass 1m) with the in-memory run's bytes, every product
// file; blocks of 7, 16 and all lines, 1 and 2 threads.
TEST(SlarStream, ObliqueStreamedEqualsInMemoryByteForByte) {
  const SceneFile f(oblique_test_scene());
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const int saved = omp_get_max_threads();
  for (double heading : {0.0, 30.0, 45.0, 90.0, 200.0}) {
    const RadarParams radar = test_radar(f.scene, heading, heading != 45.0);
    const SlarSimulation sim = simulate_slar(read, radar, src);
    EXPECT_EQ(sim.geometry.direct_sampling, heading == 0.0 || heading == 90.0);
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      expect_streams_as_in_memory(f, read, sim, radar, src, threads,
                                  fmt::format("heading {} threads {}", heading, threads));
    }
  }
  omp_set_num_threads(saved);
}

// The free-disk check of a streamed track off the grid axes counts the
// temporaries pass 1 spills for pass 1m (lines x samples x 5 bytes; 0 along
// an axis at one line per cell): a disk ceiling (RIS_MAX_DISK_MB) above the products and the
// temporaries passes, one above the products alone but below both is
// refused, naming them and writing nothing.
TEST(SlarStream, DiskCheckCountsAnObliqueTracksTemporaries) {
  const SceneFile f(oblique_test_scene());
  const Scene grid = read_scene(f.path);
  const RadarParams along = test_radar(f.scene, 0.0, true);
  EXPECT_EQ(streamed_temporary_bytes(grid, along), 0);
  // Along an axis at another line spacing the samples' values are spilled.
  RadarParams spaced = along;
  spaced.azimuth_line_spacing_m = 0.5 * grid.dy_m;
  const SlarGeometry spaced_layout = slar_geometry_layout(
      grid, resolve_track(spaced.track, grid, spaced.source_file), spaced.azimuth_line_spacing_m);
  EXPECT_EQ(streamed_temporary_bytes(grid, spaced),
            std::int64_t(spaced_layout.lines) * spaced_layout.samples * 5);
  const RadarParams oblique = test_radar(f.scene, 30.0, true);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const SlarSimulation sim = simulate_slar(grid, oblique, src);
  const std::int64_t temporaries = streamed_temporary_bytes(grid, oblique);
  EXPECT_EQ(temporaries, std::int64_t(sim.geometry.lines) * sim.geometry.samples * 5);
  RadarParams coherent = oblique;  // the coherent SAR streams there too, with the same spills
  coherent.mode = RadarMode::sar;
  coherent.sar.coherent = true;
  EXPECT_EQ(streamed_temporary_bytes(grid, coherent), temporaries);
  const std::int64_t mib = std::int64_t(1) << 20;
  const std::int64_t products = std::int64_t(grid.rows) * grid.cols * 7;
  ASSERT_GT(temporaries, 2 * mib) << "the temporaries must outweigh the margin below";
  const auto run_under = [&](std::int64_t cap_mib, const fs::path& out) {
    RunRequest r;
    r.scene_path = f.path;
    r.radar = oblique;
    r.sigma0 = std::make_shared<test::CosineSigma0Source>(src);
    r.out_dir = out;
    r.stream = true;
    r.quiet = true;
    ::setenv("RIS_MAX_DISK_MB", std::to_string(cap_mib).c_str(), 1);
    try {
      run_simulation(r, {});
    } catch (...) {
      ::unsetenv("RIS_MAX_DISK_MB");
      throw;
    }
    ::unsetenv("RIS_MAX_DISK_MB");
  };
  EXPECT_NO_THROW(run_under((products + temporaries) / mib + 2, f.dir / "ok"));
  EXPECT_TRUE(fs::exists(f.dir / "ok" / "scene_mask.tif"));
  try {
    run_under(products / mib + 1, f.dir / "refused");  // above the products alone
    ADD_FAILURE() << "not refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("MiB of temporary files (a streamed track off the grid "
                                         "axes)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(f.dir / "refused"));
}

// The incoherent SAR streams too (range and azimuth windows, NESZ noise),
// along the axes and off them: the same bytes as in memory, metadata
// included.
TEST(SlarStream, StreamedSarEqualsInMemoryByteForByte) {
  const SceneFile f;
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  for (double heading : {0.0, 270.0, 30.0}) {  // 30: slar_stream_oblique.h
    RadarParams radar = test_radar(f.scene, heading, true);
    radar.mode = RadarMode::sar;
    radar.sar.range_resolution_m = 2.5 * radar.range_bin_m;
    radar.sar.azimuth_resolution_m = 14.0;
    radar.sar.azimuth_looks = 2;
    radar.sar.nesz = 1e-3;
    const SlarRunInfo info{f.path.string(), "sar.toml", "test", 3, 2};
    const std::string tag = fmt::format("sar heading {}", heading);
    const fs::path mem = f.dir / ("mem-" + tag);
    const SlarSimulation sim = simulate_slar(read, radar, src);
    ASSERT_FALSE(sim.noise_power_w.empty()) << tag;
    write_slar_products(mem, read, sim, render_slar(sim, info.seed), info);
    for (int block : {7, 1000}) {
      SlarStreamOptions o;
      o.block_lines = block;
      o.quiet = true;
      const fs::path out = f.dir / fmt::format("stream-{}-{}", tag, block);
      simulate_slar_streamed(f.path, radar, src, info, out, o);
      expect_same_folders(mem, out, tag + fmt::format(" block {}", block));
    }
  }
}

// A track along a grid axis whose lines are not one per cell row or column
// (spacing half and two and a half cells) streams too, its scene maps
// through pass 1m from each sample's spilled values, with the in-memory
// run's bytes (maps from the kept geometry, written top down): SLAR and
// incoherent SAR, headings 0 and 90 deg, blocks of 7, 16 and all lines, 1
// and 2 threads, on a scene of several 256-cell tiles each way.
TEST(SlarStream, SpacedGridAxisStreamedEqualsInMemoryByteForByte) {
  const SceneFile f(oblique_test_scene());
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const int saved = omp_get_max_threads();
  for (const bool sar : {false, true}) {
    for (double heading : {0.0, 90.0}) {
      for (double cells : {0.5, 2.5}) {
        RadarParams radar = test_radar(f.scene, heading, heading == 0.0);
        radar.azimuth_line_spacing_m = cells * f.scene.dy_m;
        if (sar) {
          radar.mode = RadarMode::sar;
          radar.sar.range_resolution_m = 2.5 * radar.range_bin_m;
          radar.sar.azimuth_resolution_m = 14.0;
          radar.sar.azimuth_looks = 2;
          radar.sar.nesz = 1e-3;
        }
        const SlarSimulation sim = simulate_slar(read, radar, src);
        ASSERT_TRUE(sim.geometry.direct_sampling);
        ASSERT_FALSE(fused_slar_applies(read, sim.geometry));
        for (int threads : {1, 2}) {
          omp_set_num_threads(threads);
          expect_streams_as_in_memory(f, read, sim, radar, src, threads,
                                      fmt::format("{} heading {} spacing {} cells threads {}",
                                                  sar ? "sar" : "slar", heading, cells, threads));
        }
      }
    }
  }
  omp_set_num_threads(saved);
}

// Bad input fails with an InputError and leaves no output folder (nor a
// staging folder) behind, including a failure found after blocks were
// written (a swath that misses the scene).
TEST(SlarStream, BadInputLeavesNoOutput) {
  const SceneFile f;
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const RadarParams radar = test_radar(f.scene, 0.0, true);
  const SlarRunInfo info{"x", "r.toml", "test", 1, 1};
  SlarStreamOptions o;
  o.quiet = true;
  const auto expect_fails = [&](const fs::path& scene, const RadarParams& r,
                                const std::string& expected) {
    const fs::path out = f.dir / "out";
    try {
      simulate_slar_streamed(scene, r, src, info, out, o);
      ADD_FAILURE() << "no error for " << expected;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(out));
  };
  expect_fails(f.dir / "missing.tif", radar, "missing.tif");
  test::write_file(f.dir / "text.tif", "not a raster\n");
  expect_fails(f.dir / "text.tif", radar, "text.tif");
  RadarParams far = radar;
  far.near_slant_range_m += 50000.0;  // the swath lies beyond the scene
  far.far_slant_range_m += 50000.0;
  expect_fails(f.path, far, "misses the scene");
  // Nothing but the inputs is left in the folder.
  std::vector<std::string> left = files_in(f.dir.path());
  EXPECT_EQ(left, (std::vector<std::string>{"scene.tif", "text.tif"}));
}

}  // namespace
}  // namespace ris
