// `ris simulate`: a SLAR, SAR or PPI simulation of a scene into one output
// folder, by the radar file's `mode` (ris/sim/slar_simulation.h and
// slar_products.h; ris/sim/ppi_simulation.h and ppi_products.h; docs/modes.md).
//
//   ris simulate [--scene S] [--radar R] [--backscatter B] [--targets T]
//                [--out DIR] [--seed N] [--threads N] [--quiet]
//                [--stream] [--block-lines N]
//
// With no arguments: the standard scene (built from its TOML description on
// the fly) with the seed's figure-4-5 radar and the standard backscatter
// library, into ./out.
//
// A scene raster too large for an in-memory run (scene_needs_streaming) is
// streamed from its file in blocks of azimuth lines (ris/sim/slar_stream.h;
// the same products, bounded memory); --stream or --block-lines N asks for
// that on any scene raster (SLAR only).
#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "command_registry.h"
#include "ris/backscatter/library.h"
#include "ris/io/dem_import.h"
#include "ris/io/scene_stream.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/point_target.h"
#include "ris/sim/point_target_irf.h"
#include "ris/sim/ppi_products.h"
#include "ris/sim/ppi_simulation.h"
#include "ris/sim/sar_coherent.h"
#include "ris/sim/slar_products.h"
#include "ris/sim/slar_simulation.h"
#include "ris/sim/slar_stream.h"
#include "ris/util/error.h"
#include "ris/util/progress.h"
#include "ris/util/units.h"

