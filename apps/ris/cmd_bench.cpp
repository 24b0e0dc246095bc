// `ris bench`: end-to-end SLAR throughput on a generated fractal scene
// (ris/perf/bench_setup.h), measured against the machine's memory bandwidth
// in the same run (docs/performance.md).
//
//   ris bench [--size N | --rows R --cols C] [--cell 6.096] [--repeats 5]
//             [--oblique-heading 30] [--no-oblique] [--no-standard] [--no-io] [--seed 7]
//
// Prints, per track (along a grid axis, oblique) and thread count (1, 2):
// the median wall time of simulate_slar + render_slar (geometry, radiometry,
// image formation, scene maps, speckle, greytones, ground range; products not
// written) and scene cells per second; the per-stage split; the standard
// scene's time; the time to write the products (I/O, separately); a
// bandwidth baseline (one pass reading the elevation and category arrays and
// writing one byte per cell, 2 threads); the peak resident memory; and last
// `cells_per_s_2threads=<n>` (along-axis track, 2 threads).
//
//   ris bench --topo [--topo-posting 0.0625] [--repeats N]
//
// Instead: ris topo's DEM pass (ris/perf/topo_bench.h), DEM cells per
// second on 2 threads (wall and per CPU-second) with the load average, and
// last `topo_dem_cells_per_s_2threads=<n>`.
#include <fmt/format.h>
#include <omp.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "bench_camera.h"
#include "bench_objects.h"
#include "bench_quad_pol.h"
#include "command_registry.h"
#include "ris/backscatter/library.h"
#include "ris/perf/bench_setup.h"
#include "ris/perf/topo_bench.h"
#include "ris/scene/scene_builder.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_channels.h"
#include "ris/sim/slar_products.h"
#include "ris/sim/slar_simulation.h"
#include "ris/sim/slar_stream.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"
#include "seed_option.h"

namespace ris::app {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double peak_rss_mib() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) / 1024.0;  // Linux: kilobytes
}

struct BenchArgs {
  int size = 2000;
  int rows = 0, cols = 0;
  double cell_m = 6.096;  // 20 ft, the standard scene's cell
  int repeats = 5;
  double oblique_heading_deg = 30.0;
  bool standard = true;
  bool oblique = true;
  bool io = true;
  std::uint64_t seed = 7;
  bool topo = false;     // ris topo's DEM pass instead (ris/perf/topo_bench.h)
  bool objects = false;  // the SBR tracer instead (apps/ris/bench_objects.h)
  bool camera = false;   // the frame camera instead (apps/ris/bench_camera.h)
  double topo_posting_arcsec = TopoBenchOptions{}.posting_arcsec;
};

double process_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

struct RunTiming {
  double total_s = 0.0;
  double cpu_s = 0.0;  // process CPU time (all threads): robust to a loaded machine
  std::map<std::string, double> stage_s;      // simulate_slar stages + render
  std::map<std::string, double> stage_cpu_s;  // the same, process CPU time
};

// One end-to-end run, with the per-stage split from simulate_slar's progress
// callback (called at the start of each stage).
RunTiming run_once(const Scene& scene, const RadarParams& radar, const Sigma0Source& sigma0,
                   SlarSimulation* keep = nullptr, SlarPictures* keep_pic = nullptr) {
  RunTiming t;
  std::string stage;
  auto stage_t0 = Clock::now();
  double stage_cpu0 = 0.0;
  SlarOptions options;
  options.progress = [&](std::string_view name, double) {
    if (!stage.empty()) {
      t.stage_s[stage] += seconds_since(stage_t0);
      t.stage_cpu_s[stage] += process_cpu_s() - stage_cpu0;
    }
    stage = std::string(name);
    stage_t0 = Clock::now();
    stage_cpu0 = process_cpu_s();
  };
  const auto t0 = Clock::now();
  const double cpu0 = process_cpu_s();
  SlarSimulation sim = simulate_slar(scene, radar, sigma0, options);
  t.stage_s[stage] += seconds_since(stage_t0);
  t.stage_cpu_s[stage] += process_cpu_s() - stage_cpu0;
  const auto r0 = Clock::now();
  const double r_cpu0 = process_cpu_s();
  SlarPictures pic = render_slar(sim, 1);
  const std::string render_stage = "render (speckle, greytone, ground range)";
  t.stage_s[render_stage] += seconds_since(r0);
  t.stage_cpu_s[render_stage] += process_cpu_s() - r_cpu0;
  t.total_s = seconds_since(t0);
  t.cpu_s = process_cpu_s() - cpu0;
  if (keep) *keep = std::move(sim);
  if (keep_pic) *keep_pic = std::move(pic);
  return t;
}

