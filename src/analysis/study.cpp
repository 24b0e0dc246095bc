#include "ris/analysis/study.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "ris/sensor/radar_params.h"
#include "ris/sim/slar_channels.h"
#include "ris/sim/slar_products.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

}  // namespace

std::string StudyBand::label() const {
  return fmt::format("{:g} GHz {}", frequency_hz / 1e9, to_string(polarisation));
}

std::string StudyBand::slug() const {
  return fmt::format("{:g}GHz_{}", frequency_hz / 1e9, to_string(polarisation));
}

std::vector<StudyBand> parse_study_bands(std::string_view text, const std::string& key) {
  std::vector<StudyBand> bands;
  const std::string expected =
      "expected a comma-separated list of FREQUENCY:POLARISATION, e.g. \"1.25 GHz:HH, 8.6 "
      "GHz:VV\"";
  if (trim(text).empty()) throw InputError("", key, "empty band list; " + expected);
  std::size_t start = 0;
  while (start <= text.size()) {
    const std::size_t comma = std::min(text.find(',', start), text.size());
    const std::string_view entry = trim(text.substr(start, comma - start));
    start = comma + 1;
    if (entry.empty()) {
      throw InputError("", key, fmt::format("empty entry in \"{}\"; {}", text, expected));
    }
    const std::size_t colon = entry.rfind(':');
    if (colon == std::string_view::npos) {
      throw InputError("", key,
                       fmt::format("\"{}\" has no polarisation after ':'; {}", entry, expected));
    }
    StudyBand b;
    try {
      b.frequency_hz = parse_quantity(trim(entry.substr(0, colon)), Quantity::frequency);
      b.polarisation = parse_polarisation(trim(entry.substr(colon + 1)));
    } catch (const std::invalid_argument& e) {
      throw InputError("", key, fmt::format("bad band \"{}\": {}", entry, e.what()));
    }
    if (!(b.frequency_hz > 0.0) || !std::isfinite(b.frequency_hz)) {
      throw InputError("", key,
                       fmt::format("bad band \"{}\": the frequency must be positive", entry));
    }
    for (const StudyBand& other : bands) {
      if (other == b) {
        throw InputError("", key, fmt::format("duplicate band {} in \"{}\"", b.label(), text));
      }
    }
    bands.push_back(b);
    if (comma == text.size()) break;
  }
  return bands;
}

std::string default_study_bands_text() {
  return "1.25 GHz:HH, 5.3 GHz:HH, 8.6 GHz:HH, 8.6 GHz:VV, 8.6 GHz:HV, 13 GHz:HH";
}

std::vector<StudyBand> default_study_bands() {
  return parse_study_bands(default_study_bands_text(), "--bands");
}

void check_study_bands(const std::vector<StudyBand>& bands, const Sigma0Source& sigma0,
                       const std::vector<std::uint16_t>& categories,
                       const std::string& backscatter_file, const std::string& key) {
  for (const StudyBand& b : bands) {
    const RadarBand band{b.frequency_hz, b.polarisation};
    for (std::uint16_t c : categories) {
      if (!sigma0.has_category(c)) continue;  // simulate_slar names it
      try {
        (void)sigma0.sigma0(c, deg_to_rad(30.0), band);
      } catch (const InputError& e) {
        throw InputError(
            backscatter_file, key,
            fmt::format("band {} is outside the backscatter library's validity for category {} "
                        "({}): {}",
                        b.label(), c, sigma0.category_name(c), e.what()));
      }
    }
  }
}

RadarParams radar_for_band(const RadarParams& radar, const StudyBand& band) {
  return radar_at_band(radar, band.frequency_hz, band.polarisation);
}