namespace ris::app {
namespace {

struct SimulateArgs {
  std::string scene;
  std::string radar;
  std::string backscatter;
  std::string out = "out";
  std::string targets;
  std::uint64_t seed = 1;
  int threads = 0;
  bool quiet = false;
  bool stream = false;
  int block_lines = 0;
};

using StageFn = std::function<void(std::string_view, double)>;

std::string absolute_out(const std::string& out) {
  return std::filesystem::absolute(out).lexically_normal().string();
}

// PPI: rays from a site, the B-scope and the scope (docs/modes.md).
void run_ppi(const SimulateArgs& a, const Scene& scene, const RadarParams& radar,
             const Sigma0Source& sigma0, const SlarOptions& options, const SlarRunInfo& info,
             const StageFn& stage) {
  const PpiSimulation ppi = simulate_ppi(scene, radar, sigma0, options);
  for (const std::string& w : ppi.warnings) spdlog::warn("{}", w);
  stage("speckle and greytones", 0.9);
  const PpiPictures pic = render_ppi(ppi, a.seed);
  stage("writing products", 0.95);
  write_ppi_products(a.out, scene, ppi, pic, info);
  stage("done", 1.0);
  const SlarGeometry& g = ppi.geometry.rays;
  fmt::print("simulated {} ({} x {} cells) with {} (PPI)\n", a.scene, scene.cols, scene.rows,
             a.radar);
  fmt::print("  B-scope: {} rays x {} range bins; scope {} x {} pixels of {:.2f} m\n",
             ppi.bscope.lines, ppi.bscope.bins, ppi.scope_grid.size, ppi.scope_grid.size,
             ppi.scope_grid.pixel_m);
  fmt::print("  antenna at {:.1f} m (terrain {:.1f} m); shadow {:.2f}% of ray samples\n",
             ppi.geometry.altitude_m, ppi.geometry.site_ground_m,
             100.0 * double(g.shadow_samples) / (double(g.lines) * double(g.samples)));
  if (!options.targets.empty()) {
    fmt::print("  point targets: {} seen, {} hidden\n", ppi.point_returns.size(),
               ppi.hidden_targets.size());
  }
}

// SLAR and SAR (incoherent or coherent); point targets' impulse responses.
void run_slar(const SimulateArgs& a, const Scene& scene, const RadarParams& radar,
              const Sigma0Source& sigma0, const SlarOptions& options, const SlarRunInfo& info,
              const StageFn& stage) {
  const SlarSimulation sim = simulate_slar(scene, radar, sigma0, options);
  for (const std::string& w : sim.warnings) spdlog::warn("{}", w);
  stage("speckle and greytones", 0.9);
  const bool coherent = radar.mode == RadarMode::sar && radar.sar.coherent;
  const SlarPictures pictures = coherent
                                    ? render_slar(sim, a.seed, coherent_sar_intensity(sim, a.seed))
                                    : render_slar(sim, a.seed);
  nlohmann::json extra = nlohmann::json::object();
  std::vector<PointTargetIrf> irfs;
  if (!options.targets.empty()) {
    irfs = measure_point_targets(sim, pictures, coherent);
    extra["point_targets"] = point_target_irf_json(irfs, sim, a.targets, coherent);
  }
  stage("writing products", 0.95);
  write_slar_products(a.out, scene, sim, pictures, info, extra);
  stage("done", 1.0);

  const SlarGeometry& g = sim.geometry;
  const double samples = double(g.lines) * double(g.samples);
  fmt::print("simulated {} ({} x {} cells) with {} ({})\n", a.scene, scene.cols, scene.rows,
             a.radar, radar.mode == RadarMode::sar ? (coherent ? "coherent SAR" : "SAR") : "SLAR");
  fmt::print("  image: {} azimuth lines x {} range bins (slant), {} ground-range pixels\n",
             sim.image.lines, sim.image.bins, sim.ground_grid.count);
  fmt::print(
      "  shadow {:.2f}%, layover {:.2f}%, back-facing {:.2f}% of samples; {} no-data cells\n",
      100.0 * double(g.shadow_samples) / samples, 100.0 * double(g.layover_samples) / samples,
      100.0 * double(g.back_facing_samples) / samples, g.nodata_cells);
  for (const PointTargetIrf& t : irfs) {
    fmt::print(
        "  target at R {:.1f} m, s {:.1f} m: 3 dB width {:.2f} m (range) x {:.2f} m (azimuth), "
        "PSLR {:.1f} dB, ISLR {:.1f} dB\n",
        t.target.slant_range_m, t.target.along_m, t.irf.range.width_m, t.irf.azimuth.width_m,
        t.irf.pslr_db, t.irf.islr_db);
  }
  for (const std::string& h : sim.hidden_targets) fmt::print("  target {} hidden\n", h);
}

// Whether to stream: asked for, or a scene raster too large for memory
// (only its header is read to decide).
bool should_stream(const SimulateArgs& a) {
  if (a.block_lines < 0) {
    throw InputError("", "--block-lines",
                     fmt::format("expected a positive number of lines, got {}", a.block_lines));
  }
  const bool is_raster = std::filesystem::path(a.scene).extension() != ".toml";
  if (a.stream || a.block_lines > 0) {
    if (!is_raster) {
      throw InputError(a.scene, "--stream",
                       "a streamed run reads a scene raster; build the description first with: "
                       "ris scene build " +
                           a.scene + " -o scene.tif");
    }
    return true;
  }
  if (!is_raster || dem_needs_import(a.scene)) return false;
  const SceneStreamReader probe(a.scene);
  if (!scene_needs_streaming(probe.grid().rows, probe.grid().cols)) return false;
  spdlog::warn(
      "{}: {} x {} cells is too large for an in-memory run; streaming it in blocks of "
      "azimuth lines",
      a.scene, probe.grid().cols, probe.grid().rows);
  return true;
}

void run_streamed(const SimulateArgs& a, std::chrono::steady_clock::time_point t0) {
  if (!a.targets.empty()) {
    throw InputError(a.targets, "--targets",
                     "a streamed run does not take point targets; run the scene in memory "
                     "(a smaller scene or window) to add them");
  }
  const RadarParams radar = load_radar(a.radar);
  const std::string backscatter =
      a.backscatter.empty() ? default_sigma0_library_path() : a.backscatter;
  const std::unique_ptr<Sigma0Source> sigma0 = load_sigma0_source(backscatter);
  const SlarRunInfo info{a.scene, a.radar, backscatter, a.seed,
                         a.threads > 0 ? a.threads : omp_get_max_threads()};
  SlarStreamOptions o;
  o.block_lines = a.block_lines;
  o.quiet = a.quiet;
  const SlarStreamSummary s = simulate_slar_streamed(a.scene, radar, *sigma0, info, a.out, o);
  for (const std::string& w : s.sim.warnings) spdlog::warn("{}", w);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const SlarGeometry& g = s.sim.geometry;
  const double samples = double(g.lines) * double(g.samples);
  fmt::print("simulated {} ({} x {} cells, streamed in {} blocks of {} lines) with {}\n", a.scene,
             s.grid.cols, s.grid.rows, s.blocks, s.block_lines, a.radar);
  fmt::print("  image: {} azimuth lines x {} range bins (slant), {} ground-range pixels\n",
             s.sim.image.lines, s.sim.image.bins, s.sim.ground_grid.count);
  fmt::print(
      "  shadow {:.2f}%, layover {:.2f}%, back-facing {:.2f}% of samples; {} no-data cells\n",
      100.0 * double(g.shadow_samples) / samples, 100.0 * double(g.layover_samples) / samples,
      100.0 * double(g.back_facing_samples) / samples, g.nodata_cells);
  for (const auto& [name, t] : s.stage_seconds) fmt::print("  {:.2f} s  {}\n", t, name);
  fmt::print("  {:.2f} s; outputs in {}\n", seconds,
             std::filesystem::absolute(a.out).lexically_normal().string());
}

void run_simulate(const SimulateArgs& a) {
  if (a.threads < 0) {
    throw InputError("", "--threads",
                     fmt::format("expected 0 (all cores) or more, got {}", a.threads));
  }
  if (a.threads > 0) omp_set_num_threads(a.threads);
  const auto t0 = std::chrono::steady_clock::now();
  if (should_stream(a)) {
    run_streamed(a, t0);
    return;
  }

  // Progress only on a terminal and without --quiet (ris/util/progress.h):
  // percent of the run by stage, rate and time remaining.
  auto bar = std::make_shared<ProgressBar>("simulate", 100, "%", a.quiet);
  auto done_pct = std::make_shared<std::int64_t>(0);
  SlarOptions options;
  if (bar->enabled()) {
    options.progress = [bar, done_pct](std::string_view stage, double fraction) {
      const auto pct = static_cast<std::int64_t>(100.0 * fraction);
      bar->advance(pct - *done_pct);
      *done_pct = pct;
      bar->set_stage(std::string(stage));
    };
  }
  const auto stage = [&](std::string_view name, double fraction) {
    if (options.progress) options.progress(name, fraction);
  };

  stage("reading inputs", 0.0);
  const RadarParams radar = load_radar(a.radar);
  const Scene scene = load_scene_source(a.scene).scene;
  const std::string backscatter =
      a.backscatter.empty() ? default_sigma0_library_path() : a.backscatter;
  const std::unique_ptr<Sigma0Source> sigma0 = load_sigma0_source(backscatter);
  options.backscatter_file = backscatter;
  if (!a.targets.empty()) options.targets = load_point_targets(a.targets);
  const SlarRunInfo info{a.scene, a.radar, backscatter, a.seed,
                         a.threads > 0 ? a.threads : omp_get_max_threads()};

  if (radar.mode == RadarMode::ppi) {
    run_ppi(a, scene, radar, *sigma0, options, info, stage);
  } else {
    run_slar(a, scene, radar, *sigma0, options, info, stage);
  }
  bar->finish();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fmt::print("  {:.2f} s; outputs in {}\n", seconds, absolute_out(a.out));
}

void add_simulate(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  args->scene = default_scene_path();
  args->radar = default_radar_path();
  auto* cmd = app.add_subcommand(
      "simulate", "Simulate a SLAR, SAR or PPI image of a scene (the radar file's mode)");
  cmd->add_option("--scene", args->scene, "Scene: a .toml description or a raster")
      ->capture_default_str();
  cmd->add_option("--radar", args->radar, "Radar description (TOML)")->capture_default_str();
  cmd->add_option("--backscatter", args->backscatter,
                  "Backscatter library (.toml) or table (.csv); default: the standard library");
  cmd->add_option("--out", args->out, "Output folder (written as a whole)")->capture_default_str();
  cmd->add_option("--targets", args->targets,
                  "Point targets (TOML, [[target]] tables): corner reflectors etc.");
  cmd->add_option("--seed", args->seed, "Fading seed")->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
  cmd->add_flag("--quiet", args->quiet, "No progress bar (it shows only on a terminal anyway)");
  cmd->add_flag("--stream", args->stream,
                "Stream the scene raster from its file in blocks of azimuth lines (bounded "
                "memory; automatic when the scene is too large for memory)");
  cmd->add_option("--block-lines", args->block_lines,
                  "Azimuth lines per streamed block (implies --stream; default: from a 512 MiB "
                  "budget)");
  cmd->callback([args] { run_simulate(*args); });
}

const Registration reg{"simulate", add_simulate};

}  // namespace
}  // namespace ris::app
