// `ris calibrate REAL --acquisition P --dem D --land-cover L --out LIB.csv`
// (issue 34 item 4, docs/calibrate.md): fits each category's sigma0(theta)
// from a calibrated image on the acquisition's radar grid against local
// incidence (ris/analysis/calibration_samples.h for the geometry and the
// area normalisation, ris/analysis/backscatter_fit.h for the fit) at the
// acquisition's band and polarisation, and writes a sigma0 table that
// `ris simulate --backscatter` reads, with a JSON summary of each
// category's fit and spread. Both files or neither.
//
//   ris calibrate REAL -a P --dem D [--land-cover L] [--category C] --out LIB.csv
//                 [--quantity beta0|sigma0] [--scale auto|power|amplitude|db] [--band B]
//                 [--polarisation POL] [--bin-deg W] [--min-bin-pixels N] [--min-pixels N]
//                 [--edge PX] [--fit table|quadratic] [--library NAMES] [--no-clamp]
//                 [--append] [--summary LIB.json] [--threads N] [--quiet]
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "acquisition_options.h"
#include "command_registry.h"
#include "ris/analysis/backscatter_fit.h"
#include "ris/analysis/calibration_samples.h"
#include "ris/backscatter/library.h"
#include "ris/io/atomic_file.h"
#include "ris/io/intensity_image.h"
#include "ris/io/safe_paths.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/polarisation.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris::app {
namespace {

constexpr double kLightSpeed_m_s = 299792458.0;

struct CalibrateArgs {
  std::string image, dem, land_cover, out, summary, library, quantity = "beta0", scale = "auto";
  std::string polarisation, fit = "table";
  AcquisitionArgs acq;
  int band = 1, category = 1, edge_px = 1, threads = 0;
  double bin_deg = 1.0;
  std::int64_t min_bin_pixels = 50, min_pixels = 500;
  bool no_clamp = false, append = false, quiet = false;
};

std::string lower_extension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

// Everything that needs no input file.
BackscatterFitOptions check_options(CalibrateArgs& a) {
  if (a.quantity != "beta0" && a.quantity != "sigma0")
    throw InputError("", "--quantity", "expected beta0 or sigma0, got \"" + a.quantity + "\"");
  if (a.fit != "table" && a.fit != "quadratic")
    throw InputError("", "--fit", "expected table or quadratic, got \"" + a.fit + "\"");
  if (!(a.bin_deg > 0.0 && a.bin_deg <= 30.0))
    throw InputError("", "--bin-deg", fmt::format("expected 0..30 degrees, got {}", a.bin_deg));
  if (a.min_bin_pixels < 2) throw InputError("", "--min-bin-pixels", "expected 2 or more pixels");
  if (a.min_pixels < 1) throw InputError("", "--min-pixels", "expected 1 or more pixels");
  if (a.edge_px < 0 || a.edge_px > 20) throw InputError("", "--edge", "expected 0..20 pixels");
  if (a.category < 1 || a.category > 65534)
    throw InputError("", "--category", "expected a category id 1..65534");
  if (lower_extension(a.out) != ".csv")
    throw InputError(a.out, "--out", "expected a sigma0 table (.csv)");
  if (a.append && a.summary.empty())
    throw InputError("", "--summary",
                     "with --append, name this run's summary (the default, --out with .json, "
                     "holds the first run's)");
  if (a.append && !std::filesystem::is_regular_file(a.out))
    throw InputError(a.out, "--append", "no table to append to: run once without --append");
  if (a.summary.empty()) a.summary = std::filesystem::path(a.out).replace_extension(".json");
  if (lower_extension(a.summary) != ".json")
    throw InputError(a.summary, "--summary", "expected a .json file");
  require_safe_output_file(a.out, "--out");
  require_safe_output_file(a.summary, "--summary");
  checked_thread_count(a.threads, "--threads");
  BackscatterFitOptions o;
  o.bin_deg = a.bin_deg;
  o.min_bin_pixels = a.min_bin_pixels;
  o.min_category_pixels = a.min_pixels;
  o.form = a.fit == "table" ? FitForm::table : FitForm::quadratic;
  return o;
}

RadarBand band_of(const CalibrateArgs& a, const Acquisition& acq) {
  RadarBand band;
  band.frequency_hz = kLightSpeed_m_s / acq.grid.wavelength_m;
  const std::string pol = a.polarisation.empty() ? acq.polarisation : a.polarisation;
  try {
    band.polarisation = parse_polarisation(pol);
  } catch (const std::invalid_argument&) {
    throw InputError(a.polarisation.empty() ? acq.source : "", "--polarisation",
                     fmt::format("the image's polarisation \"{}\" is not HH, HV, VH or VV: give "
                                 "--polarisation",
                                 pol));
  }
  return band;
}

CalibrationImage read_image(const CalibrateArgs& a) {
  const IntensityImage img =
      read_intensity_image(a.image, a.band, parse_pixel_scale(a.scale, "--scale"));
  CalibrationImage c;
  c.source = a.image;
  c.cols = img.cols;
  c.rows = img.rows;
  c.values = img.intensity;
  c.quantity = a.quantity == "beta0" ? CalibratedQuantity::beta0 : CalibratedQuantity::sigma0;
  std::size_t finite = 0, not_positive = 0;
  for (const float v : c.values) {
    finite += std::isfinite(v);
    not_positive += std::isfinite(v) && v <= 0.0f;
  }
  if (finite == 0) throw InputError(a.image, "", "no pixel has data");
  if (img.read_as == "power" && 2 * not_positive > finite)
    throw InputError(a.image, "--scale",
                     fmt::format("{} of its {} values are at or below 0: for an image in dB give "
                                 "--scale db",
                                 not_positive, finite));
  return c;
}

nlohmann::json summary_json(const CalibrateArgs& a, const Acquisition& acq, const RadarBand& band,
                            const CalibrationSamples& s, const std::vector<CategoryFit>& fits,
                            const std::function<std::string(std::int32_t)>& name_of) {
  nlohmann::json j = {
      {"image", a.image},
      {"quantity", a.quantity},
      {"acquisition", acq.source},
      {"dem", a.dem},
      {"land_cover", a.land_cover.empty() ? nlohmann::json(nullptr) : nlohmann::json(a.land_cover)},
      {"frequency_ghz", band.frequency_hz / 1e9},
      {"polarisation", std::string(to_string(band.polarisation))},
      {"window",
       {{"line0", s.window.line0},
        {"lines", s.window.lines},
        {"bin0", s.window.bin0},
        {"bins", s.window.bins}}},
      {"excluded_pixels",
       {{"no_ground", s.no_ground},
        {"layover_shadow", s.layover_shadow},
        {"no_image_data", s.no_image_data},
        {"boundary", s.boundary}}},
      {"method",
       {{"incidence", "local incidence to the DEM facet normal (ris topo's radar pass)"},
        {"area", a.quantity == "beta0" ? "sigma0 = beta0 sin(theta_local)"
                                       : "sigma0 = sigma0_ellipsoid sin(theta_local) / "
                                         "sin(theta_ellipsoid)"},
        {"bin_deg", a.bin_deg},
        {"estimate", "mean of linear sigma0 per bin, at the bin's mean incidence"},
        {"fit", a.fit},
        {"min_bin_pixels", a.min_bin_pixels},
        {"min_pixels", a.min_pixels},
        {"edge_px", a.edge_px}}},
      {"output", a.out},
      {"categories", nlohmann::json::array()}};
  for (const CategoryFit& f : fits) {
    nlohmann::json c = {{"category", f.category},
                        {"name", name_of(f.category)},
                        {"pixels", f.pixels},
                        {"used_pixels", f.used_pixels},
                        {"fitted", f.fitted}};
    if (!f.fitted) {
      c["reason"] = f.reason;
    } else {
      c["quadratic_db"] = {f.quad[0], f.quad[1], f.quad[2]};
      c["rms_residual_db"] = f.rms_residual_db;
      c["max_residual_db"] = f.max_residual_db;
      c["median_standard_error_db"] = f.median_se_db;
      nlohmann::json bins = nlohmann::json::array();
      for (const auto& b : f.bins)
        bins.push_back({{"angle_deg", b.angle_deg},
                        {"pixels", b.pixels},
                        {"sigma0_db", 10.0 * std::log10(b.mean_linear)},
                        {"cv", b.cv},
                        {"standard_error_db", b.se_db},
                        {"residual_db", b.residual_db},
                        {"table_db", b.table_db}});
      c["bins"] = bins;
    }
    j["categories"].push_back(c);
  }
  return j;
}

void print_fits(const std::vector<CategoryFit>& fits,
                const std::function<std::string(std::int32_t)>& name_of) {
  fmt::print("{:>8} {:<18} {:>9} {:>5} {:>15} {:>16} {:>8} {:>8} {:>6}\n", "category", "name",
             "pixels", "bins", "incidence deg", "sigma0 dB", "rms dB", "se dB", "cv");
  for (const CategoryFit& f : fits) {
    if (!f.fitted) continue;
    const auto& lo = f.bins.front();
    const auto& hi = f.bins.back();
    double cv = 0.0;
    for (const auto& b : f.bins) cv += b.cv * static_cast<double>(b.pixels);
    fmt::print(
        "{:>8} {:<18} {:>9} {:>5} {:>7.2f}..{:<6.2f} {:>7.2f}..{:<7.2f} {:>8.3f} {:>8.3f} "
        "{:>6.3f}\n",
        f.category, name_of(f.category), f.used_pixels, f.bins.size(), lo.angle_deg, hi.angle_deg,
        lo.table_db, hi.table_db, f.rms_residual_db, f.median_se_db,
        cv / static_cast<double>(f.used_pixels));
  }
}

// A new table, or (--append) the existing one with this run's curves
// after it: another band or polarisation of the same categories.
std::string table_text(const CalibrateArgs& a, const std::vector<CategoryFit>& fits,
                       const RadarBand& band,
                       const std::function<std::string(std::int32_t)>& name_of,
                       const std::string& provenance) {
  if (!a.append) return backscatter_table_csv(fits, band, name_of, provenance, !a.no_clamp);
  std::ifstream in(a.out, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (!in) throw InputError(a.out, "--append", "cannot read the table");
  std::string text = buffer.str();
  if (!text.empty() && text.back() != '\n') text += '\n';
  return text + "# appended: " + provenance + "\n" + backscatter_table_rows(fits, band, name_of);
}

void run_calibrate(CalibrateArgs a) {
  const BackscatterFitOptions fit_options = check_options(a);
  const Acquisition acq = read_acquisition(a.acq.path, a.acq.options());
  const RadarBand band = band_of(a, acq);
  const EllipsoidalDem dem = read_ellipsoidal_dem(a.dem);
  std::optional<LoadedScene> cover;
  if (!a.land_cover.empty()) cover = load_scene_source(a.land_cover);
  std::unique_ptr<Sigma0Source> names;
  if (!a.library.empty()) names = load_sigma0_source(a.library);
  const CalibrationImage image = read_image(a);

  CalibrationSampleOptions so;
  so.land_cover = cover ? &cover->scene : nullptr;
  so.land_cover_source = a.land_cover;
  so.fallback = static_cast<std::uint16_t>(a.category);
  so.edge_px = a.edge_px;
  so.threads = a.threads;
  const CalibrationSamples s = acquisition_calibration_samples(acq, dem, image, so);
  const std::vector<CategoryFit> fits =
      fit_backscatter(s.sigma0, s.local_incidence_deg, s.category, fit_options);

  const auto name_of = [&](std::int32_t id) -> std::string {
    const auto c = static_cast<std::uint16_t>(id);
    if (names && names->has_category(c)) return names->category_name(c);
    if (cover) {
      const auto it = cover->category_names.find(c);
      if (it != cover->category_names.end()) return it->second;
    }
    return "";
  };
  const auto fitted =
      std::count_if(fits.begin(), fits.end(), [](const auto& f) { return f.fitted; });
  for (const CategoryFit& f : fits)
    if (!f.fitted)
      fmt::print(stderr, "warning: category {}{}: not fitted ({}); the library lacks it\n",
                 f.category, name_of(f.category).empty() ? "" : " (" + name_of(f.category) + ")",
                 f.reason);
  if (fitted == 0)
    throw InputError(a.image, "",
                     fmt::format("no category could be fitted ({} categories seen, {} pixels "
                                 "usable): see the warnings",
                                 fits.size(),
                                 std::count_if(s.category.begin(), s.category.end(),
                                               [](std::int32_t c) { return c >= 0; })));
  const std::string provenance =
      fmt::format("from {} ({}), acquisition {}, DEM {}{}", a.image, a.quantity, acq.source, a.dem,
                  a.land_cover.empty() ? "" : ", land cover " + a.land_cover);
  const std::string csv = table_text(a, fits, band, name_of, provenance);
  const nlohmann::json j = summary_json(a, acq, band, s, fits, name_of);
  // Both files or neither: each written under a temporary name, renamed
  // only when both are complete and the table reads back as a table.
  AtomicPath csv_out(a.out), json_out(a.summary);
  write_text_file_atomic(csv_out.temp_path(), csv);
  try {
    load_sigma0_source(csv_out.temp_path().string());
  } catch (const InputError& e) {
    std::string what = e.what();
    const std::string temp = csv_out.temp_path().string();
    for (std::size_t at = what.find(temp); at != std::string::npos; at = what.find(temp))
      what.replace(at, temp.size(), a.out);
    throw InputError(
        a.out, a.append ? "--append" : "",
        "the table with the new rows does not read back (" + what +
            (a.append ? "); is a curve of this band and polarisation in it already?" : ")"));
  }
  write_text_file_atomic(json_out.temp_path(), j.dump(1) + "\n");
  csv_out.commit();
  json_out.commit();
  if (a.quiet) return;
  fmt::print(
      "{}: {} of {} pixels of the window fitted at {:.6g} GHz {} (excluded: {} no ground, "
      "{} layover/shadow, {} no data, {} at category boundaries)\n",
      a.image,
      std::count_if(s.category.begin(), s.category.end(), [](std::int32_t c) { return c >= 0; }),
      s.window.size(), band.frequency_hz / 1e9, to_string(band.polarisation), s.no_ground,
      s.layover_shadow, s.no_image_data, s.boundary);
  print_fits(fits, name_of);
  fmt::print("wrote {} and {}\n", a.out, a.summary);
}

void add_calibrate(CLI::App& app) {
  auto a = std::make_shared<CalibrateArgs>();
  auto* cmd = app.add_subcommand(
      "calibrate",
      "Fit each category's sigma0(local incidence) from a calibrated image on an acquisition's "
      "grid; write a sigma0 table ris simulate --backscatter reads");
  cmd->add_option("image", a->image,
                  "Calibrated image (beta0 or sigma0, linear or dB) on the acquisition's grid: "
                  "the DEM's window of it (as ris simulate --acquisition writes) or the whole grid")
      ->required();
  add_acquisition_options(cmd, a->acq);
  cmd->add_option("--dem", a->dem, "DEM (geographic WGS 84; geoid heights converted)")->required();
  cmd->add_option("--land-cover", a->land_cover,
                  "Land cover: a ris scene in a projected CRS whose categories the terrain takes "
                  "(as ris simulate --acquisition --land-cover)");
  cmd->add_option("--category", a->category,
                  "Category of the terrain outside the land cover (or of all of it without one)")
      ->capture_default_str();
  cmd->add_option("--out,-o", a->out, "Sigma0 table to write (.csv)")->required();
  cmd->add_option("--summary", a->summary, "JSON summary (default: --out with .json)");
  cmd->add_option("--quantity", a->quantity,
                  "What the image holds: beta0 (a NISAR RSLC's |z|^2) or sigma0 (ellipsoid-"
                  "referenced)")
      ->capture_default_str();
  cmd->add_option("--scale", a->scale, "Pixel values: auto, power, amplitude or db")
      ->capture_default_str();
  cmd->add_option("--band", a->band, "Raster band or SLC layer, from 1")->capture_default_str();
  cmd->add_option("--polarisation", a->polarisation,
                  "Polarisation of the image (default: the acquisition's)");
  cmd->add_option("--bin-deg", a->bin_deg, "Local-incidence bin width (degrees)")
      ->capture_default_str();
  cmd->add_option("--min-bin-pixels", a->min_bin_pixels, "Pixels a bin needs to be kept")
      ->capture_default_str();
  cmd->add_option("--min-pixels", a->min_pixels, "Pixels a category needs to be fitted")
      ->capture_default_str();
  cmd->add_option("--edge", a->edge_px,
                  "Pixels within this distance of another category are left out (mixed)")
      ->capture_default_str();
  cmd->add_option("--fit", a->fit,
                  "table: the bins' means; quadratic: a quadratic in dB through them")
      ->capture_default_str();
  cmd->add_option("--library", a->library, "Category library whose names the table gives");
  cmd->add_flag("--no-clamp", a->no_clamp,
                "Refuse angles outside the fitted range (default: they take the end value)");
  cmd->add_flag("--append", a->append,
                "Add this run's curves (another band or polarisation) to the existing --out "
                "table");
  cmd->add_option("--threads", a->threads, "Threads (0: all)")->capture_default_str();
  cmd->add_flag("--quiet,-q", a->quiet, "Print nothing on success");
  cmd->callback([a] { run_calibrate(*a); });
}

const Registration reg{"calibrate", add_calibrate};

}  // namespace
}  // namespace ris::app
