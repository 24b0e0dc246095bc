// `ris compare SIMULATED REAL`: how well a simulated image matches a real one
// of the same scene (docs/quality.md, "ris compare"; the seed's
// recommendation 3.2.10, validation against real imagery). Co-registration
// (multilooked, normalised cross-correlation of the dB images over an image
// pyramid, then a sub-pixel step: ris/image/image_registration.h),
// correlation of dB values at 1, 3, 5 and 9 pixel windows, bias and RMS
// difference, per-category bias, histogram distance, agreement of the
// simulation's shadow and layover masks with the real image's dark and bright
// parts, and the same correlations for two baselines that know only the
// geometry (cos of the local incidence, and Muhleman's law), so that what the
// backscatter modelling adds shows.
//
//   ris compare SIM REAL [--sim-band N] [--real-band N] [--sim-scale S]
//               [--real-scale S] [--max-shift N] [--no-register]
//               [--mask MASK] [--categories RASTER] [--categories-band N]
//               [--local-incidence RASTER] [--out DIR] [--json]
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_registry.h"
#include "ris/image/compare_report.h"
#include "ris/image/contact_sheet.h"
#include "ris/image/line_chart.h"
#include "ris/io/atomic_file.h"
#include "ris/io/intensity_image.h"
#include "ris/io/raster_io.h"
#include "ris/util/error.h"