std::vector<CategoryStats> category_stats(const std::vector<std::int32_t>& labels,
                                          std::span<const std::uint8_t> grey,
                                          std::span<const float> mean_power_w,
                                          const std::vector<std::uint16_t>& categories,
                                          const std::vector<std::string>& names) {
  RIS_CHECK(labels.size() == grey.size() && labels.size() == mean_power_w.size());
  RIS_CHECK(names.size() == categories.size());
  std::vector<std::int32_t> slot(65536, -1);
  for (std::size_t i = 0; i < categories.size(); ++i) {
    slot[categories[i]] = static_cast<std::int32_t>(i);
  }
  struct Sums {
    std::int64_t n = 0;
    double g = 0.0, g2 = 0.0, p = 0.0;
  };
  std::vector<Sums> sums(categories.size());
  for (std::size_t i = 0; i < labels.size(); ++i) {
    if (labels[i] < 0) continue;
    const std::int32_t s = slot[static_cast<std::size_t>(labels[i])];
    if (s < 0) continue;
    Sums& a = sums[static_cast<std::size_t>(s)];
    const double v = grey[i];
    ++a.n;
    a.g += v;
    a.g2 += v * v;
    a.p += mean_power_w[i];
  }
  std::vector<CategoryStats> out;
  for (std::size_t i = 0; i < categories.size(); ++i) {
    const Sums& a = sums[i];
    CategoryStats c;
    c.category = categories[i];
    c.name = names[i];
    c.pixels = a.n;
    if (a.n == 0) {
      c.mean_grey = c.std_grey = c.mean_power_w = kNaN;
    } else {
      const double n = double(a.n);
      c.mean_grey = a.g / n;
      c.std_grey = std::sqrt(std::max(0.0, a.g2 / n - c.mean_grey * c.mean_grey));
      c.mean_power_w = a.p / n;
    }
    out.push_back(c);
  }
  return out;
}

void choose_best(StudyResult& r) {
  r.best_panel = -1;
  double best = 0.0;
  r.null_check_passed = r.null_check_run;
  r.null_max_abs_z = 0.0;
  for (std::size_t i = 0; i < r.panels.size(); ++i) {
    const StudyPanel& p = r.panels[i];
    if (p.separability.score > best) {
      best = p.separability.score;
      r.best_panel = static_cast<int>(i);
    }
    if (r.null_check_run) {
      r.null_max_abs_z = std::max(r.null_max_abs_z, p.null_separability.max_abs_z);
      if (p.null_separability.separated_pairs > 0) r.null_check_passed = false;
    }
  }
}

namespace {

std::vector<std::uint16_t> categories_with_data(const Scene& scene) {
  std::vector<std::uint8_t> seen(65536, 0);
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (scene.valid[i]) seen[scene.category[i]] = 1;
  }
  std::vector<std::uint16_t> used;
  for (std::size_t c = 0; c < seen.size(); ++c) {
    if (seen[c] != 0) used.push_back(static_cast<std::uint16_t>(c));
  }
  return used;
}

// I / F per pixel: the speckled power over the radar-equation factor (the
// mean power of the sigma0 = 1 run); NaN where F is 0.
std::vector<double> calibrated_sigma0(std::span<const float> speckled_w,
                                      std::span<const float> factor_w) {
  RIS_CHECK(speckled_w.size() == factor_w.size());
  std::vector<double> out(speckled_w.size());
  for (std::size_t i = 0; i < out.size(); ++i) {
    out[i] = factor_w[i] > 0.0f ? double(speckled_w[i]) / double(factor_w[i]) : kNaN;
  }
  return out;
}

std::vector<double> looks_per_pixel(const SlarPictures& pic, int lines, int bins) {
  RIS_CHECK(pic.looks.size() == static_cast<std::size_t>(bins));
  std::vector<double> out(static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins));
  for (int l = 0; l < lines; ++l) {
    std::copy(pic.looks.begin(), pic.looks.end(),
              out.begin() + static_cast<std::ptrdiff_t>(l) * bins);
  }
  return out;
}

// The separability of the categories in one rendered run of the band's
// geometry, calibrated by the factor run.
BandSeparability separability_of(const SlarPictures& pic, const SlarSimulation& sim,
                                 const SlarSimulation& factor,
                                 const std::vector<std::int32_t>& labels, const IncidenceBins& ib,
                                 const std::vector<std::uint16_t>& categories,
                                 const SeparabilityOptions& options) {
  const std::vector<double> cal =
      calibrated_sigma0(pic.speckled_power_w, factor.image.mean_power_w);
  const std::vector<double> looks = looks_per_pixel(pic, sim.image.lines, sim.image.bins);
  return band_separability(labels, ib, cal, looks, categories, options);
}

}  // namespace

