#include "ris/sim/ppi_stream.h"
#include "build_paths.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <tuple>
#include <vector>

#include "ris/perf/bench_setup.h"
#include "ris/scene/scene_io.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/ppi_products.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// A fractal scene 4 km x 3 km at 20 m with a no-data hole, a no-data edge
// column, a tower (shadow and layover) and two categories.
Scene test_scene() {
  Scene s = make_bench_scene(150, 200, 20.0, 5);
  for (int r = 40; r < 52; ++r)
    for (int c = 120; c < 131; ++c) s.valid[s.index(r, c)] = 0;
  for (int r = 0; r < s.rows; ++r) s.valid[s.index(r, 0)] = 0;
  for (int r = 90; r < 95; ++r)
    for (int c = 60; c < 65; ++c) s.elevation_m[s.index(r, c)] += 120.0f;
  for (int r = 100; r < 140; ++r)
    for (int c = 10; c < 90; ++c) s.category[s.index(r, c)] = 3;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (!s.valid[i]) s.category[i] = kNoDataCategory;
  return s;
}

// A shipped PPI radar with its site moved onto the test scene (off the cell
// centres).
RadarParams shipped_radar(const Scene& s, const std::string& name) {
  RadarParams r = load_radar(std::string(ris::test::data_dir()) + "/radars/" + name + ".toml");
  const auto [x, y] = s.world_from_grid(0.47 * s.cols, 0.53 * s.rows);
  r.ppi.site_x_m = x;
  r.ppi.site_y_m = y;
  return r;
}

std::vector<std::string> files_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// Every file of two output folders, byte for byte (the rasters' pixels and
// tags, the PNGs, metadata.json's text).
void expect_same_folders(const fs::path& a, const fs::path& b, const std::string& what) {
  const std::vector<std::string> na = files_in(a), nb = files_in(b);
  EXPECT_EQ(na, nb) << what;
  EXPECT_EQ(na.size(), ppi_product_stems().size() + 1) << what;  // + metadata.json
  for (const std::string& name : na) {
    if (!fs::exists(b / name)) continue;
    EXPECT_TRUE(test::read_file(a / name) == test::read_file(b / name)) << what << ": " << name;
  }
}

struct Case {
  std::string radar;
  double sector_start_deg = 0.0, sector_width_deg = 0.0;  // width 0: the radar's scan
  bool auto_reference = true;
};

// The pixels the automatic greytone reference takes its median over.
std::size_t valid_pixels(const SlarImage& b) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < b.mean_power_w.size(); ++i) {
    const float p = b.mean_power_w[i];
    n += std::isfinite(p) && p > 0.0f && !(b.mask[i] & pixel_flag::kNoData) ? 1 : 0;
  }
  return n;
}