namespace ris::app {
namespace {

struct CompareArgs {
  std::string sim, real;
  int sim_band = 1, real_band = 1;
  std::string sim_scale = "auto", real_scale = "auto";
  int max_shift = 16;
  bool no_register = false;
  std::string mask, categories, local_incidence, out;
  int categories_band = 1;
  bool json = false;
};

// Greytones of dB values over [lo, hi] (0 for no data).
std::vector<std::uint8_t> grey(const std::vector<float>& db, double lo, double hi) {
  std::vector<std::uint8_t> g(db.size(), 0);
  for (std::size_t i = 0; i < db.size(); ++i)
    if (std::isfinite(db[i]))
      g[i] =
          static_cast<std::uint8_t>(std::clamp(1.0 + 254.0 * (db[i] - lo) / (hi - lo), 1.0, 255.0));
  return g;
}

std::pair<double, double> percentiles(const std::vector<float>& db) {
  std::vector<float> v;
  for (float x : db)
    if (std::isfinite(x)) v.push_back(x);
  if (v.empty()) return {0.0, 1.0};
  std::sort(v.begin(), v.end());
  const double lo = v[v.size() / 100], hi = v[v.size() - 1 - v.size() / 100];
  return {lo, hi > lo ? hi : lo + 1.0};
}

// The comparison sheet (real, simulated, difference, scatter density) and
// the two dB histograms, into the staged output folder.
void write_pictures(const StagedDirectory& dir, const std::vector<float>& sim_db,
                    const std::vector<float>& real_db, int cols, int rows) {
  const auto [slo, shi] = percentiles(sim_db);
  const auto [rlo, rhi] = percentiles(real_db);
  const std::vector<std::uint8_t> gs = grey(sim_db, slo, shi), gr = grey(real_db, rlo, rhi);
  // Difference of the standardised dB images, +-3 (each image's p1-p99 as 0-1).
  std::vector<std::uint8_t> gd(sim_db.size(), 0);
  for (std::size_t i = 0; i < gd.size(); ++i) {
    if (!std::isfinite(sim_db[i]) || !std::isfinite(real_db[i])) continue;
    const double d = (real_db[i] - rlo) / (rhi - rlo) - (sim_db[i] - slo) / (shi - slo);
    gd[i] = static_cast<std::uint8_t>(std::clamp(128.0 + 127.0 * d, 1.0, 255.0));
  }
  // Scatter density: 256 x 256 bins of (simulated, real) dB, log counts, dark = many.
  const int n = 256;
  std::vector<double> counts(static_cast<std::size_t>(n * n), 0.0);
  for (std::size_t i = 0; i < sim_db.size(); ++i) {
    if (!std::isfinite(sim_db[i]) || !std::isfinite(real_db[i])) continue;
    const int x = std::clamp(static_cast<int>((sim_db[i] - slo) / (shi - slo) * (n - 1)), 0, n - 1);
    const int y =
        std::clamp(static_cast<int>((rhi - real_db[i]) / (rhi - rlo) * (n - 1)), 0, n - 1);
    counts[static_cast<std::size_t>(y * n + x)] += 1.0;
  }
  const double top = std::log1p(*std::max_element(counts.begin(), counts.end()));
  std::vector<std::uint8_t> gsc(counts.size());
  for (std::size_t i = 0; i < counts.size(); ++i)
    gsc[i] = static_cast<std::uint8_t>(255.0 - 254.0 * std::log1p(counts[i]) / std::max(top, 1e-9));
  write_contact_sheet_png(dir.path("sheet.png"), "simulated against real",
                          {{gr.data(), cols, rows, "real (dB, p1-p99)"},
                           {gs.data(), cols, rows, "simulated (dB, p1-p99)"},
                           {gd.data(), cols, rows, "real - simulated (standardised)"},
                           {gsc.data(), n, n, "scatter: simulated (x) vs real (y)"}},
                          ContactSheetStyle{});
  const auto hist = [](const std::vector<float>& db, double lo, double hi, Rgb8 colour,
                       const std::string& label) {
    ChartSeries s{label, {}, {}, colour};
    const int bins = 60;
    std::vector<double> c(bins, 0.0);
    double total = 0.0;
    for (float v : db) {
      if (!std::isfinite(v)) continue;
      const int k = static_cast<int>((v - lo) / (hi - lo) * bins);
      if (k >= 0 && k < bins) c[static_cast<std::size_t>(k)] += 1.0, total += 1.0;
    }
    for (int k = 0; k < bins; ++k) {
      s.x.push_back(lo + (k + 0.5) * (hi - lo) / bins);
      s.y.push_back(total > 0 ? c[static_cast<std::size_t>(k)] / total : 0.0);
    }
    return s;
  };
  ChartSpec spec;
  spec.title = "dB histograms (each image's own scale: p1-p99 mapped to 0-1)";
  spec.x_label = "standardised dB (0: p1, 1: p99)";
  spec.y_label = "fraction of pixels";
  std::vector<float> ss(sim_db.size()), rs(real_db.size());
  for (std::size_t i = 0; i < ss.size(); ++i) {
    ss[i] = static_cast<float>((sim_db[i] - slo) / (shi - slo));
    rs[i] = static_cast<float>((real_db[i] - rlo) / (rhi - rlo));
  }
  write_line_chart_png(
      dir.path("histograms.png"), spec,
      {hist(rs, -0.2, 1.2, {30, 30, 30}, "real"), hist(ss, -0.2, 1.2, {214, 40, 40}, "simulated")});
}

RasterF64 same_grid(const std::string& path, int cols, int rows, const std::string& option) {
  RasterF64 r = read_raster_f64(path);
  if (r.cols != cols || r.rows != rows) {
    throw InputError(
        path, option,
        fmt::format("{} x {} pixels, the simulated image has {} x {}", r.cols, r.rows, cols, rows));
  }
  return r;
}

void run_compare(const CompareArgs& a) {
  const IntensityImage sim =
      read_intensity_image(a.sim, a.sim_band, parse_pixel_scale(a.sim_scale, "--sim-scale"));
  IntensityImage real =
      read_intensity_image(a.real, a.real_band, parse_pixel_scale(a.real_scale, "--real-scale"));
  if (real.cols != sim.cols || real.rows != sim.rows) {
    real = read_intensity_image_on_grid(a.real, a.real_band,
                                        parse_pixel_scale(a.real_scale, "--real-scale"), sim);
  }
  const int cols = sim.cols, rows = sim.rows;
  nlohmann::json out;
  out["simulated"] = {{"path", a.sim}, {"read_as", sim.read_as}, {"cols", cols}, {"rows", rows}};
  out["real"] = {{"path", a.real}, {"source", real.source}, {"read_as", real.read_as}};

  RasterF64 categories, mask, local_incidence;
  CompareRequest request;
  request.register_images = !a.no_register;
  request.max_shift_px = a.max_shift;
  if (!a.categories.empty()) {
    categories = same_grid(a.categories, cols, rows, "--categories");
    if (a.categories_band < 1 || a.categories_band > categories.bands) {
      throw InputError(
          a.categories, "--categories-band",
          fmt::format("band {} asked for, the raster has {}", a.categories_band, categories.bands));
    }
    const std::size_t plane = static_cast<std::size_t>(cols) * rows;
    request.categories =
        std::span<const double>(categories.data.data() + plane * (a.categories_band - 1), plane);
  }
  if (!a.mask.empty()) {
    mask = same_grid(a.mask, cols, rows, "--mask");
    request.mask = mask.data;
  }
  if (!a.local_incidence.empty()) {
    local_incidence = same_grid(a.local_incidence, cols, rows, "--local-incidence");
    request.local_incidence_deg = local_incidence.data;
  }
  const CompareReport rep = compare_measures(sim.intensity, real.intensity, cols, rows, request);
  out.update(rep.measures);
  const std::vector<float>& real_aligned = rep.real_aligned;

  if (!a.out.empty()) {
    StagedDirectory dir(a.out);
    write_pictures(dir, intensity_to_db(sim.intensity), intensity_to_db(real_aligned), cols, rows);
    write_text_file_atomic(dir.path("compare.json"), out.dump(1) + "\n");
    dir.commit();
  }
  if (a.json) {
    fmt::print("{}\n", out.dump(1));
    return;
  }
  fmt::print("simulated {} ({} x {}) against real {}\n", a.sim, cols, rows, real.source);
  if (out.contains("registration")) {
    const auto& r = out["registration"];
    fmt::print(
        "registration: real shifted by {:+.3f} px (columns), {:+.3f} px (rows) against the "
        "simulation; peak r = {:.3f} at {:.1f} standard errors of independent images ({:.1f} "
        "needed), {:.1f} above its sidelobes\n",
        r["shift_x_px"].get<double>(), r["shift_y_px"].get<double>(),
        r["peak_correlation"].get<double>(), r["peak_z"].get<double>(), r["min_z"].get<double>(),
        r["peak_to_sidelobe"].get<double>());
  }
  const auto table = [](const std::string& name, const nlohmann::json& rowsj) {
    for (const auto& w : rowsj) {
      fmt::print("  {:<22} {:>2} x {:<2} {:>8} {:>8.3f} {:>8.3f} {:>9.2f} {:>8.2f}\n", name,
                 w["window"].get<int>(), w["window"].get<int>(), w["blocks"].get<std::int64_t>(),
                 w["pearson"].get<double>(), w["spearman"].get<double>(),
                 w["bias_db"].get<double>(), w["rms_db"].get<double>());
    }
  };
  fmt::print("  {:<22} {:>7} {:>8} {:>8} {:>8} {:>9} {:>8}\n", "image", "window", "blocks",
             "Pearson", "Spearman", "bias dB", "RMS dB");
  table("ris simulation", out["agreement"]);
  if (out.contains("baselines")) {
    table("baseline cos(theta_l)", out["baselines"]["cos_local_incidence"]);
    table("baseline Muhleman", out["baselines"]["muhleman"]);
  }
  fmt::print("histogram distance (Hellinger, 1 dB bins): {:.3f}\n",
             out["histogram_hellinger"].get<double>());
  if (out.contains("masks")) {
    fmt::print("masks: shadow vs dark IoU {:.3f}, layover vs bright IoU {:.3f}\n",
               out["masks"]["shadow_vs_dark_iou"].get<double>(),
               out["masks"]["layover_vs_bright_iou"].get<double>());
  }
  if (!a.out.empty()) fmt::print("sheet, histograms and compare.json in {}\n", a.out);
}

void add_compare(CLI::App& app) {
  auto a = std::make_shared<CompareArgs>();
  auto* cmd = app.add_subcommand("compare", "Compare a simulated image with a real one");
  cmd->add_option("simulated", a->sim, "Simulated image (e.g. mean_power_slant.tif)")->required();
  cmd->add_option("real", a->real, "Real image: a raster or a NISAR/UAVSAR RSLC .h5 product")
      ->required();
  cmd->add_option("--sim-band", a->sim_band, "Band of the simulated image")->capture_default_str();
  cmd->add_option("--real-band", a->real_band, "Band (or SLC layer) of the real image")
      ->capture_default_str();
  cmd->add_option("--sim-scale", a->sim_scale, "auto, power, amplitude or db")
      ->capture_default_str();
  cmd->add_option("--real-scale", a->real_scale, "auto, power, amplitude or db")
      ->capture_default_str();
  cmd->add_option("--max-shift", a->max_shift, "Largest shift searched, pixels")
      ->capture_default_str();
  cmd->add_flag("--no-register", a->no_register, "Take the images as aligned");
  cmd->add_option("--mask", a->mask, "The simulation's mask (mask_slant.tif): shadow/layover IoU");
  cmd->add_option("--categories", a->categories, "Category raster on the simulated image's grid");
  cmd->add_option("--categories-band", a->categories_band, "Band of --categories")
      ->capture_default_str();
  cmd->add_option("--local-incidence", a->local_incidence,
                  "Local incidence (degrees) on the simulated image's grid: the geometry-only "
                  "baselines");
  cmd->add_option("--out", a->out, "Folder for sheet.png, histograms.png and compare.json");
  cmd->add_flag("--json", a->json, "Print the results as JSON");
  cmd->callback([a] {
    if (a->max_shift < 1) {
      throw InputError("", "--max-shift", fmt::format("expected 1 or more, got {}", a->max_shift));
    }
    run_compare(*a);
  });
}

const Registration reg{"compare", add_compare};

}  // namespace
}  // namespace ris::app
