// The study's output folder (write_study_products, ris/analysis/study.h): panels,
// contact sheet, per-category greytones, separability per pair and per
// incidence bin, and metadata with the method and the verdict.
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "ris/analysis/study.h"
#include "ris/image/contact_sheet.h"
#include "ris/io/atomic_file.h"
#include "ris/io/raster_io.h"
#include "ris/util/units.h"

namespace ris {

namespace {

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

// JSON has no NaN or infinity: missing values are null.
nlohmann::json json_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

std::string category_label(const StudyResult& r, std::uint16_t c) {
  for (std::size_t i = 0; i < r.categories.size(); ++i) {
    if (r.categories[i] == c) return r.category_names[i];
  }
  return std::to_string(c);
}

std::string panel_file(std::size_t i, const StudyBand& b) {
  return fmt::format("panel_{}_{}.png", i + 1, b.slug());
}

// z may be infinite (no sampling error): written as inf / -inf.
std::string csv_z(double z) {
  if (std::isinf(z)) return z > 0 ? "inf" : "-inf";
  return csv_number(z, 3);
}

struct SeparabilityTables {
  std::string pairs =
      "run,panel,band,category_a,name_a,category_b,name_b,bins,delta_db,z,jm,jm_noise,"
      "separated\n";
  std::string bins =
      "run,panel,band,incidence_lo_deg,incidence_hi_deg,category_a,category_b,pixels_a,"
      "pixels_b,looks,sigma0_a_db,sigma0_b_db,z,jm,jm_noise\n";

  void add(const StudyResult& r, const char* run, std::size_t panel, const BandSeparability& s) {
    const std::string band = csv_text(r.panels[panel].band.label());
    for (const PairSeparability& p : s.pairs) {
      pairs += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{}\n", run, panel + 1, band, p.a,
                           csv_text(category_label(r, p.a)), p.b, csv_text(category_label(r, p.b)),
                           p.bins, csv_number(p.delta_db, 3), csv_z(p.z), csv_number(p.jm, 5),
                           csv_number(p.jm_noise, 5), p.separated ? 1 : 0);
    }
    for (const PairBin& b : s.bins) {
      const double lo = r.incidence.first_lo_rad + b.bin * r.incidence.width_rad;
      bins += fmt::format("{},{},{},{:.3f},{:.3f},{},{},{},{},{:.2f},{:.3f},{:.3f},{},{},{}\n", run,
                          panel + 1, band, rad_to_deg(lo), rad_to_deg(lo + r.incidence.width_rad),
                          b.a, b.b, b.pixels_a, b.pixels_b, b.looks, 10.0 * std::log10(b.mean_a),
                          10.0 * std::log10(b.mean_b), csv_z(b.z), csv_number(b.jm, 5),
                          csv_number(b.jm_noise, 5));
    }
  }
};

nlohmann::json separability_json(const BandSeparability& s) {
  return {{"score", json_number(s.score)},
          {"compared_pairs", s.compared_pairs},
          {"separated_pairs", s.separated_pairs},
          {"min_jm", json_number(s.min_jm)},
          {"max_abs_z", json_number(s.max_abs_z)}};
}

nlohmann::json method_json(const StudyResult& r) {
  return {{"calibration",
           "calibrated sigma0 = speckled power / the pixel's radar-equation factor (the mean power "
           "of the same run with sigma0 = 1 for every category)"},
          {"matched_geometry",
           "pixels attributed to one category, range-bin centre inside the window, all "
           "contributing elements' local incidence inside one incidence bin"},
          {"separability",
           "per incidence bin, Jeffries-Matusita JM = 2 (1 - exp(-B)) of the gamma laws of L-look "
           "speckle, B = L ln((m_a + m_b) / (2 sqrt(m_a m_b))); pixel-weighted mean over bins"},
          {"sampling_error",
           "z = ln(m_a / m_b) / its standard error, combined over bins with inverse-variance "
           "weights; separated when |z| > z_critical (Bonferroni over bands x pairs)"},
          {"score", "mean over compared pairs of JM, counting separated pairs only"},
          {"null_check", "every category given Muhleman's law; no pair may be separated"},
          {"z_critical", r.z_critical},
          {"window",
           {{"range_fraction", {r.window.range_lo_fraction, r.window.range_hi_fraction}},
            {"slant_range_m", {r.incidence.range_lo_m, r.incidence.range_hi_m}},
            {"incidence_bin_deg", rad_to_deg(r.window.incidence_bin_rad)},
            {"incidence_bins", r.incidence.count}}}};
}

// metadata.json but its panels.
nlohmann::json study_metadata(const StudyResult& r, const StudyRunInfo& info) {
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
  meta["method"] = method_json(r);
  meta["verdict"] = study_verdict(r);
  meta["best_panel"] = nullptr;
  if (r.best_panel >= 0) {
    const StudyPanel& b = r.panels[static_cast<std::size_t>(r.best_panel)];
    meta["best_panel"] = {{"panel", r.best_panel + 1},
                          {"band", b.band.label()},
                          {"score", json_number(b.separability.score)}};
  }
  meta["null_check"] = nullptr;
  if (r.null_check_run) {
    meta["null_check"] = {{"passed", r.null_check_passed},
                          {"max_abs_z", json_number(r.null_max_abs_z)},
                          {"z_critical", r.z_critical}};
  }
  return meta;
}

}  // namespace

