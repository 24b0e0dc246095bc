// `ris study`: the frequency/polarisation study (the seed's figure 7): one
// scene and track imaged at several (frequency, polarisation) pairs, with a
// contact sheet, per-category greytone statistics and the separability of
// every pair of categories at matched geometry (ris/analysis/study.h).
//
//   ris study [--study FILE] [--scene S] [--radar R] [--backscatter B]
//             [--bands "1.25 GHz:HH, 8.6 GHz:VV, ..."] [--range-fraction LO,HI]
//             [--incidence-bin ANGLE] [--no-null-check] [--out DIR] [--seed N]
//             [--panel-size PX] [--threads N]
//
// With no arguments: the standard scene, the seed's figure-7 radar
// (data/radars/seed-fig7.toml) and the standard backscatter library at the
// default bands over the whole swath, into ./study. --study reads a study
// file (data/studies/seed-fig7.toml); options given on the command line win.
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
#include "ris/analysis/study.h"
#include "ris/analysis/study_config.h"
#include "ris/backscatter/library.h"
#include "ris/scene/scene_builder.h"
#include "ris/scene/scene_io.h"
#include "ris/sensor/one_channel_radar.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"
#include "ris/util/progress.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"
#include "seed_option.h"

namespace ris::app {
namespace {

struct StudyArgs {
  std::string study;
  std::string range_fraction;
  std::string incidence_bin;
  bool no_null_check = false;
  std::string scene;
  std::string radar;
  std::string backscatter;
  std::string bands;
  std::string out = "study";
  std::uint64_t seed = 1;
  int threads = 0;
  int panel_px = 360;
  bool quiet = false;
  // Given on the command line (these win over the study file).
  bool scene_given = false, radar_given = false, bands_given = false, seed_given = false;
};

Scene load_study_scene(const std::string& path) {
  if (std::filesystem::path(path).extension() == ".toml") {
    return build_scene(read_scene_description(path));
  }
  return read_scene(path);
}

// The window from the command line (which wins) or the study file.
StudyWindow study_window(const StudyArgs& a, const StudyConfig& c) {
  StudyWindow w;
  if (c.range_lo_fraction) w.range_lo_fraction = *c.range_lo_fraction;
  if (c.range_hi_fraction) w.range_hi_fraction = *c.range_hi_fraction;
  if (c.incidence_bin_rad) w.incidence_bin_rad = *c.incidence_bin_rad;
  if (!a.range_fraction.empty()) {
    const auto comma = a.range_fraction.find(',');
    try {
      if (comma == std::string::npos) throw std::invalid_argument("no comma");
      w.range_lo_fraction = std::stod(a.range_fraction.substr(0, comma));
      w.range_hi_fraction = std::stod(a.range_fraction.substr(comma + 1));
    } catch (const std::exception&) {
      throw InputError("", "--range-fraction",
                       fmt::format("expected LO,HI (fractions of the swath, e.g. 0.3333,0.6667), "
                                   "got \"{}\"",
                                   a.range_fraction));
    }
    check_study_window(w, "", "--range-fraction");
  }
  if (!a.incidence_bin.empty()) {
    try {
      w.incidence_bin_rad = parse_quantity(a.incidence_bin, Quantity::angle);
    } catch (const std::invalid_argument& e) {
      throw InputError("", "--incidence-bin", e.what());
    }
    check_study_window(w, "", "--incidence-bin");
  }
  return w;
}

// The file's inputs where the command line left the default.
StudyArgs with_study_file(StudyArgs a, const StudyConfig& c) {
  if (c.scene && !a.scene_given) a.scene = *c.scene;
  if (c.radar && !a.radar_given) a.radar = *c.radar;
  if (c.backscatter && a.backscatter.empty()) a.backscatter = *c.backscatter;
  if (c.bands && !a.bands_given) a.bands = *c.bands;
  if (c.seed && !a.seed_given) a.seed = *c.seed;
  return a;
}

void print_study(const StudyResult& r, const StudyArgs& a, const std::string& title) {
  const auto name = [&](std::uint16_t c) {
    for (std::size_t i = 0; i < r.categories.size(); ++i)
      if (r.categories[i] == c) return r.category_names[i];
    return std::to_string(c);
  };
  fmt::print("{}study of {} with {} at {} bands\n", title.empty() ? "" : title + ": ", a.scene,
             a.radar, r.panels.size());
  fmt::print(
      "  window: slant range {:.0f}-{:.0f} m ({:.3f}-{:.3f} of the swath), {} incidence bins "
      "of {:g} deg from {:.1f} deg\n",
      r.incidence.range_lo_m, r.incidence.range_hi_m, r.window.range_lo_fraction,
      r.window.range_hi_fraction, r.incidence.count, rad_to_deg(r.incidence.width_rad),
      rad_to_deg(r.incidence.first_lo_rad));
  fmt::print("  {:<14} {:>10} {:>8} {:>8}  best separated pair (JM, dB)\n", "band", "separated",
             "score", "min JM");
  for (const StudyPanel& p : r.panels) {
    const BandSeparability& s = p.separability;
    const PairSeparability* best = nullptr;
    for (const PairSeparability& c : s.pairs)
      if (c.separated && (best == nullptr || c.jm > best->jm)) best = &c;
    fmt::print("  {:<14} {:>10} {:>8.4f} {:>8.4f}  {}\n", p.band.label(),
               fmt::format("{}/{}", s.separated_pairs, s.compared_pairs), s.score, s.min_jm,
               best ? fmt::format("{} / {} ({:.3f}, {:+.2f} dB)", name(best->a), name(best->b),
                                  best->jm, best->delta_db)
                    : std::string("-"));
  }
  if (r.null_check_run) {
    fmt::print(
        "  null check (every category Muhleman's law): {} (largest |z| {:.2f}, limit {:.2f})\n",
        r.null_check_passed ? "passed" : "FAILED: the geometry alone separates pairs",
        r.null_max_abs_z, r.z_critical);
  }
  if (r.best_panel >= 0) {
    fmt::print("  best band for telling the categories apart: {} (score {:.4f})\n",
               r.panels[static_cast<std::size_t>(r.best_panel)].band.label(),
               r.panels[static_cast<std::size_t>(r.best_panel)].separability.score);
  } else {
    fmt::print(
        "  no band separates these categories (no pair beyond its sampling error, "
        "|z| <= {:.2f})\n",
        r.z_critical);
  }
}

void run_study_command(const StudyArgs& given) {
  const StudyConfig config = given.study.empty() ? StudyConfig{} : read_study_config(given.study);
  const StudyArgs a = with_study_file(given, config);
  checked_thread_count(a.threads, "--threads");  // the cap (ris/util/resource_guard.h)
  if (a.panel_px < 16) {
    throw InputError("", "--panel-size", fmt::format("expected 16 or more, got {}", a.panel_px));
  }
  if (a.threads > 0) omp_set_num_threads(a.threads);
  const auto t0 = std::chrono::steady_clock::now();
  // Bands first: a bad list fails before any expensive work.
  const std::vector<StudyBand> bands = parse_study_bands(a.bands, "--bands");

  StudyOptions options;
  options.window = study_window(a, config);
  options.null_check = !a.no_null_check;
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
  const RadarParams radar = load_one_channel_radar(a.radar, "ris study");
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
  print_study(r, a, config.name);
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
  cmd->add_option("--study", args->study,
                  "Study file (TOML, data/studies/): inputs and window; options given here win");
  auto* scene = cmd->add_option("--scene", args->scene, "Scene: a .toml description or a raster")
                    ->capture_default_str();
  auto* radar =
      cmd->add_option("--radar", args->radar,
                      "Radar description (TOML); its frequency and polarisation are replaced")
          ->capture_default_str();
  cmd->add_option("--backscatter", args->backscatter,
                  "Backscatter library (.toml) or table (.csv); default: the standard library");
  auto* bands =
      cmd->add_option("--bands", args->bands, "Comma-separated FREQUENCY:POLARISATION pairs")
          ->capture_default_str();
  cmd->add_option("--range-fraction", args->range_fraction,
                  "Range interval compared, fractions of the swath LO,HI (default 0,1; the "
                  "seed's middle third: 0.3333,0.6667)");
  cmd->add_option("--incidence-bin", args->incidence_bin,
                  "Width of the local-incidence bins pairs are compared in (default 1 deg)");
  cmd->add_flag("--no-null-check", args->no_null_check,
                "Skip the null check (one backscatter for every category)");
  cmd->add_option("--out", args->out, "Output folder (written as a whole)")->capture_default_str();
  auto* seed = add_seed_option(cmd, args->seed, "Fading seed (the same in every panel)");
  cmd->add_option("--panel-size", args->panel_px,
                  "Contact sheet: longer side of a panel, pixels (panels are never enlarged)")
      ->capture_default_str();
  cmd->add_option("--threads", args->threads, "Threads (0: all cores)")->capture_default_str();
  cmd->add_flag("--quiet", args->quiet, "No progress (a bar on a terminal, else log lines)");
  cmd->callback([args, scene, radar, bands, seed] {
    args->scene_given = scene->count() > 0;
    args->radar_given = radar->count() > 0;
    args->bands_given = bands->count() > 0;
    args->seed_given = seed->count() > 0;
    run_study_command(*args);
  });
}

const Registration reg{"study", add_study};

}  // namespace
}  // namespace ris::app
