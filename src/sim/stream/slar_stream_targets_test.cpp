#include "sim/stream/slar_stream_targets.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "build_paths.h"
#include "ris/perf/bench_setup.h"
#include "ris/scene/scene_io.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/point_target_irf.h"
#include "ris/sim/sar_coherent.h"
#include "ris/sim/slar_stream.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"
#include "stream_fixtures.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// The rugged scene (no-data hole and edge, a tower) of the streamed tests,
// written as a GeoTIFF; its folder takes the outputs.
struct SceneFile {
  Scene scene = test::rugged_test_scene();
  test::TempDir dir;
  fs::path path = dir / "scene.tif";
  SceneFile() {
    for (std::size_t i = 0; i < scene.size(); ++i)
      if (!scene.valid[i]) scene.category[i] = kNoDataCategory;
    write_scene_geotiff(scene, path);
  }
};

RadarParams targets_radar(const Scene& s, double heading_deg, bool sar) {
  RadarParams r = test::stream_test_radar(s, heading_deg);
  if (sar) {
    r.mode = RadarMode::sar;
    r.sar.range_resolution_m = 2.5 * r.range_bin_m;
    r.sar.azimuth_resolution_m = 14.0;
    r.sar.azimuth_looks = 2;
    r.sar.nesz = 1e-3;
  }
  return r;
}

// Targets over the scene (x 0..900 m, y 0..600 m): in the open, near the
// scene's edges (their measurement windows clipped), behind and on the
// tower (rows 28-32, columns 60-64), and two on one line.
std::vector<PointTarget> scene_targets() {
  const double xy[][2] = {{200.0, 300.0}, {455.0, 12.0},  {455.0, 588.0}, {880.0, 450.0},
                          {700.0, 295.0}, {625.0, 295.0}, {300.0, 150.0}, {500.0, 150.0},
                          {40.0, 40.0},   {760.0, 300.0}, {622.0, 262.0}};
  std::vector<PointTarget> out;
  for (std::size_t k = 0; k < std::size(xy); ++k) {
    PointTarget t;
    t.name = fmt::format("t{}", k);
    t.x_m = xy[k][0];
    t.y_m = xy[k][1];
    t.height_m = k % 3 == 0 ? 2.0 : 0.0;
    t.rcs_m2 = 1000.0 * double(k + 1);
    t.source_file = "targets.toml";
    t.index = static_cast<int>(k);
    out.push_back(t);
  }
  return out;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

void expect_same_folders(const fs::path& a, const fs::path& b, const std::string& what) {
  const std::vector<std::string> na = files_in(a), nb = files_in(b);
  EXPECT_EQ(na, nb) << what;
  EXPECT_EQ(na.size(), 12u) << what;
  for (const std::string& name : na) {
    if (!fs::exists(b / name)) continue;
    EXPECT_TRUE(test::read_file(a / name) == test::read_file(b / name)) << what << ": " << name;
  }
}

// The in-memory run with targets, its products as `ris simulate` writes
// them (the measurements in metadata.json).
SlarSimulation write_in_memory(const Scene& scene, const RadarParams& radar,
                               const Sigma0Source& src, const SlarRunInfo& info,
                               const std::vector<PointTarget>& targets, const fs::path& out) {
  SlarOptions o;
  o.targets = targets;
  SlarSimulation sim = simulate_slar(scene, radar, src, o);
  const SlarPictures pic = render_slar(sim, info.seed);
  const nlohmann::json extra = {
      {"point_targets",
       point_target_irf_json(measure_point_targets(sim, pic, false), sim, "targets.toml", false)}};
  write_slar_products(out, scene, sim, pic, info, extra);
  return sim;
}

// Streams the scene with `targets` in blocks of 7, 16 and all lines and
// checks each run's folder against `mem` byte for byte; check(summary,
// what) adds the test's own expectations.
void expect_streamed_blocks_equal(
    const SceneFile& f, const RadarParams& radar, const Sigma0Source& src, const SlarRunInfo& info,
    const std::vector<PointTarget>& targets, const fs::path& mem, const std::string& tag,
    const std::function<void(const SlarStreamSummary&, const std::string&)>& check) {
  for (int block : {7, 16, 1000}) {
    SlarStreamOptions o;
    o.block_lines = block;
    o.quiet = true;
    o.targets = targets;
    o.targets_file = "targets.toml";
    const fs::path out = f.dir / "stream";
    const SlarStreamSummary sum = simulate_slar_streamed(f.path, radar, src, info, out, o);
    const std::string what = tag + fmt::format(" block {}", block);
    expect_same_folders(mem, out, what);
    check(sum, what);
    fs::remove_all(out);
  }
}

// Streamed == in memory, byte for byte, with point targets: SLAR along and
// across the grid, the incoherent SAR; blocks of 7, 16 and all lines; 1 and
// 2 threads. The targets' returns, hidden names and measurements too.
TEST(SlarStreamTargets, StreamedEqualsInMemoryByteForByte) {
  const SceneFile f;
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const std::vector<PointTarget> targets = scene_targets();
  const int saved = omp_get_max_threads();
  struct Case {
    double heading;
    bool sar;
  };
  for (const Case c : {Case{0.0, false}, Case{270.0, false}, Case{180.0, true}}) {
    const RadarParams radar = targets_radar(f.scene, c.heading, c.sar);
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const SlarRunInfo info{f.path.string(), "r.toml", "test", 5, threads};
      const std::string tag =
          fmt::format("heading {} sar {} threads {}", c.heading, c.sar, threads);
      const fs::path mem = f.dir / "mem";
      const SlarSimulation sim = write_in_memory(read, radar, src, info, targets, mem);
      EXPECT_GE(sim.point_returns.size(), 3u) << tag;
      EXPECT_GE(sim.hidden_targets.size(), 1u) << tag;
      expect_streamed_blocks_equal(
          f, radar, src, info, targets, mem, tag,
          [&](const SlarStreamSummary& sum, const std::string& what) {
            EXPECT_EQ(sum.sim.hidden_targets, sim.hidden_targets) << what;
            ASSERT_EQ(sum.sim.point_returns.size(), sim.point_returns.size()) << what;
            EXPECT_EQ(sum.irfs.size(),
                      measure_point_targets(sim, render_slar(sim, 5), false).size())
                << what;
          });
      fs::remove_all(mem);
    }
  }
  omp_set_num_threads(saved);
}