// The test: streamed and in-memory PPI runs give identical bytes for
// both shipped PPI radars (slant and ground scope), a sector scan, both
// greytone references, blocks of 7, 16 and all rays, 1 and 2 threads, and
// scene windows from the default down to a few hundred cells (many windows
// a range segment, short segments).
TEST(PpiStream, StreamedEqualsInMemoryByteForByte) {
  const Scene scene = test_scene();
  test::TempDir dir;
  const fs::path scene_path = dir / "scene.tif";
  write_scene_geotiff(scene, scene_path);
  const Scene read = read_scene(scene_path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const int saved = omp_get_max_threads();
  const std::vector<Case> cases = {{"ppi-ground-mast-30m", 0.0, 0.0, true},
                                   {"ppi-airborne-nav-10000ft", 0.0, 0.0, true},
                                   {"ppi-ground-mast-30m", 30.0, 100.0, false},
                                   {"ppi-airborne-nav-10000ft", 200.0, 91.0, true}};
  bool even_median = false;  // an auto reference over an even count (the mean of two middles)
  for (const Case& c : cases) {
    RadarParams radar = shipped_radar(scene, c.radar);
    if (c.sector_width_deg > 0.0) {
      radar.ppi.scan_start_rad = deg_to_rad(c.sector_start_deg);
      radar.ppi.scan_width_rad = deg_to_rad(c.sector_width_deg);
    }
    radar.reference.automatic = c.auto_reference;
    if (!c.auto_reference) {
      radar.reference.mean_power_w = 1e-12;
      radar.reference.greytone = 100.0;
    }
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const SlarRunInfo info{scene_path.string(), c.radar + ".toml", "test", 7, threads};
      const std::string tag =
          fmt::format("{} sector {} threads {}", c.radar, c.sector_width_deg, threads);
      const fs::path mem = dir / "mem";
      const PpiSimulation sim = simulate_ppi(read, radar, src);
      write_ppi_products(mem, read, sim, render_ppi(sim, info.seed), info);
      if (c.auto_reference && valid_pixels(sim.bscope) % 2 == 0) even_median = true;
      const int rays = sim.geometry.rays.lines;
      for (int block : {7, 16, rays}) {
        for (std::int64_t window : {std::int64_t(0), std::int64_t(300)}) {
          if (window > 0 && block == rays) continue;
          PpiStreamOptions o;
          o.block_rays = block;
          o.window_cells = window;
          o.segment_samples = window > 0 ? 40 : 0;
          o.quiet = true;
          const fs::path out = dir / "stream";
          const PpiStreamSummary sum = simulate_ppi_streamed(scene_path, radar, src, info, out, o);
          const std::string what = tag + fmt::format(" block {} window {}", block, window);
          EXPECT_EQ(sum.block_rays, block) << what;
          EXPECT_EQ(sum.blocks, (rays + block - 1) / block) << what;
          if (window > 0) {
            // Many windows, each small (one ray's 40-sample segment spans at
            // most 20 cells a side, plus the slopes' ring).
            EXPECT_GT(sum.windows, rays) << what;
            EXPECT_LE(sum.max_window_cells, 24 * 24) << what;
          }
          expect_same_folders(mem, out, what);
          fs::remove_all(out);
        }
      }
      fs::remove_all(mem);
    }
  }
  omp_set_num_threads(saved);
  EXPECT_TRUE(even_median) << "no case tests the mean of the two middle values";
}

// Targets on the test scene (column, row): in front of the site, on and
// behind the tower (low, hidden from the 30 m mast), near two corners; all
// but the one behind the tower 150 m above the terrain (above the relief).
std::vector<PointTarget> test_targets(const Scene& s) {
  std::vector<PointTarget> out;
  const std::pair<double, double> at[] = {
      {120.5, 60.5}, {62.5, 92.5}, {48.3, 98.1}, {180.2, 20.7}, {30.5, 130.5}};
  for (const auto& [c, r] : at) {
    PointTarget t;
    t.index = static_cast<int>(out.size());
    t.name = fmt::format("t{}", t.index);
    std::tie(t.x_m, t.y_m) = s.world_from_grid(c, r);
    t.height_m = t.index == 2 ? 2.0 : 150.0;  // the others above the relief
    t.rcs_m2 = 1000.0;
    t.source_file = "targets.toml";
    out.push_back(t);
  }
  return out;
}