// Median over repeats (after one warm-up run), stage splits from the run
// closest to the median.
RunTiming run_median(const Scene& scene, const RadarParams& radar, const Sigma0Source& sigma0,
                     int threads, int repeats) {
  omp_set_num_threads(threads);
  run_once(scene, radar, sigma0);  // warm-up: page faults, LUT, caches
  std::vector<RunTiming> runs;
  std::vector<double> totals, cpus;
  for (int i = 0; i < repeats; ++i) {
    runs.push_back(run_once(scene, radar, sigma0));
    totals.push_back(runs.back().total_s);
    cpus.push_back(runs.back().cpu_s);
  }
  const double m = median(totals);
  RunTiming best = runs.front();
  for (const RunTiming& r : runs)
    if (std::abs(r.total_s - m) < std::abs(best.total_s - m)) best = r;
  best.total_s = m;
  best.cpu_s = median(cpus);
  return best;
}

// The bandwidth baseline: read elevation (4 B) and category (2 B) of every
// cell, write one byte per cell (an image-sized output): 7 B per cell of
// memory traffic, the least any pipeline over the scene must move.
double bandwidth_pass_s(const Scene& scene, std::vector<std::uint8_t>& out, int threads,
                        int repeats) {
  omp_set_num_threads(threads);
  const std::int64_t n = static_cast<std::int64_t>(scene.size());
  const float* h = scene.elevation_m.data();
  const std::uint16_t* c = scene.category.data();
  std::uint8_t* o = out.data();
  std::vector<double> times;
  for (int rep = 0; rep <= repeats; ++rep) {
    const auto t0 = Clock::now();
#pragma omp parallel for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      o[i] = static_cast<std::uint8_t>(static_cast<std::uint32_t>(h[i]) + c[i]);
    }
    if (rep > 0) times.push_back(seconds_since(t0));  // rep 0 warms up
  }
  return median(times);
}

void print_run(const std::string& label, const RunTiming& t, double cells) {
  fmt::print(
      "  {:<22} {:9.1f} ms  {:8.2f} M cells/s   (CPU {:8.1f} ms: {:7.2f} M cells per "
      "CPU-s)\n",
      label, 1e3 * t.total_s, cells / t.total_s / 1e6, 1e3 * t.cpu_s, cells / t.cpu_s / 1e6);
}

void print_stages(const RunTiming& t) {
  for (const auto& [name, s] : t.stage_s) {
    const auto cpu = t.stage_cpu_s.find(name);
    fmt::print("      {:<40} {:8.1f} ms ({:4.1f}%)  CPU {:8.1f} ms\n", name, 1e3 * s,
               100.0 * s / t.total_s, cpu == t.stage_cpu_s.end() ? 0.0 : 1e3 * cpu->second);
  }
}

// The speed-up from 1 to 2 threads, flagged when 2 threads took longer
// than 1: another job holds a core (seen at a load average of 7.5 on 2
// cores: 0.41x), and the figures measure it, not ris.
void print_speed_up(const RunTiming& t1, const RunTiming& t2, int max_threads) {
  fmt::print("  speed-up 1 -> 2 threads: {:.2f}x\n", t1.total_s / t2.total_s);
  if (max_threads > 1 && t2.total_s > t1.total_s) {
    double now[3] = {0, 0, 0};
    if (getloadavg(now, 3) < 0) now[0] = -1.0;
    fmt::print(
        "  machine busy, figures not representative: 2 threads took longer than 1 (load "
        "average {:.2f} on {} cores); rerun when the machine is idle\n",
        now[0], max_threads);
  }
}