// The coherent SAR with point targets (measured on the intensity) at each
// heading, in memory, then streamed in blocks of 7, 16 and all lines, with
// 1 and 2 threads: the same bytes, hidden targets and measurements. Returns
// the hidden targets over the headings.
std::size_t expect_coherent_streamed_equal(const std::vector<double>& headings, bool along_axis,
                                           double cells_a_line = 1.0) {
  const SceneFile f;
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const std::vector<PointTarget> targets = scene_targets();
  const int saved = omp_get_max_threads();
  std::size_t hidden = 0;
  for (double heading : headings) {
    RadarParams radar = targets_radar(f.scene, heading, true);
    radar.sar.coherent = true;
    radar.sar.range_looks = 2;
    if (cells_a_line != 1.0) radar.azimuth_line_spacing_m = cells_a_line * f.scene.dy_m;
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const SlarRunInfo info{f.path.string(), "r.toml", "test", 9, threads};
      const std::string tag = fmt::format("coherent heading {} cells a line {} threads {}", heading,
                                          cells_a_line, threads);
      const fs::path mem = f.dir / "mem";
      SlarOptions mo;
      mo.targets = targets;
      const SlarSimulation sim = simulate_slar(read, radar, src, mo);
      EXPECT_EQ(sim.geometry.direct_sampling, along_axis) << tag;
      hidden += sim.hidden_targets.size();
      const SlarPictures pic = render_slar(sim, info.seed, coherent_sar_intensity(sim, info.seed));
      const std::vector<PointTargetIrf> irfs = measure_point_targets(sim, pic, true);
      EXPECT_GE(irfs.size(), along_axis ? 3u : 1u) << tag;
      write_slar_products(
          mem, read, sim, pic, info,
          {{"point_targets", point_target_irf_json(irfs, sim, "targets.toml", true)}});
      expect_streamed_blocks_equal(f, radar, src, info, targets, mem, tag,
                                   [&](const SlarStreamSummary& sum, const std::string& what) {
                                     EXPECT_EQ(sum.sim.hidden_targets, sim.hidden_targets) << what;
                                     EXPECT_EQ(sum.irfs.size(), irfs.size()) << what;
                                   });
      fs::remove_all(mem);
    }
  }
  omp_set_num_threads(saved);
  return hidden;
}

