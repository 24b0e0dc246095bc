// The frequency/polarisation study (the seed's figure 7): one scene and one
// track imaged at several (frequency, polarisation) pairs, to find the band
// that best tells the scene's categories apart.
//
// Each panel is a full SLAR run through the public pipeline (simulate_slar,
// render_slar) with the radar at the band (radar_at_band: every
// frequency-dependent default follows it, e.g. the seed's equation-16
// N = 2 R phi^2 / lambda). Categories are compared by calibrated sigma0 at
// matched geometry, with speckle at the radar's number of looks, pair by pair
// (ris/analysis/study_separability.h): per band, two more runs of the same
// geometry give each pixel's radar-equation factor (sigma0 = 1 everywhere)
// and the null check (one backscatter, Muhleman's law, for every category:
// no pair may then be separated beyond its sampling error).
//
// Category attribution (attribute_pixels, pure_category_map): a slant-range
// pixel is given to category c when every visible scene element that
// contributes power to it is of category c. An element contributes to the
// range bins its slant-range span [min(R_near_end, R, R_far_end), max(...)]
// overlaps (slar_image.h) on every azimuth line within the footprint
// half-width w(R)/2 = R phi / 2 of its own line, plus one line
// (conservative: the image counts partial line overlaps), and every line of
// that footprint window lies inside the image and has such elements (a
// footprint that reaches past the track's ends, or over a line with nothing
// in the bin, would lower the power). Pixels flagged shadow, layover or no
// data are never attributed. The geometry does not depend on the band, so
// the attribution is computed once.
//
// Greytone statistics per category (category_stats) are kept for the
// interpreter's view (categories.csv); they do not rank bands.
//
// Example:
//   auto bands = ris::parse_study_bands("1.25 GHz:HH, 8.6 GHz:VV", "--bands");
//   ris::StudyOptions o;
//   o.window.range_lo_fraction = 1.0 / 3.0;   // the seed's middle third
//   o.window.range_hi_fraction = 2.0 / 3.0;
//   ris::StudyResult r = ris::run_study(scene, ris::load_radar("radar.toml"), *sigma0,
//                                       "lib.toml", bands, o);
//   ris::write_study_products("study", r, info);
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/analysis/study_separability.h"
#include "ris/backscatter/polarisation.h"
#include "ris/backscatter/sigma0_source.h"
#include "ris/image/contact_sheet.h"
#include "ris/scene/scene.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

struct StudyBand {
  double frequency_hz = 0.0;
  Polarisation polarisation = Polarisation::HH;
  // "8.6 GHz HH"
  std::string label() const;
  // "8.6GHz_HH", for file names
  std::string slug() const;
  bool operator==(const StudyBand&) const = default;
};

// Parses "F:P, F:P, ..." (F a frequency with units, P HH/VV/HV/VH). Throws
// InputError(file = "", key) for an empty list, a malformed or non-positive
// entry, or a duplicate band.
std::vector<StudyBand> parse_study_bands(std::string_view text, const std::string& key);

// The default list: the two bands the seed's figure 7 names (8.6 GHz HH and
// VV, its panel labels; the OCR of the other four is lost) completed with
// L, C and Ku band and a cross-polarised X band, all inside the standard
// library's 1-18 GHz validity: 1.25 HH, 5.3 HH, 8.6 HH, 8.6 VV, 8.6 HV, 13 HH.
std::vector<StudyBand> default_study_bands();
std::string default_study_bands_text();

// Checks every band against the backscatter source for every category the
// scene uses (that the source has), before any simulation: a band outside a
// model's validity throws InputError(key, "--bands" by default) naming the
// band, the category and the library's own complaint.
void check_study_bands(const std::vector<StudyBand>& bands, const Sigma0Source& sigma0,
                       const std::vector<std::uint16_t>& categories,
                       const std::string& backscatter_file, const std::string& key = "--bands");

// The radar at the band's frequency and polarisation (radar_at_band,
// ris/sensor/radar_params.h): what its file would give with `frequency` and
// `polarisation` replaced.
RadarParams radar_for_band(const RadarParams& radar, const StudyBand& band);

// lines x bins: the category a slant-range pixel is attributed to, or -1
// (see the header comment).
// sim must keep its per-sample geometry (SlarOptions::keep_geometry).
std::vector<std::int32_t> pure_category_map(const SlarSimulation& sim);