// `ris bench --topo`: DEM cells per second of ris topo's DEM pass (one
// geo2rdr per DEM cell) on 2 threads, with the load average beside it.
void run_topo_bench_command(const BenchArgs& a) {
  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) < 0) load[0] = -1.0;
  TopoBenchOptions o;
  o.posting_arcsec = a.topo_posting_arcsec;
  o.repeats = a.repeats;
  const TopoBenchResult r = run_topo_bench(o);
  double after[3] = {0, 0, 0};
  if (getloadavg(after, 3) < 0) after[0] = -1.0;
  const double cells = static_cast<double>(r.dem_cells);
  fmt::print(
      "ris bench --topo: airborne example ({} lines x {} bins), rolling hills at {:g} arc-second "
      "postings ({} x {} cells), one facet per cell, {} threads, median of {}\n"
      "  load average {:.2f} before, {:.2f} after (2 cores)\n"
      "  DEM pass: {:.2f} M DEM cells in {:.3f} s: {:.1f} M DEM cells/s (wall), {:.1f} M per "
      "CPU-second (CPU {:.3f} s)\n"
      "  radar pass: {} pixels in {:.3f} s\n",
      r.grid_lines, r.grid_bins, o.posting_arcsec, r.dem_rows, r.dem_cols, o.threads, o.repeats,
      load[0], after[0], cells / 1e6, r.dem_seconds, cells / r.dem_seconds / 1e6,
      cells / r.dem_cpu_seconds / 1e6, r.dem_cpu_seconds, r.grid_lines * r.grid_bins,
      r.radar_seconds);
  fmt::print("topo_dem_cells_per_s_2threads={:.0f}\n", cells / r.dem_seconds);
}

// The benches run instead of the default one (--camera, --objects, --topo);
// false when none is asked for.
bool run_other_bench(const BenchArgs& a) {
  if (a.camera) {
    run_camera_bench(ris::data_dir().string(), a.repeats);
  } else if (a.objects) {
    run_objects_bench(a.repeats);
    run_town_bench(ris::data_dir().string());
  } else if (a.topo) {
    run_topo_bench_command(a);
  } else {
    return false;
  }
  return true;
}