StudyResult run_study(const Scene& scene, const RadarParams& base_radar, const Sigma0Source& sigma0,
                      const std::string& backscatter_file, const std::vector<StudyBand>& bands,
                      const StudyOptions& options) {
  if (bands.empty()) throw InputError("", options.bands_key, "no bands to study");
  const std::vector<std::uint16_t> used = categories_with_data(scene);
  check_study_bands(bands, sigma0, used, backscatter_file, options.bands_key);

  StudyResult result;
  result.window = options.window;
  result.null_check_run = options.null_check;
  const std::size_t pairs = used.size() * (used.size() - (used.empty() ? 0 : 1)) / 2;
  const double tests = double(std::max<std::size_t>(1, pairs * bands.size()));
  result.z_critical = normal_two_sided_quantile(options.family_error / tests);
  const SeparabilityOptions sep{result.z_critical, options.min_pixels};
  const UniformSigma0 unit(sigma0, nullptr, "sigma0 = 1 (the radar-equation factor)");
  const UniformSigma0 null_law(sigma0, muhleman_sigma0, "muhleman for every category (null check)");

  // Every band's three simulations (speckled, the sigma0 = 1 calibration,
  // the null check's) are channels of one run over one geometry
  // (ris/sim/slar_channels.h): each the bytes of its own run, the geometry
  // computed once. Channel 0 (the first band) keeps the per-sample geometry
  // the attribution reads.
  const std::size_t per_band = options.null_check ? 3 : 2;
  std::vector<SlarChannel> channels;
  for (const StudyBand& band : bands) {
    const RadarParams radar = radar_for_band(base_radar, band);
    channels.push_back({radar, &sigma0, backscatter_file});
    channels.push_back({radar, &unit, backscatter_file});
    if (options.null_check) channels.push_back({radar, &null_law, backscatter_file});
  }
  SlarOptions slar;
  slar.backscatter_file = backscatter_file;
  slar.keep_geometry = true;
  if (options.progress) {
    slar.progress = [&](std::string_view stage, double f) {
      options.progress(fmt::format("{} bands ({})", bands.size(), stage), 0.8 * f);
    };
  }
  const std::vector<SlarSimulation> sims = simulate_slar_channels(scene, channels, slar);
  // The geometry, hence the attribution and the bins, is the same in every band.
  const PixelAttribution at = attribute_pixels(sims.front());
  result.incidence = incidence_bins(sims.front(), at, options.window);
  const std::vector<std::int32_t> labels = at.category;
  result.categories = sims.front().categories;
  result.category_names = sims.front().category_names;
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const StudyBand& band = bands[i];
    if (options.progress) {
      options.progress(fmt::format("{} (separability)", band.label()),
                       0.8 + 0.2 * double(i) / double(bands.size()));
    }
    const SlarSimulation& sim = sims[i * per_band];
    const SlarSimulation& factor = sims[i * per_band + 1];
    const SlarPictures pic = render_slar(sim, options.seed);
    RIS_CHECK(labels.size() == pic.slant_grey.size());

    StudyPanel p;
    p.band = band;
    p.lines = sim.image.lines;
    p.bins = sim.image.bins;
    p.slant_grey.assign(pic.slant_grey.begin(), pic.slant_grey.end());
    p.stats = category_stats(labels, pic.slant_grey, sim.image.mean_power_w, result.categories,
                             result.category_names);
    p.separability =
        separability_of(pic, sim, factor, labels, result.incidence, result.categories, sep);
    if (options.null_check) {
      const SlarSimulation& null_sim = sims[i * per_band + 2];
      p.null_separability = separability_of(render_slar(null_sim, options.seed), null_sim, factor,
                                            labels, result.incidence, result.categories, sep);
    }
    SlarRunInfo info{options.scene_path, base_radar.source_file, backscatter_file, options.seed, 0};
    p.simulation = slar_metadata(scene, sim, pic, info);
    result.panels.push_back(std::move(p));
  }
  result.incidence.bin = {};
  result.incidence.incidence_rad = {};
  choose_best(result);
  return result;
}

}  // namespace ris