// The coherent SAR streams with blocks overlapping by the azimuth
// response's half-length (src/sim/stream/sar_coherent_stream.h): with point
// targets (measured on the intensity), along and across the grid, blocks
// of 7, 16 and all lines, 1 and 2 threads, the same bytes as in memory.
TEST(SlarStreamTargets, CoherentSarStreamedEqualsInMemoryByteForByte) {
  expect_coherent_streamed_equal({0.0, 90.0}, true);
}

// The base height read from the file is terrain_height_at's, on cell
// centres, between them, at the scene's edges and beside no data.
TEST(SlarStreamTargets, TerrainHeightFromTheFileIsTheInMemoryOne) {
  const SceneFile f;
  const Scene read = read_scene(f.path);
  const SceneStreamReader in(f.path);
  for (double x : {0.0, 3.0, 5.0, 17.3, 404.9, 455.0, 895.0, 900.0}) {
    for (double y : {0.0, 2.5, 12.0, 333.3, 401.0, 595.0, 600.0}) {
      const double a = terrain_height_at(read, x, y), b = detail::streamed_terrain_height(in, x, y);
      if (std::isnan(a)) {
        EXPECT_TRUE(std::isnan(b)) << x << " " << y;
      } else {
        EXPECT_EQ(a, b) << x << " " << y;
      }
    }
  }
  EXPECT_TRUE(std::isnan(detail::streamed_terrain_height(in, -1.0, 10.0)));
  EXPECT_TRUE(std::isnan(detail::streamed_terrain_height(in, 10.0, 601.0)));
}

// A target off the scene or on no data fails as in memory (same message),
// and leaves no output.
TEST(SlarStreamTargets, BadTargetFailsAsInMemory) {
  const SceneFile f;
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const RadarParams radar = targets_radar(f.scene, 0.0, false);
  const SlarRunInfo info{f.path.string(), "r.toml", "test", 5, 1};
  for (const auto& [x, y] : {std::pair{950.0, 100.0}, std::pair{5.0, 300.0}}) {
    std::vector<PointTarget> t = scene_targets();
    t[3].x_m = x;
    t[3].y_m = y;
    std::string in_memory, streamed;
    try {
      SlarOptions o;
      o.targets = t;
      simulate_slar(read, radar, src, o);
    } catch (const InputError& e) {
      in_memory = e.what();
    }
    try {
      SlarStreamOptions o;
      o.quiet = true;
      o.targets = t;
      simulate_slar_streamed(f.path, radar, src, info, f.dir / "out", o);
    } catch (const InputError& e) {
      streamed = e.what();
    }
    EXPECT_NE(in_memory.find("target[3].position"), std::string::npos) << in_memory;
    EXPECT_EQ(in_memory, streamed);
    EXPECT_FALSE(fs::exists(f.dir / "out"));
  }
}

// Off the grid axes too (slar_stream_oblique.h: each block's engine run
// gets the candidates on its lines, as compute_block's), streamed == in
// memory byte for byte with point targets: SLAR at 30 and 200 deg, the
// incoherent SAR at 45 deg; blocks of 7, 16 and all lines; 1 and 2
// threads; the returns, hidden names (one at least) and measurements too.
TEST(SlarStreamTargets, ObliqueStreamedEqualsInMemoryByteForByte) {
  const SceneFile f;
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const std::vector<PointTarget> targets = scene_targets();
  const int saved = omp_get_max_threads();
  std::size_t hidden = 0;  // over the cases (behind the tower at 30 and 45 deg)
  struct Case {
    double heading;
    bool sar;
  };
  for (const Case c : {Case{30.0, false}, Case{45.0, true}, Case{200.0, false}}) {
    const RadarParams radar = targets_radar(f.scene, c.heading, c.sar);
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const SlarRunInfo info{f.path.string(), "r.toml", "test", 5, threads};
      const std::string tag =
          fmt::format("heading {} sar {} threads {}", c.heading, c.sar, threads);
      const fs::path mem = f.dir / "mem";
      const SlarSimulation sim = write_in_memory(read, radar, src, info, targets, mem);
      ASSERT_FALSE(sim.geometry.direct_sampling) << tag;
      EXPECT_GE(sim.point_returns.size(), 3u) << tag;
      hidden += sim.hidden_targets.size();
      const std::size_t measured = measure_point_targets(sim, render_slar(sim, 5), false).size();
      EXPECT_GE(measured, 1u) << tag;
      expect_streamed_blocks_equal(
          f, radar, src, info, targets, mem, tag,
          [&](const SlarStreamSummary& sum, const std::string& what) {
            EXPECT_EQ(sum.sim.hidden_targets, sim.hidden_targets) << what;
            ASSERT_EQ(sum.sim.point_returns.size(), sim.point_returns.size()) << what;
            for (std::size_t k = 0; k < sim.point_returns.size(); ++k) {
              EXPECT_EQ(sum.sim.point_returns[k].line, sim.point_returns[k].line) << what;
              EXPECT_EQ(sum.sim.point_returns[k].slant_range_m, sim.point_returns[k].slant_range_m)
                  << what;
            }
            EXPECT_EQ(sum.sim.image.point_power_w, sim.image.point_power_w) << what;
            EXPECT_EQ(sum.irfs.size(), measured) << what;
          });
      fs::remove_all(mem);
    }
  }
  omp_set_num_threads(saved);
  EXPECT_GE(hidden, 1u);
}

