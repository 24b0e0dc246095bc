// The frequency/polarisation study (the seed's figure 7): one scene and one
// track imaged at several (frequency, polarisation) pairs, with per-category
// greytone statistics and the contrast between categories in each panel, to
// choose the band that best separates the scene's categories.
//
// Each panel is a full SLAR run through the public pipeline (simulate_slar,
// render_slar) with the radar file re-read with its `frequency` and
// `polarisation` keys replaced, so every frequency-dependent default (the
// reference cell's wavelength, the seed's equation-16 N = 2 R phi^2 / lambda)
// follows the band. The geometry does not depend on the band, but
// simulate_slar offers no way to pass one in, so it is recomputed per panel.
//
// Category attribution (pure_category_map): a slant-range pixel is given to
// category c when every visible scene element that contributes power to it
// is of category c. An element contributes to the range bins its slant-range
// span [min(R_near_end, R, R_far_end), max(...)] overlaps (slar_image.h) on
// every azimuth line within the footprint half-width w(R)/2 = R phi / 2 of
// its own line, plus one line (conservative: the image counts partial line
// overlaps), and every line of that footprint window lies inside the image
// and has such elements (a footprint that reaches past the track's ends, or
// over a line with nothing in the bin, would lower the power). Pixels
// flagged shadow, layover or no data are never attributed.
// Statistics are taken on the panel's greytones (after speckle, as an
// interpreter sees them) and on the mean power before speckle.
//
// Contrast between categories a and b in a panel (study_contrast):
//   C_ab = |mean_a - mean_b| / sqrt((var_a + var_b) / 2)
// over greytones (the two-class separability d' with a pooled standard
// deviation; speckle and the range trend inside a category widen var), and,
// beside it, delta_db = |10 log10(Pbar_a / Pbar_b)| where Pbar is a
// category's mean of the mean (pre-speckle) power over its pixels.
// The pair that discriminates best is the (panel, pair) of largest C; the
// panel that best separates all categories is the one whose smallest C over
// all pairs is largest (every category told from every other), ties to the
// larger mean C.
//
// Example:
//   auto bands = ris::parse_study_bands("1.25 GHz:HH, 8.6 GHz:VV", "--bands");
//   ris::StudyResult r = ris::run_study(scene, ris::load_radar("radar.toml"), *sigma0,
//                                       "lib.toml", bands);
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
// model's validity throws InputError(key "--bands") naming the band, the
// category and the library's own complaint.
void check_study_bands(const std::vector<StudyBand>& bands, const Sigma0Source& sigma0,
                       const std::vector<std::uint16_t>& categories,
                       const std::string& backscatter_file);

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

struct PairContrast {
  std::uint16_t a = 0, b = 0;  // a < b
  double contrast = 0.0;       // C_ab; NaN when either has no pixels
  double delta_db = 0.0;
};

// C_ab and delta_db of two categories (see the header comment).
PairContrast study_contrast(const CategoryStats& a, const CategoryStats& b);

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
  std::vector<PairContrast> pairs;  // every a < b
  double min_contrast = 0.0;        // NaN with fewer than two reported categories
  double mean_contrast = 0.0;
  nlohmann::json simulation;  // slar_metadata of the run (radar, derived, ...)
};

struct StudyResult {
  std::vector<StudyPanel> panels;
  std::vector<std::uint16_t> categories;
  std::vector<std::string> category_names;
  int best_panel = -1;       // separates all categories best
  int best_pair_panel = -1;  // the panel of the best pair
  PairContrast best_pair;
};

struct StudyOptions {
  std::uint64_t seed = 1;  // the same fading seed in every panel
  std::string scene_path;  // for each panel's metadata
  std::function<void(std::string_view, double)> progress;
};

// Runs the study. Throws InputError for bad input (see check_study_bands and
// simulate_slar).
// radar: as loaded (its source_file is named in each panel's metadata).
StudyResult run_study(const Scene& scene, const RadarParams& radar, const Sigma0Source& sigma0,
                      const std::string& backscatter_file, const std::vector<StudyBand>& bands,
                      const StudyOptions& options = {});

// Best panel and pair from the panels' contrasts (fills best_*).
void choose_best(StudyResult& result);

struct StudyRunInfo {
  std::string scene_path;
  std::string radar_path;
  std::string backscatter_path;
  std::uint64_t seed = 0;
};

// Writes, through StagedDirectory (all or nothing):
//   panel_<i>_<band>.png  slant-range greytones of each panel
//   contact_sheet.png     the panels side by side, labelled (the seed's fig. 7)
//   categories.csv        panel, band, category: pixels, greytone mean/std,
//                         mean power (dB W)
//   contrast.csv          panel, band, pair: C_ab, delta_db
//   metadata.json         inputs, bands, the choices and each run's metadata
void write_study_products(const std::filesystem::path& out_dir, const StudyResult& result,
                          const StudyRunInfo& info, const ContactSheetStyle& sheet_style = {});

}  // namespace ris
