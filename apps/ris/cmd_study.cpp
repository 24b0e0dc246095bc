// `ris study`: the frequency/polarisation study (the seed's figure 7): one
// scene and track imaged at several (frequency, polarisation) pairs, with a
// contact sheet, per-category greytone statistics and the contrast between
// categories (ris/sim/study.h).
//
//   ris study [--scene S] [--radar R] [--backscatter B]
//             [--bands "1.25 GHz:HH, 8.6 GHz:VV, ..."] [--out DIR] [--seed N]
//             [--panel-size PX] [--threads N]
//
// With no arguments: the standard scene, the seed's figure-7 radar
// (data/radars/seed-fig7.toml) and the standard backscatter library at the
// default bands, into ./study.
#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "command_registry.h"
#include "ris/backscatter/library.h"
#include "ris/scene/scene_builder.h"
#include "ris/scene/scene_io.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/study.h"
#include "ris/util/error.h"
#include "ris/util/progress.h"
#include "ris/util/resource_guard.h"
#include "seed_option.h"

namespace ris::app {
namespace {

struct StudyArgs {
  std::string scene;
  std::string radar;
  std::string backscatter;
  std::string bands;
  std::string out = "study";
  std::uint64_t seed = 1;
  int threads = 0;
  int panel_px = 360;
  bool quiet = false;
};

Scene load_study_scene(const std::string& path) {
  if (std::filesystem::path(path).extension() == ".toml") {
    return build_scene(read_scene_description(path));
  }
  return read_scene(path);
}

void run_study_command(const StudyArgs& a) {
  checked_thread_count(a.threads, "--threads");  // the cap (ris/util/resource_guard.h)
  if (a.panel_px < 16) {
    throw InputError("", "--panel-size", fmt::format("expected 16 or more, got {}", a.panel_px));
  }
  if (a.threads > 0) omp_set_num_threads(a.threads);
  const auto t0 = std::chrono::steady_clock::now();
  // Bands first: a bad list fails before any expensive work.
  const std::vector<StudyBand> bands = parse_study_bands(a.bands, "--bands");

  StudyOptions options;
  options.seed = a.seed;
  options.scene_path = a.scene;
  // A bar on a terminal, plain lines in a log, nothing with --quiet.
  auto bar = std::make_shared<ProgressBar>("study", 100, "%", a.quiet);
  auto done_pct = std::make_shared<std::int64_t>(0);
  if (bar->enabled()) {
    options.progress = [bar, done_pct](std::string_view stage, double fraction) {
      const auto pct = static_cast<std::int64_t>(100.0 * fraction);
      bar->advance(pct - *done_pct);
      *done_pct = pct;
      bar->set_stage(std::string(stage));
    };
  }
  const RadarParams radar = load_radar(a.radar);
  const Scene scene = load_study_scene(a.scene);
  const std::string backscatter =
      a.backscatter.empty() ? default_sigma0_library_path() : a.backscatter;
  const std::unique_ptr<Sigma0Source> sigma0 = load_sigma0_source(backscatter);

  const StudyResult r = run_study(scene, radar, *sigma0, backscatter, bands, options);
  ContactSheetStyle style;
  style.max_panel_px = a.panel_px;
  write_study_products(a.out, r, StudyRunInfo{a.scene, a.radar, backscatter, a.seed}, style);
  bar->finish();

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fmt::print("study of {} with {} at {} bands\n", a.scene, a.radar, r.panels.size());
  fmt::print("  {:<16} {:>12} {:>12}  best pair in panel (C, dB)\n", "band", "min C", "mean C");
  const auto name = [&](std::uint16_t c) {
    for (std::size_t i = 0; i < r.categories.size(); ++i)
      if (r.categories[i] == c) return r.category_names[i];
    return std::to_string(c);
  };
  for (const StudyPanel& p : r.panels) {
    const PairContrast* best = nullptr;
    for (const PairContrast& c : p.pairs)
      if (std::isfinite(c.contrast) && (best == nullptr || c.contrast > best->contrast)) best = &c;
    fmt::print("  {:<16} {:>12.3f} {:>12.3f}  {}\n", p.band.label(), p.min_contrast,
               p.mean_contrast,
               best ? fmt::format("{} / {} ({:.2f}, {:.1f} dB)", name(best->a), name(best->b),
                                  best->contrast, best->delta_db)
                    : std::string("-"));
  }
  if (r.best_panel >= 0) {
    fmt::print("  best band for telling all categories apart: {} (smallest pair contrast {:.3f})\n",
               r.panels[static_cast<std::size_t>(r.best_panel)].band.label(),
               r.panels[static_cast<std::size_t>(r.best_panel)].min_contrast);
  }
  if (r.best_pair_panel >= 0) {
    fmt::print("  best discriminated pair: {} / {} at {} (C = {:.3f}, {:.1f} dB)\n",
               name(r.best_pair.a), name(r.best_pair.b),
               r.panels[static_cast<std::size_t>(r.best_pair_panel)].band.label(),
               r.best_pair.contrast, r.best_pair.delta_db);
  }
  fmt::print("  {:.2f} s; outputs in {}\n", seconds,
             std::filesystem::absolute(a.out).lexically_normal().string());
}

void add_study(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  args->scene = default_scene_path();
  args->radar = data_path("radars/seed-fig7.toml");
  args->bands = default_study_bands_text();
  auto* cmd = app.add_subcommand(
      "study", "Frequency/polarisation study: one scene at several bands (the seed's figure 7)");
  cmd->add_option("--scene", args->scene, "Scene: a .toml description or a raster")
      ->capture_default_str();
  cmd->add_option("--radar", args->radar,
                  "Radar description (TOML); its frequency and polarisation are replaced")
      ->capture_default_str();
  cmd->add_option("--backscatter", args->backscatter,
                  "Backscatter library (.toml) or table (.csv); default: the standard library");
  cmd->add_option("--bands", args->bands, "Comma-separated FREQUENCY:POLARISATION pairs")
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Output folder (written as a whole)")->capture_default_str();
  add_seed_option(cmd, args->seed, "Fading seed (the same in every panel)");
  cmd->add_option("--panel-size", args->panel_px,
                  "Contact sheet: longer side of a panel, pixels (panels are never enlarged)")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
  cmd->add_flag("--quiet", args->quiet, "No progress (a bar on a terminal, else log lines)");
  cmd->callback([args] { run_study_command(*args); });
}

const Registration reg{"study", add_study};

}  // namespace
}  // namespace ris::app
