#include "ris/sim/study.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "ris/image/contact_sheet.h"
#include "ris/io/atomic_file.h"
#include "ris/io/raster_io.h"
#include "ris/sensor/radar_params.h"
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

std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::string csv_number(double v, int decimals) {
  return std::isfinite(v) ? fmt::format("{:.{}f}", v, decimals) : std::string();
}

// JSON has no NaN: missing values are null.
nlohmann::json json_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
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
                       const std::string& backscatter_file) {
  for (const StudyBand& b : bands) {
    const RadarBand band{b.frequency_hz, b.polarisation};
    for (std::uint16_t c : categories) {
      if (!sigma0.has_category(c)) continue;  // simulate_slar names it
      try {
        (void)sigma0.sigma0(c, deg_to_rad(30.0), band);
      } catch (const InputError& e) {
        throw InputError(
            backscatter_file, "--bands",
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

std::vector<std::int32_t> pure_category_map(const SlarSimulation& sim) {
  constexpr std::int32_t kEmpty = -1;
  constexpr std::int32_t kMixed = -2;
  const SlarGeometry& g = sim.geometry;
  // Needs the per-sample geometry: simulate_slar with SlarOptions::keep_geometry.
  RIS_CHECK(g.flags.size() ==
            static_cast<std::size_t>(g.lines) * static_cast<std::size_t>(g.samples));
  const SlarImage& img = sim.image;
  RIS_CHECK(g.lines == img.lines);
  const int lines = img.lines;
  const int bins = img.bins;
  const auto merge = [](std::int32_t& cell, std::int32_t c) {
    if (cell == kEmpty) {
      cell = c;
    } else if (cell != c) {
      cell = kMixed;
    }
  };

  // The categories reaching each (line, bin) from that line's own elements.
  std::vector<std::int32_t> own(static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins),
                                kEmpty);
  for (int l = 0; l < g.lines; ++l) {
    for (int s = 0; s < g.samples; ++s) {
      const std::size_t i = g.index(l, s);
      if (!sample_visible(g.flags[i])) continue;
      const double r = g.slant_range_m[i];
      const double a = g.range_near_end_m[i];
      const double b = g.range_far_end_m[i];
      if (!std::isfinite(r)) continue;
      double r0 = r, r1 = r;
      if (std::isfinite(a)) r0 = std::min(r0, a), r1 = std::max(r1, a);
      if (std::isfinite(b)) r0 = std::min(r0, b), r1 = std::max(r1, b);
      const double k0f = std::floor((r0 - img.range.near_m) / img.range.bin_m);
      const double k1f = std::floor((r1 - img.range.near_m) / img.range.bin_m);
      if (k1f < 0.0 || k0f >= bins) continue;
      const int k0 = static_cast<int>(std::max(k0f, 0.0));
      const int k1 = static_cast<int>(std::min(k1f, double(bins - 1)));
      for (int k = k0; k <= k1; ++k) merge(own[img.index(l, k)], g.category[i]);
    }
  }

  // Azimuth: the footprint w(R) = R phi gathers lines within w/2 (plus the
  // line strip's half width) of the pixel's line.
  const double phi = sim.radar.azimuth_beamwidth_rad;
  const double ds = img.line_spacing_m;
  std::vector<std::int32_t> label(own.size(), kEmpty);
  for (int k = 0; k < bins; ++k) {
    const double w = slar_footprint_m(img.range.centre_m(k), phi);
    const int h = static_cast<int>(std::ceil(0.5 * w / ds + 0.5));
    for (int l = 0; l < lines; ++l) {
      const std::size_t p = img.index(l, k);
      if ((img.mask[p] & (pixel_flag::kShadow | pixel_flag::kLayover | pixel_flag::kNoData)) != 0) {
        continue;
      }
      // The whole footprint must lie on imaged lines, and every line of it
      // must put elements of one category into this bin: a line with none
      // (shadow, beyond the scene or the track's ends) would lower the power.
      if (l - h < 0 || l + h >= lines) continue;
      std::int32_t cell = kEmpty;
      for (int m = l - h; m <= l + h; ++m) {
        const std::int32_t o = own[img.index(m, k)];
        if (o < 0) {
          cell = kMixed;
          break;
        }
        merge(cell, o);
        if (cell == kMixed) break;
      }
      label[p] = cell >= 0 ? cell : kEmpty;
    }
  }
  return label;
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

PairContrast study_contrast(const CategoryStats& a, const CategoryStats& b) {
  PairContrast p;
  p.a = std::min(a.category, b.category);
  p.b = std::max(a.category, b.category);
  if (a.pixels == 0 || b.pixels == 0) {
    p.contrast = p.delta_db = kNaN;
    return p;
  }
  // Floor: the standard deviation of uniform quantisation to whole
  // greytones, 1/sqrt(12), so a noiseless image still gives a finite value.
  const double pooled = std::max(
      std::sqrt(0.5 * (a.std_grey * a.std_grey + b.std_grey * b.std_grey)), 1.0 / std::sqrt(12.0));
  p.contrast = std::abs(a.mean_grey - b.mean_grey) / pooled;
  p.delta_db = (a.mean_power_w > 0.0 && b.mean_power_w > 0.0)
                   ? std::abs(10.0 * std::log10(a.mean_power_w / b.mean_power_w))
                   : kNaN;
  return p;
}

void choose_best(StudyResult& r) {
  r.best_panel = -1;
  r.best_pair_panel = -1;
  r.best_pair = PairContrast{};
  double best_pair = -1.0;
  for (std::size_t i = 0; i < r.panels.size(); ++i) {
    StudyPanel& p = r.panels[i];
    double lo = std::numeric_limits<double>::infinity(), sum = 0.0;
    int n = 0;
    for (const PairContrast& c : p.pairs) {
      if (!std::isfinite(c.contrast)) continue;
      lo = std::min(lo, c.contrast);
      sum += c.contrast;
      ++n;
      if (c.contrast > best_pair) {
        best_pair = c.contrast;
        r.best_pair = c;
        r.best_pair_panel = static_cast<int>(i);
      }
    }
    p.min_contrast = n > 0 ? lo : kNaN;
    p.mean_contrast = n > 0 ? sum / n : kNaN;
    if (n == 0) continue;
    const StudyPanel* best =
        r.best_panel >= 0 ? &r.panels[static_cast<std::size_t>(r.best_panel)] : nullptr;
    if (best == nullptr || p.min_contrast > best->min_contrast ||
        (p.min_contrast == best->min_contrast && p.mean_contrast > best->mean_contrast)) {
      r.best_panel = static_cast<int>(i);
    }
  }
}

StudyResult run_study(const Scene& scene, const RadarParams& base_radar, const Sigma0Source& sigma0,
                      const std::string& backscatter_file, const std::vector<StudyBand>& bands,
                      const StudyOptions& options) {
  if (bands.empty()) throw InputError("", "--bands", "no bands to study");
  std::vector<std::uint8_t> seen(65536, 0);
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (scene.valid[i]) seen[scene.category[i]] = 1;
  }
  std::vector<std::uint16_t> used;
  for (std::size_t c = 0; c < seen.size(); ++c) {
    if (seen[c] != 0) used.push_back(static_cast<std::uint16_t>(c));
  }
  check_study_bands(bands, sigma0, used, backscatter_file);

  StudyResult result;
  std::vector<std::int32_t> labels;
  const double n_bands = double(bands.size());
  for (std::size_t i = 0; i < bands.size(); ++i) {
    const StudyBand& band = bands[i];
    SlarOptions slar;
    slar.backscatter_file = backscatter_file;
    slar.keep_geometry = true;  // the attribution reads the per-sample geometry
    if (options.progress) {
      slar.progress = [&](std::string_view stage, double f) {
        options.progress(fmt::format("{} ({})", band.label(), stage), (double(i) + f) / n_bands);
      };
    }
    const RadarParams radar = radar_for_band(base_radar, band);
    const SlarSimulation sim = simulate_slar(scene, radar, sigma0, slar);
    const SlarPictures pic = render_slar(sim, options.seed);
    // The geometry, hence the attribution, is the same in every band.
    if (labels.empty()) {
      labels = pure_category_map(sim);
      result.categories = sim.categories;
      result.category_names = sim.category_names;
    }
    RIS_CHECK(labels.size() == pic.slant_grey.size());
    StudyPanel p;
    p.band = band;
    p.lines = sim.image.lines;
    p.bins = sim.image.bins;
    p.slant_grey.assign(pic.slant_grey.begin(), pic.slant_grey.end());
    p.stats = category_stats(labels, pic.slant_grey, sim.image.mean_power_w, result.categories,
                             result.category_names);
    for (std::size_t a = 0; a < p.stats.size(); ++a) {
      for (std::size_t b = a + 1; b < p.stats.size(); ++b) {
        p.pairs.push_back(study_contrast(p.stats[a], p.stats[b]));
      }
    }
    SlarRunInfo info{options.scene_path, base_radar.source_file, backscatter_file, options.seed, 0};
    p.simulation = slar_metadata(scene, sim, pic, info);
    result.panels.push_back(std::move(p));
  }
  choose_best(result);
  return result;
}

namespace {

std::string category_label(const StudyResult& r, std::uint16_t c) {
  for (std::size_t i = 0; i < r.categories.size(); ++i) {
    if (r.categories[i] == c) return r.category_names[i];
  }
  return std::to_string(c);
}

std::string panel_file(std::size_t i, const StudyBand& b) {
  return fmt::format("panel_{}_{}.png", i + 1, b.slug());
}

}  // namespace

void write_study_products(const std::filesystem::path& out_dir, const StudyResult& r,
                          const StudyRunInfo& info, const ContactSheetStyle& sheet_style) {
  StagedDirectory dir(out_dir);
  std::vector<ContactPanel> sheet;
  std::string cats =
      "panel,band,frequency_ghz,polarisation,category,name,pixels,mean_grey,std_grey,"
      "mean_power_dbw\n";
  std::string pairs = "panel,band,category_a,name_a,category_b,name_b,contrast,delta_db\n";
  nlohmann::json panels = nlohmann::json::array();
  for (std::size_t i = 0; i < r.panels.size(); ++i) {
    const StudyPanel& p = r.panels[i];
    write_png_gray(dir.path(panel_file(i, p.band)), p.slant_grey.data(), p.bins, p.lines);
    sheet.push_back({p.slant_grey.data(), p.bins, p.lines, p.band.label()});
    for (const CategoryStats& c : p.stats) {
      cats +=
          fmt::format("{},{},{:g},{},{},{},{},{},{},{}\n", i + 1, csv_text(p.band.label()),
                      p.band.frequency_hz / 1e9, to_string(p.band.polarisation), c.category,
                      csv_text(c.name), c.pixels, csv_number(c.mean_grey, 3),
                      csv_number(c.std_grey, 3), csv_number(10.0 * std::log10(c.mean_power_w), 3));
    }
    for (const PairContrast& c : p.pairs) {
      pairs += fmt::format("{},{},{},{},{},{},{},{}\n", i + 1, csv_text(p.band.label()), c.a,
                           csv_text(category_label(r, c.a)), c.b, csv_text(category_label(r, c.b)),
                           csv_number(c.contrast, 4), csv_number(c.delta_db, 3));
    }
    panels.push_back({{"panel", i + 1},
                      {"band", p.band.label()},
                      {"frequency_hz", p.band.frequency_hz},
                      {"polarisation", to_string(p.band.polarisation)},
                      {"file", panel_file(i, p.band)},
                      {"min_contrast", json_number(p.min_contrast)},
                      {"mean_contrast", json_number(p.mean_contrast)},
                      {"simulation", p.simulation}});
  }
  const std::string scene_name = std::filesystem::path(info.scene_path).stem().string();
  write_contact_sheet_png(
      dir.path("contact_sheet.png"),
      scene_name.empty()
          ? std::string("Frequency/polarisation study (slant range)")
          : fmt::format("{}: frequency/polarisation study (slant range)", scene_name),
      sheet, sheet_style);
  write_text_file_atomic(dir.path("categories.csv"), cats);
  write_text_file_atomic(dir.path("contrast.csv"), pairs);

  nlohmann::json meta;
  meta["software"] = {{"name", "ris"}, {"version", RIS_VERSION}};
  meta["inputs"] = {{"scene", info.scene_path},
                    {"radar", info.radar_path},
                    {"backscatter", info.backscatter_path},
                    {"seed", info.seed}};
  nlohmann::json band_list = nlohmann::json::array();
  for (const StudyPanel& p : r.panels) band_list.push_back(p.band.label());
  meta["bands"] = band_list;
  meta["attribution"] =
      "slant-range pixels whose contributing visible elements (range span x azimuth footprint) "
      "are all one category; shadow, layover and no-data pixels excluded";
  meta["contrast"] =
      "C_ab = |mean_a - mean_b| / max(sqrt((var_a + var_b) / 2), 1/sqrt(12)) over greytones; "
      "delta_db = |10 log10(mean power a / mean power b)| before speckle";
  if (r.best_panel >= 0) {
    const StudyPanel& b = r.panels[static_cast<std::size_t>(r.best_panel)];
    meta["best_panel"] = {{"panel", r.best_panel + 1},
                          {"band", b.band.label()},
                          {"min_contrast", json_number(b.min_contrast)},
                          {"mean_contrast", json_number(b.mean_contrast)}};
  }
  if (r.best_pair_panel >= 0) {
    const StudyPanel& b = r.panels[static_cast<std::size_t>(r.best_pair_panel)];
    meta["best_pair"] = {{"panel", r.best_pair_panel + 1},
                         {"band", b.band.label()},
                         {"category_a", r.best_pair.a},
                         {"name_a", category_label(r, r.best_pair.a)},
                         {"category_b", r.best_pair.b},
                         {"name_b", category_label(r, r.best_pair.b)},
                         {"contrast", json_number(r.best_pair.contrast)},
                         {"delta_db", json_number(r.best_pair.delta_db)}};
  }
  meta["panels"] = panels;
  write_text_file_atomic(dir.path("metadata.json"), meta.dump(2) + "\n");
  dir.commit();
}

}  // namespace ris