std::string study_verdict(const StudyResult& r) {
  if (r.best_panel < 0) return "no band separates these categories";
  return fmt::format("best band: {}",
                     r.panels[static_cast<std::size_t>(r.best_panel)].band.label());
}

StudyTables study_tables(const StudyResult& r, const StudyRunInfo& info) {
  StudyTables out;
  out.categories_csv =
      "panel,band,frequency_ghz,polarisation,category,name,pixels,mean_grey,std_grey,"
      "mean_power_dbw\n";
  SeparabilityTables tables;
  nlohmann::json panels = nlohmann::json::array();
  for (std::size_t i = 0; i < r.panels.size(); ++i) {
    const StudyPanel& p = r.panels[i];
    for (const CategoryStats& c : p.stats) {
      out.categories_csv +=
          fmt::format("{},{},{:g},{},{},{},{},{},{},{}\n", i + 1, csv_text(p.band.label()),
                      p.band.frequency_hz / 1e9, to_string(p.band.polarisation), c.category,
                      csv_text(c.name), c.pixels, csv_number(c.mean_grey, 3),
                      csv_number(c.std_grey, 3), csv_number(10.0 * std::log10(c.mean_power_w), 3));
    }
    tables.add(r, "library", i, p.separability);
    if (r.null_check_run) tables.add(r, "null", i, p.null_separability);
    nlohmann::json panel = {{"panel", i + 1},
                            {"band", p.band.label()},
                            {"frequency_hz", p.band.frequency_hz},
                            {"polarisation", to_string(p.band.polarisation)},
                            {"file", panel_file(i, p.band)},
                            {"separability", separability_json(p.separability)},
                            {"simulation", p.simulation}};
    if (r.null_check_run) panel["null_separability"] = separability_json(p.null_separability);
    panels.push_back(panel);
  }
  out.separability_csv = std::move(tables.pairs);
  out.separability_bins_csv = std::move(tables.bins);
  out.metadata = study_metadata(r, info);
  out.metadata["panels"] = panels;
  return out;
}

void write_study_products(const std::filesystem::path& out_dir, const StudyResult& r,
                          const StudyRunInfo& info, const ContactSheetStyle& sheet_style) {
  const StudyTables tables = study_tables(r, info);
  StagedDirectory dir(out_dir);
  std::vector<ContactPanel> sheet;
  for (std::size_t i = 0; i < r.panels.size(); ++i) {
    const StudyPanel& p = r.panels[i];
    write_png_gray(dir.path(panel_file(i, p.band)), p.slant_grey.data(), p.bins, p.lines);
    sheet.push_back({p.slant_grey.data(), p.bins, p.lines, p.band.label()});
  }
  const std::string scene_name = std::filesystem::path(info.scene_path).stem().string();
  write_contact_sheet_png(
      dir.path("contact_sheet.png"),
      scene_name.empty()
          ? std::string("Frequency/polarisation study (slant range)")
          : fmt::format("{}: frequency/polarisation study (slant range)", scene_name),
      sheet, sheet_style);
  write_text_file_atomic(dir.path("categories.csv"), tables.categories_csv);
  write_text_file_atomic(dir.path("separability.csv"), tables.separability_csv);
  write_text_file_atomic(dir.path("separability_bins.csv"), tables.separability_bins_csv);
  write_text_file_atomic(dir.path("metadata.json"), tables.metadata.dump(2) + "\n");
  dir.commit();
}

}  // namespace ris