// Point targets stream: the same files (metadata.json's seen and hidden
// included), returns, powers and hidden names as in memory, for blocks of
// 7, 16 and all rays and 1 and 2 threads; a full circle (a target hidden
// behind the tower) and a sector (the targets outside it hidden).
TEST(PpiStream, StreamedTargetsEqualInMemoryByteForByte) {
  Scene scene = test_scene();  // raised: the site's terrain well above the datum
  for (float& z : scene.elevation_m) z += 300.0f;
  test::TempDir dir;
  const fs::path scene_path = dir / "scene.tif";
  write_scene_geotiff(scene, scene_path);
  const Scene read = read_scene(scene_path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  SlarOptions mem_options;
  mem_options.targets = test_targets(read);
  const int saved = omp_get_max_threads();
  std::size_t seen = 0;
  for (double width : {0.0, 100.0}) {
    RadarParams radar = shipped_radar(scene, "ppi-ground-mast-30m");
    if (width > 0.0) {
      radar.ppi.scan_start_rad = deg_to_rad(30.0);
      radar.ppi.scan_width_rad = deg_to_rad(width);
    }
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const SlarRunInfo info{scene_path.string(), "r.toml", "test", 7, threads};
      const fs::path mem = dir / "mem";
      const PpiSimulation sim = simulate_ppi(read, radar, src, mem_options);
      write_ppi_products(mem, read, sim, render_ppi(sim, info.seed), info);
      if (width == 0.0) {
        EXPECT_EQ(sim.hidden_targets, std::vector<std::string>{"t2"}) << "behind the tower";
      } else {
        EXPECT_FALSE(sim.hidden_targets.empty());
      }
      seen += sim.point_returns.size();
      const int rays = sim.geometry.rays.lines;
      for (int block : {7, 16, rays}) {
        const std::string what = fmt::format("width {} threads {} block {}", width, threads, block);
        PpiStreamOptions o;
        o.block_rays = block;
        o.quiet = true;
        o.targets = mem_options.targets;
        const fs::path out = dir / "stream";
        const PpiStreamSummary sum = simulate_ppi_streamed(scene_path, radar, src, info, out, o);
        EXPECT_EQ(sum.sim.hidden_targets, sim.hidden_targets) << what;
        EXPECT_TRUE(test::same_bytes(sum.sim.bscope.point_power_w, sim.bscope.point_power_w))
            << what;
        ASSERT_EQ(sum.sim.point_returns.size(), sim.point_returns.size()) << what;
        for (std::size_t k = 0; k < sim.point_returns.size(); ++k) {
          EXPECT_EQ(sum.sim.point_returns[k].line, sim.point_returns[k].line) << what;
          EXPECT_EQ(sum.sim.point_returns[k].along_m, sim.point_returns[k].along_m) << what;
          EXPECT_EQ(sum.sim.point_returns[k].slant_range_m, sim.point_returns[k].slant_range_m)
              << what;
        }
        expect_same_folders(mem, out, what);
        fs::remove_all(out);
      }
      fs::remove_all(mem);
    }
  }
  omp_set_num_threads(saved);
  EXPECT_GT(seen, 0u);
  // A target off the scene or on no data: simulate_ppi's InputError, no output.
  for (const auto& [c, r] : {std::pair{-3.0, 10.0}, std::pair{125.5, 45.5}}) {
    PpiStreamOptions o;
    o.quiet = true;
    o.targets = mem_options.targets;
    std::tie(o.targets[1].x_m, o.targets[1].y_m) = scene.world_from_grid(c, r);
    SlarOptions m;
    m.targets = o.targets;
    const RadarParams radar = shipped_radar(scene, "ppi-ground-mast-30m");
    std::string in_memory;
    try {
      simulate_ppi(read, radar, src, m);
    } catch (const InputError& e) {
      in_memory = e.what();
    }
    EXPECT_FALSE(in_memory.empty());
    try {
      simulate_ppi_streamed(scene_path, radar, src, {scene_path.string(), "r.toml", "test", 7, 1},
                            dir / "bad", o);
      ADD_FAILURE() << "no error for a bad target";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), in_memory);
      EXPECT_EQ(e.file(), "targets.toml");
    }
    EXPECT_FALSE(fs::exists(dir / "bad"));
  }
}