// Along a grid axis at a line spacing other than the cell size (half and
// two and a half cells), streamed == in memory byte for byte with point
// targets: SLAR and the incoherent SAR, headings 0 and 90 deg; blocks of 7,
// 16 and all lines; 1 and 2 threads; the returns and measurements too.
TEST(SlarStreamTargets, SpacedGridAxisStreamedEqualsInMemoryByteForByte) {
  const SceneFile f;
  const Scene read = read_scene(f.path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const std::vector<PointTarget> targets = scene_targets();
  const int saved = omp_get_max_threads();
  struct Case {
    double heading;
    bool sar;
    double cells;
  };
  for (const Case c : {Case{0.0, false, 0.5}, Case{90.0, true, 2.5}, Case{90.0, false, 0.5},
                       Case{0.0, true, 2.5}}) {
    RadarParams radar = targets_radar(f.scene, c.heading, c.sar);
    radar.azimuth_line_spacing_m = c.cells * f.scene.dy_m;
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const SlarRunInfo info{f.path.string(), "r.toml", "test", 5, threads};
      const std::string tag = fmt::format("heading {} sar {} spacing {} cells threads {}",
                                          c.heading, c.sar, c.cells, threads);
      const fs::path mem = f.dir / "mem";
      const SlarSimulation sim = write_in_memory(read, radar, src, info, targets, mem);
      ASSERT_TRUE(sim.geometry.direct_sampling) << tag;
      EXPECT_GE(sim.point_returns.size(), 3u) << tag;
      const std::size_t measured = measure_point_targets(sim, render_slar(sim, 5), false).size();
      expect_streamed_blocks_equal(
          f, radar, src, info, targets, mem, tag,
          [&](const SlarStreamSummary& sum, const std::string& what) {
            EXPECT_EQ(sum.sim.hidden_targets, sim.hidden_targets) << what;
            ASSERT_EQ(sum.sim.point_returns.size(), sim.point_returns.size()) << what;
            EXPECT_EQ(sum.sim.image.point_power_w, sim.image.point_power_w) << what;
            EXPECT_EQ(sum.irfs.size(), measured) << what;
          });
      fs::remove_all(mem);
    }
  }
  omp_set_num_threads(saved);
}

// Off the grid axes too, the coherent SAR streams: each oblique block runs
// its halo of lines (slar_stream_oblique.h through sar_coherent_stream.h),
// their counts and map values dropped, so the same bytes as in memory at
// 30, 45 and 200 deg, with point targets (one hidden at least), blocks of
// 7, 16 and all lines, 1 and 2 threads.
TEST(SlarStreamTargets, ObliqueCoherentSarStreamedEqualsInMemoryByteForByte) {
  EXPECT_GE(expect_coherent_streamed_equal({30.0, 45.0, 200.0}, false), 1u);
}

// Along a grid axis at 2.5 and 0.5 cells a line, the coherent SAR streams
// too: its own lines' per-sample map values are spilled for pass 1m, its
// halo's dropped; the in-memory bytes with point targets.
TEST(SlarStreamTargets, SpacedGridAxisCoherentSarStreamedEqualsInMemoryByteForByte) {
  expect_coherent_streamed_equal({0.0}, true, 2.5);
  expect_coherent_streamed_equal({90.0}, true, 0.5);
}

}  // namespace
}  // namespace ris