struct CategoryStats {
  std::uint16_t category = 0;
  std::string name;
  std::int64_t pixels = 0;
  double mean_grey = 0.0;  // NaN when pixels == 0
  double std_grey = 0.0;
  double mean_power_w = 0.0;  // mean of the pre-speckle mean power
};

// Greytone statistics of each category over its attributed pixels.
// `categories` lists the categories to report (one entry each, in order).
std::vector<CategoryStats> category_stats(const std::vector<std::int32_t>& labels,
                                          std::span<const std::uint8_t> grey,
                                          std::span<const float> mean_power_w,
                                          const std::vector<std::uint16_t>& categories,
                                          const std::vector<std::string>& names);

struct StudyPanel {
  StudyBand band;
  int lines = 0, bins = 0;
  std::vector<std::uint8_t> slant_grey;  // lines x bins
  std::vector<CategoryStats> stats;
  BandSeparability separability;       // the library's backscatter
  BandSeparability null_separability;  // one law for all (empty without the null check)
  nlohmann::json simulation;           // slar_metadata of the run (radar, derived, ...)
};

struct StudyResult {
  std::vector<StudyPanel> panels;
  std::vector<std::uint16_t> categories;
  std::vector<std::string> category_names;
  StudyWindow window;
  IncidenceBins incidence;  // the bins' layout (its per-pixel map is dropped)
  double z_critical = 0.0;
  int best_panel = -1;  // the largest score; -1: no band separates these categories
  bool null_check_run = false;
  bool null_check_passed = false;  // no pair separated in any band's null run
  double null_max_abs_z = 0.0;
};

struct StudyOptions {
  std::uint64_t seed = 1;  // the same fading seed in every panel
  std::string scene_path;  // for each panel's metadata
  StudyWindow window;
  bool null_check = true;
  // Family error rate of the separation tests: z_critical is the two-sided
  // normal quantile of family_error / (bands x pairs) (Bonferroni).
  double family_error = 0.01;
  std::int64_t min_pixels = 20;  // per category and incidence bin
  // The option or argument the bands came from, named by a band error
  // ("--bands" on the command line, "bands" in Python).
  std::string bands_key = "--bands";
  std::function<void(std::string_view, double)> progress;
};

// Runs the study. Throws InputError for bad input (see check_study_bands and
// simulate_slar).
// radar: as loaded (its source_file is named in each panel's metadata).
StudyResult run_study(const Scene& scene, const RadarParams& radar, const Sigma0Source& sigma0,
                      const std::string& backscatter_file, const std::vector<StudyBand>& bands,
                      const StudyOptions& options = {});

// Best panel from the panels' scores (fills best_panel, -1 when every score
// is 0) and the null check's verdict from the null runs.
void choose_best(StudyResult& result);

// "best band: 8.6 GHz HH" or "no band separates these categories".
std::string study_verdict(const StudyResult& result);

struct StudyRunInfo {
  std::string scene_path;
  std::string radar_path;
  std::string backscatter_path;
  std::uint64_t seed = 0;
};

// The study's tables and metadata, exactly as write_study_products writes
// them into categories.csv, separability.csv, separability_bins.csv and
// metadata.json (Python's ris.study reads its tables from here).
struct StudyTables {
  std::string categories_csv, separability_csv, separability_bins_csv;
  nlohmann::json metadata;
};
StudyTables study_tables(const StudyResult& result, const StudyRunInfo& info);

// Writes, through StagedDirectory (all or nothing):
//   panel_<i>_<band>.png  slant-range greytones of each panel
//   contact_sheet.png     the panels side by side, labelled (the seed's fig. 7)
//   categories.csv        panel, band, category: pixels, greytone mean/std,
//                         mean power (dB W)
//   separability.csv      run (library / null), panel, band, pair: bins,
//                         delta_db, z, jm, jm_noise, separated
//   separability_bins.csv the same per incidence bin
//   metadata.json         inputs, window, method, the verdict, the null
//                         check and each run's metadata
void write_study_products(const std::filesystem::path& out_dir, const StudyResult& result,
                          const StudyRunInfo& info, const ContactSheetStyle& sheet_style = {});

}  // namespace ris