// What simulate_ppi refuses, the stream refuses, and leaves no output.
TEST(PpiStream, RefusesWhatTheInMemoryRunRefuses) {
  const Scene scene = test_scene();
  test::TempDir dir;
  const fs::path scene_path = dir / "scene.tif";
  write_scene_geotiff(scene, scene_path);
  const test::CosineSigma0Source src({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const SlarRunInfo info{scene_path.string(), "r.toml", "test", 7, 1};
  PpiStreamOptions o;
  o.quiet = true;
  RadarParams off = shipped_radar(scene, "ppi-ground-mast-30m");
  off.ppi.site_x_m = -5000.0;  // off the scene
  EXPECT_THROW(simulate_ppi_streamed(scene_path, off, src, info, dir / "a", o), InputError);
  RadarParams hole = shipped_radar(scene, "ppi-ground-mast-30m");
  std::tie(hole.ppi.site_x_m, hole.ppi.site_y_m) = scene.world_from_grid(125.0, 45.0);  // no data
  EXPECT_THROW(simulate_ppi_streamed(scene_path, hole, src, info, dir / "b", o), InputError);
  RadarParams far = shipped_radar(scene, "ppi-ground-mast-30m");
  far.near_slant_range_m = 50000.0;  // the swath misses the scene
  far.far_slant_range_m = 60000.0;
  EXPECT_THROW(simulate_ppi_streamed(scene_path, far, src, info, dir / "c", o), InputError);
  const test::CosineSigma0Source few({0, 1});  // no backscatter for category 3
  EXPECT_THROW(simulate_ppi_streamed(scene_path, shipped_radar(scene, "ppi-ground-mast-30m"), few,
                                     info, dir / "d", o),
               InputError);
  for (const char* d : {"a", "b", "c", "d"}) EXPECT_FALSE(fs::exists(dir / d)) << d;
}

// Through the command line: `ris simulate --stream` (and --block-lines, rays
// then) with a PPI radar streams, and writes the in-memory run's files.
TEST(PpiStream, CommandLineStreamsPpiRuns) {
  test::TempDir dir;
  const std::string scene = (dir / "s.tif").string();
  ASSERT_EQ(test::run_ris("scene fractal --quiet --size 200x140 --cell-size 30 --relief 300 "
                          "--patches 1,2,3 -o " +
                          scene)
                .exit_code,
            0);
  for (const char* name : {"ppi-ground-mast-30m", "ppi-airborne-nav-10000ft"}) {
    const std::string common = fmt::format("simulate --quiet --scene {} --radar {}/radars/{}.toml",
                                           scene, ris::test::data_dir(), name);
    const fs::path mem = dir / "mem", streamed = dir / "streamed", blocks = dir / "blocks";
    ASSERT_EQ(test::run_ris(common + " --out " + mem.string()).exit_code, 0) << name;
    const test::RunResult s = test::run_ris(common + " --stream --out " + streamed.string());
    ASSERT_EQ(s.exit_code, 0) << name << ": " << s.output;
    EXPECT_NE(s.output.find("streamed in 1 blocks"), std::string::npos) << s.output;
    const test::RunResult b = test::run_ris(common + " --block-lines 50 --out " + blocks.string());
    ASSERT_EQ(b.exit_code, 0) << name << ": " << b.output;
    EXPECT_NE(b.output.find("blocks of 50 rays"), std::string::npos) << b.output;
    expect_same_folders(mem, streamed, std::string(name) + " --stream");
    expect_same_folders(mem, blocks, std::string(name) + " --block-lines 50");
    for (const fs::path& p : {mem, streamed, blocks}) fs::remove_all(p);
  }
}

// The sum of the sizes of the files in `dir`.
std::int64_t folder_bytes(const fs::path& dir) {
  std::int64_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += std::int64_t(fs::file_size(e.path()));
  return n;
}

// The free-disk check of a PPI run counts its products (rays x bins and the
// scope: ppi_product_size), not the scene's cells. The bound holds
// what an in-memory run writes uncompressed and is not loose (within 1.5
// times it); on a scene of 2000^2 cells (28 MB at the SLAR's 7 bytes a
// cell) the ground radar's run passes a disk ceiling just above the bound
// (RIS_MAX_DISK_MB) and is refused, writing nothing, just below it.
TEST(PpiStream, DiskCheckCountsThePpiProductsNotTheScene) {
  test::TempDir dir;
  const std::string radar_path =
      std::string(ris::test::data_dir()) + "/radars/ppi-ground-mast-30m.toml";
  const std::int64_t bound = ppi_product_size(load_radar(radar_path)).bytes;
  const std::string small = (dir / "small.tif").string();
  ASSERT_EQ(
      test::run_ris("scene fractal --quiet --size 200x140 --cell-size 30 -o " + small).exit_code,
      0);
  const std::string common = "simulate --quiet --radar " + radar_path + " --scene ";
  const test::RunResult raw =
      test::run_ris(common + small + " --compress none --out " + (dir / "raw").string());
  ASSERT_EQ(raw.exit_code, 0) << raw.output;
  const std::int64_t written = folder_bytes(dir / "raw");
  EXPECT_LE(written, bound);
  EXPECT_GE(3 * written, 2 * bound) << "the bound " << bound << " is loose: " << written;

  const std::string big = (dir / "big.tif").string();
  ASSERT_EQ(test::run_ris("scene fractal --quiet --generator noise --size 2000 --cell-size 10 "
                          "--relief 100 -o " +
                          big)
                .exit_code,
            0);
  const std::int64_t mib = std::int64_t(1) << 20;
  ASSERT_GT(2000LL * 2000 * 7, bound + 2 * mib) << "the scene must outweigh the products";
  // The ceiling for the ris runs this test starts (they inherit it).
  const auto run_under = [&](std::int64_t cap_mib, const fs::path& out) {
    ::setenv("RIS_MAX_DISK_MB", std::to_string(cap_mib).c_str(), 1);
    const test::RunResult r = test::run_ris(common + big + " --stream --out " + out.string());
    ::unsetenv("RIS_MAX_DISK_MB");
    return r;
  };
  const test::RunResult ok = run_under(bound / mib + 2, dir / "ok");
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
  EXPECT_LE(folder_bytes(dir / "ok"), bound);
  const test::RunResult refused = run_under(bound / mib - 1, dir / "refused");
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("'scan.pixel': the products of a PPI run (720 rays x 400 range "
                                "bins, a scope of 800 x 800 pixels)"),
            std::string::npos)
      << refused.output;
  EXPECT_FALSE(fs::exists(dir / "refused"));
}

// Runs ris with the arguments; returns its peak resident set in MiB (-1 on
// failure), as tests/stream_memory_test.cpp.
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
  return double(ru.ru_maxrss) / 1024.0;  // KiB on Linux
}