void run_bench(const BenchArgs& a) {
  if (run_other_bench(a)) return;
  const int rows = a.rows > 0 ? a.rows : a.size;
  const int cols = a.cols > 0 ? a.cols : a.size;
  if (rows <= 0 || cols <= 0) throw InputError("", "--size", "expected a positive scene size");
  if (a.repeats < 1) throw InputError("", "--repeats", "expected 1 or more");
  // The bench runs in memory: checked before the scene is made (a size of
  // 1000000 once ended in std::bad_alloc).
  require_memory(in_memory_run_bytes(rows, cols, "", "--size"), "", "--size",
                 fmt::format("an in-memory run of {} x {} cells", cols, rows));
  const int max_threads = omp_get_max_threads();
  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) < 0) load[0] = -1.0;

  fmt::print(
      "ris bench: {} x {} fractal scene ({:.1f} M cells, {:.3f} m cells), {} repeats "
      "(median), {} cores available, load average {:.2f}\n"
      "(other jobs share the cores: CPU is this process's CPU time, less sensitive to them)\n",
      rows, cols, double(rows) * cols / 1e6, a.cell_m, a.repeats, max_threads, load[0]);
  auto t0 = Clock::now();
  const Scene scene = make_bench_scene(rows, cols, a.cell_m, a.seed);
  fmt::print("  scene generated in {:.2f} s (not timed below)\n", seconds_since(t0));
  const RadarParams base = load_radar(default_radar_path());
  const std::string sigma0_path = default_sigma0_library_path();
  const std::unique_ptr<Sigma0Source> sigma0 = load_sigma0_source(sigma0_path);
  const double cells = double(scene.size());

  struct TrackCase {
    std::string name;
    double heading_deg;
  };
  std::vector<TrackCase> tracks{{"along-axis track (heading 0)", 0.0}};
  if (a.oblique) {
    // --oblique-heading 90 (or 180, 270) times the other along-axis cases:
    // named as such.
    const bool on_axis = std::fmod(a.oblique_heading_deg, 90.0) == 0.0;
    tracks.push_back({fmt::format("{} track (heading {:g})", on_axis ? "along-axis" : "oblique",
                                  a.oblique_heading_deg),
                      a.oblique_heading_deg});
  }
  double cells_per_s_2 = 0.0;
  for (const TrackCase& tc : tracks) {
    const RadarParams radar = bench_radar(base, scene, deg_to_rad(tc.heading_deg));
    fmt::print("\n{} ({} range bins):\n", tc.name, radar.range_bins);
    const RunTiming t1 = run_median(scene, radar, *sigma0, 1, a.repeats);
    print_run("1 thread", t1, cells);
    print_stages(t1);
    const RunTiming t2 = run_median(scene, radar, *sigma0, 2, a.repeats);
    print_run("2 threads", t2, cells);
    print_stages(t2);
    print_speed_up(t1, t2, max_threads);
    if (tc.heading_deg == 0.0) cells_per_s_2 = cells / t2.total_s;
  }

  // The channel axis (ris/sim/slar_channels.h): 4 channels over the
  // along-axis track's geometry against 1 (the simulation only; the
  // geometry is shared, each channel's profiles and image are its own).
  {
    const RadarParams radar = bench_radar(base, scene, 0.0);
    const std::vector<SlarChannel> four{
        {radar_at_band(radar, 1.25e9, Polarisation::HH), sigma0.get(), sigma0_path},
        {radar_at_band(radar, 5.3e9, Polarisation::HH), sigma0.get(), sigma0_path},
        {radar_at_band(radar, 5.3e9, Polarisation::VV), sigma0.get(), sigma0_path},
        {radar_at_band(radar, 9.6e9, Polarisation::HH), sigma0.get(), sigma0_path}};
    const int threads = std::min(2, max_threads);
    omp_set_num_threads(threads);
    std::vector<double> one_s, four_s;
    for (int i = 0; i < a.repeats; ++i) {
      auto c0 = Clock::now();
      (void)simulate_slar_channels(scene, std::span(four).first(1), {});
      one_s.push_back(seconds_since(c0));
      c0 = Clock::now();
      (void)simulate_slar_channels(scene, four, {});
      four_s.push_back(seconds_since(c0));
    }
    std::sort(one_s.begin(), one_s.end());
    std::sort(four_s.begin(), four_s.end());
    const double t1 = one_s[one_s.size() / 2], t4 = four_s[four_s.size() / 2];
    fmt::print(
        "\nchannels (along-axis, {} threads, simulation only): 1 channel (L HH) {:.1f} ms; "
        "4 channels (L HH, C HH, C VV, X HH) {:.1f} ms = {:.2f} x one channel\n",
        threads, 1e3 * t1, 1e3 * t4, t4 / t1);
    fmt::print("channels_4_over_1={:.3f}\n", t4 / t1);
  }
  run_quad_pol_bench(ris::data_dir().string(), a.repeats);
  run_camera_bench(ris::data_dir().string(), a.repeats);

  // Bandwidth baseline on the same scene, same run.
  {
    std::vector<std::uint8_t> out(scene.size());
    const double s = bandwidth_pass_s(scene, out, 2, a.repeats);
    const double bytes = 7.0 * cells;
    fmt::print(
        "\nbandwidth baseline (read elevation + category, write 1 B/cell; 2 threads):\n"
        "  {:.1f} ms  {:.2f} M cells/s  {:.2f} GB/s\n",
        1e3 * s, cells / s / 1e6, bytes / s / 1e9);
    fmt::print("  pipeline (along-axis, 2 threads) runs at {:.1f}% of this streaming limit\n",
               100.0 * cells_per_s_2 / (cells / s));
  }

  if (a.standard) {
    const Scene std_scene = build_scene_file(default_scene_path());
    const RadarParams radar = load_radar(default_radar_path());
    const RunTiming t =
        run_median(std_scene, radar, *sigma0, std::min(2, max_threads), std::max(a.repeats, 5));
    fmt::print("\nstandard scene ({} x {}, {}), 2 threads:\n", std_scene.rows, std_scene.cols,
               std::filesystem::path(default_radar_path()).filename().string());
    print_run("simulate + render", t, double(std_scene.size()));
    print_stages(t);
    if (a.io) {
      SlarSimulation sim;
      SlarPictures pic;
      run_once(std_scene, radar, *sigma0, &sim, &pic);
      const auto dir = std::filesystem::temp_directory_path() /
                       fmt::format("ris-bench-{}", static_cast<long>(getpid()));
      // Product writing (all products, concurrently) per --compress preset:
      // median of 3 writes, and the files' total size.
      for (const CompressionPreset preset :
           {CompressionPreset::fast, CompressionPreset::small, CompressionPreset::none}) {
        SlarRunInfo info{"ku-geometric", "seed-fig4-5", "", 1, 2};
        info.compression = preset;
        std::vector<double> ms;
        for (int i = 0; i < 3; ++i) {
          std::filesystem::remove_all(dir);
          const auto w0 = Clock::now();
          write_slar_products(dir, std_scene, sim, pic, info);
          ms.push_back(1e3 * seconds_since(w0));
        }
        std::sort(ms.begin(), ms.end());
        std::uintmax_t bytes = 0;
        for (const auto& f : std::filesystem::directory_iterator(dir)) bytes += f.file_size();
        fmt::print(
            "  writing products (--compress {}, not in the figures above): {:.1f} ms, "
            "{:.2f} MB\n",
            to_string(preset), ms[1], 1e-6 * double(bytes));
      }
      std::filesystem::remove_all(dir);
    }
  }

  fmt::print("\npeak memory (ru_maxrss): {:.0f} MiB\n", peak_rss_mib());
  fmt::print("cells_per_s_2threads={:.0f}\n", cells_per_s_2);
}

