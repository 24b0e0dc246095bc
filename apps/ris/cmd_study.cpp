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

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "command_registry.h"
#include "ris/analysis/study.h"
#include "ris/analysis/study_request.h"
#include "ris/util/error.h"
#include "ris/util/progress.h"
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

// --range-fraction LO,HI into the request's two fractions.
void parse_range_fraction(const std::string& text, StudyRequest& q) {
  const auto comma = text.find(',');
  try {
    if (comma == std::string::npos) throw std::invalid_argument("no comma");
    q.range_lo_fraction = std::stod(text.substr(0, comma));
    q.range_hi_fraction = std::stod(text.substr(comma + 1));
  } catch (const std::exception&) {
    throw InputError("", "--range-fraction",
                     fmt::format("expected LO,HI (fractions of the swath, e.g. 0.3333,0.6667), "
                                 "got \"{}\"",
                                 text));
  }
}

// The command line as a study request (ris/analysis/study_request.h): what
// was given wins over the study file, which wins over the defaults.
StudyRequest study_request(const StudyArgs& a) {
  StudyRequest q;
  q.study_file = a.study;
  if (a.scene_given) q.scene = a.scene;
  if (a.radar_given) q.radar = a.radar;
  if (!a.backscatter.empty()) q.backscatter = a.backscatter;
  if (a.bands_given) q.bands = a.bands;
  if (a.seed_given) q.seed = a.seed;
  if (!a.range_fraction.empty()) parse_range_fraction(a.range_fraction, q);
  if (!a.incidence_bin.empty()) q.incidence_bin = a.incidence_bin;
  q.null_check = !a.no_null_check;
  q.panel_px = a.panel_px;
  q.threads = a.threads;
  return q;
}

void print_study(const StudyResult& r, const StudyRunInfo& a, const std::string& title) {
  const auto name = [&](std::uint16_t c) {
    for (std::size_t i = 0; i < r.categories.size(); ++i)
      if (r.categories[i] == c) return r.category_names[i];
    return std::to_string(c);
  };
  fmt::print("{}study of {} with {} at {} bands\n", title.empty() ? "" : title + ": ", a.scene_path,
             a.radar_path, r.panels.size());
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

void run_study_command(const StudyArgs& a) {
  const auto t0 = std::chrono::steady_clock::now();
  StudyRequest q = study_request(a);
  // A bar on a terminal, plain lines in a log, nothing with --quiet.
  auto bar = std::make_shared<ProgressBar>("study", 100, "%", a.quiet);
  auto done_pct = std::make_shared<std::int64_t>(0);
  if (bar->enabled()) {
    q.progress = [bar, done_pct](std::string_view stage, double fraction) {
      const auto pct = static_cast<std::int64_t>(100.0 * fraction);
      bar->advance(pct - *done_pct);
      *done_pct = pct;
      bar->set_stage(std::string(stage));
    };
  }
  const ResolvedStudy s = resolve_study(q);
  const StudyResult r = run_resolved_study(s);
  write_study_products(a.out, r, s.info, s.style);
  bar->finish();

  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  print_study(r, s.info, s.config.name);
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