// The memory bound: a streamed PPI run holds blocks of rays and windows of
// the scene, never the scene, so its peak resident memory does not grow with
// the scene. The ground radar (3 km) at the middle of scenes of 400^2 and
// 2400^2 cells of 10 m: the rays reach the scene's corner on the small one
// and the far range on the large one (300 cells), so both runs hold about
// the same rays; the in-memory run of the large scene holds its 5.8 M cells
// (scene and texels, 23 bytes a cell: ~130 MiB more).
TEST(PpiStreamMemory, PeakResidentMemoryDoesNotGrowWithTheScene) {
  test::TempDir dir;
  const std::string radar = (dir / "radar.toml").string();
  std::string text =
      test::read_file(std::string(ris::test::data_dir()) + "/radars/ppi-ground-mast-30m.toml");
  double rss[3] = {0, 0, 0};
  int k = 0;
  for (int n : {400, 2400}) {
    const std::string scene = (dir / fmt::format("s{}.tif", n)).string();
    ASSERT_EQ(test::run_ris(fmt::format("scene fractal --generator noise --size {} --cell-size 10 "
                                        "--relief 100 --category grass --quiet -o {}",
                                        n, scene))
                  .exit_code,
              0);
    // The site at the scene's middle (the fractal's south-west corner is 0, 0).
    std::string t = text;
    const std::string from = "position = [3000.0, 2100.0]";
    t.replace(t.find(from), from.size(), fmt::format("position = [{0}.0, {0}.0]", 5 * n));
    test::write_file(radar, t);
    const std::vector<std::string> args = {
        "simulate",      "--quiet",
        "--scene",       scene,
        "--radar",       radar,
        "--backscatter", std::string(ris::test::data_dir()) + "/backscatter/generic-terrain.toml"};
    std::vector<std::string> streamed = args;
    for (const std::string& a :
         {std::string("--stream"), std::string("--out"), (dir / fmt::format("o{}", n)).string()})
      streamed.push_back(a);
    rss[k++] = peak_rss_mib(streamed);
    ASSERT_GT(rss[k - 1], 0.0) << n << ": the streamed run failed";
    if (n == 2400) {
      std::vector<std::string> in_memory = args;
      in_memory.push_back("--out");
      in_memory.push_back((dir / "mem").string());
      rss[2] = peak_rss_mib(in_memory);
      ASSERT_GT(rss[2], 0.0) << "the in-memory run failed";
    }
  }
  RecordProperty("peak_rss_mib_streamed_400", std::to_string(rss[0]));
  RecordProperty("peak_rss_mib_streamed_2400", std::to_string(rss[1]));
  RecordProperty("peak_rss_mib_in_memory_2400", std::to_string(rss[2]));
  // 36 times the cells: the streamed run stays within a few tens of MiB
  // (pass 0 reads 256 rows at a time: 2400 x 256 x 7 B = 4 MiB), while the
  // in-memory run grows by the scene.
  EXPECT_LT(rss[1] - rss[0], 40.0) << rss[0] << " MiB -> " << rss[1] << " MiB";
  EXPECT_GT(rss[2] - rss[1], 60.0) << "in memory " << rss[2] << " MiB, streamed " << rss[1];
}

}  // namespace
}  // namespace ris