void add_bench(CLI::App& app) {
  auto args = std::make_shared<BenchArgs>();
  auto* cmd = app.add_subcommand("bench", "Benchmark the SLAR pipeline on a fractal scene");
  cmd->add_option("--size", args->size, "Scene rows and columns")->capture_default_str();
  cmd->add_option("--rows", args->rows, "Scene rows (overrides --size)");
  cmd->add_option("--cols", args->cols, "Scene columns (overrides --size)");
  cmd->add_option("--cell", args->cell_m, "Cell size, metres")->capture_default_str();
  cmd->add_option("--repeats", args->repeats, "Timed runs per figure (median)")
      ->capture_default_str();
  cmd->add_option("--oblique-heading", args->oblique_heading_deg,
                  "Heading of the oblique track, degrees")
      ->capture_default_str();
  add_seed_option(cmd, args->seed, "Fractal scene seed");
  cmd->add_flag("!--no-standard", args->standard, "Skip the standard scene");
  cmd->add_flag("!--no-oblique", args->oblique, "Skip the oblique track");
  cmd->add_flag("!--no-io", args->io, "Skip the product-writing (I/O) timing");
  cmd->add_flag("--topo", args->topo,
                "Instead: ris topo's DEM pass on the airborne example, DEM cells/s on 2 threads");
  cmd->add_flag("--camera", args->camera,
                "Instead: the optical frame camera over the town, rays/s on 2 threads");
  cmd->add_flag("--objects", args->objects,
                "Instead: the SBR tracer of cultural objects, rays/s on 2 threads");
  cmd->add_option("--topo-posting", args->topo_posting_arcsec,
                  "--topo: the DEM's posting, arc-seconds")
      ->capture_default_str();
  cmd->callback([args] { run_bench(*args); });
}

const Registration reg{"bench", add_bench};

}  // namespace
}  // namespace ris::app
