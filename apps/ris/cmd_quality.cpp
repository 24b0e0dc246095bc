// `ris quality IMAGE`: objective measures of one image, simulated or real
// (docs/quality.md; the seed's recommendation 3.2.4): speckle (ENL, CV,
// radiometric resolution) over homogeneous regions, the dB histogram and
// dynamic range, per-category statistics and the separability of category
// pairs, edge sharpness across a mask's shadow edges, and point-target
// impulse responses (as `ris irf`).
//
//   ris quality IMAGE [--band N] [--scale auto|power|amplitude|db]
//                     [--regions C0,R0,COLS,ROWS ...] [--window N]
//                     [--mask MASK.tif] [--mask-bit B]
//                     [--categories RASTER] [--categories-band N]
//                     [--target LINE,BIN ...] [--json]
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "command_registry.h"
#include "ris/image/quality_report.h"
#include "ris/io/intensity_image.h"
#include "ris/io/raster_io.h"
#include "ris/util/error.h"

namespace ris::app {
namespace {

struct QualityArgs {
  std::string image;
  int band = 1;
  std::string scale = "auto";
  std::vector<std::string> regions;
  int window = 16;
  std::string mask;
  int mask_bit = 1;
  std::string categories;
  int categories_band = 1;
  std::vector<std::string> targets;
  bool json = false;
};

// "a,b,c,d" as integers, naming the option in errors.
std::vector<int> int_list(const std::string& text, std::size_t count, const std::string& option) {
  std::vector<int> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      out.push_back(std::stoi(item, &used));
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError("", option, fmt::format("expected integers, got '{}'", text));
    }
  }
  if (out.size() != count) {
    throw InputError("", option,
                     fmt::format("expected {} comma-separated integers, got '{}'", count, text));
  }
  return out;
}

// A raster of the image's size as doubles (band `band`).
RasterF64 same_size_raster(const std::string& path, const IntensityImage& img,
                           const std::string& option) {
  RasterF64 r = read_raster_f64(path);
  if (r.cols != img.cols || r.rows != img.rows) {
    throw InputError(
        path, option,
        fmt::format("{} x {} pixels, the image has {} x {}", r.cols, r.rows, img.cols, img.rows));
  }
  return r;
}

// The measures as a summary on stdout.
void print_quality(const nlohmann::json& out, const IntensityImage& img, int mask_bit) {
  fmt::print("image: {} ({} x {} pixels, read as {})\n", img.source, img.cols, img.rows,
             img.read_as);
  const nlohmann::json& s = out["speckle"];
  fmt::print(
      "speckle: ENL {:.3f}, CV {:.3f}, radiometric resolution {:.2f} dB over {} regions "
      "({} pixels; {})\n",
      s["enl"].get<double>(), s["cv"].get<double>(), s["radiometric_resolution_db"].get<double>(),
      s["regions"].get<int>(), s["pixels"].get<std::int64_t>(),
      s["regions_from"].get<std::string>());
  const nlohmann::json& h = out["histogram"];
  fmt::print("histogram: p1 {:.2f} dB, median {:.2f} dB, p99 {:.2f} dB; dynamic range {:.2f} dB\n",
             h["p1_db"].get<double>(), h["p50_db"].get<double>(), h["p99_db"].get<double>(),
             h["dynamic_range_db"].get<double>());
  if (out.contains("categories")) {
    fmt::print("categories: {:>8} {:>9} {:>9} {:>8} {:>12}\n", "category", "pixels", "mean dB",
               "std dB", "<I> dB");
    for (const auto& c : out["categories"]) {
      fmt::print("            {:>8} {:>9} {:>9.2f} {:>8.2f} {:>12.2f}\n",
                 c["category"].get<std::int64_t>(), c["pixels"].get<std::int64_t>(),
                 c["mean_db"].get<double>(), c["std_db"].get<double>(),
                 c["mean_intensity_db"].get<double>());
    }
    fmt::print("pairs:      {:>4} {:>4} {:>12} {:>13} {:>6}\n", "a", "b", "contrast dB",
               "Bhattacharyya", "JM");
    for (const auto& p : out["pairs"]) {
      fmt::print("            {:>4} {:>4} {:>12.2f} {:>13.3f} {:>6.3f}\n",
                 p["a"].get<std::int64_t>(), p["b"].get<std::int64_t>(),
                 p["contrast_db"].get<double>(), p["bhattacharyya"].get<double>(),
                 p["jeffries_matusita"].get<double>());
    }
  }
  if (out.contains("edges")) {
    fmt::print("edges: {} edges of mask bit {}, 10-90% width {:.2f} pixels\n",
               out["edges"]["edges"].get<int>(), mask_bit, out["edges"]["width_px"].get<double>());
  }
  if (out.contains("targets")) {
    for (const auto& t : out["targets"]) fmt::print("target: {}\n", t.dump());
  }
}

void run_quality(const QualityArgs& a) {
  if (a.window < 4) {
    throw InputError("", "--window", fmt::format("expected 4 or more pixels, got {}", a.window));
  }
  const IntensityImage img =
      read_intensity_image(a.image, a.band, parse_pixel_scale(a.scale, "--scale"));
  std::vector<std::uint8_t> mask;
  if (!a.mask.empty()) mask = quality_mask_bits(same_size_raster(a.mask, img, "--mask").data);
  QualityRequest request;
  request.window = a.window;
  request.mask_bit = a.mask_bit;
  for (const std::string& r : a.regions) {
    const std::vector<int> v = int_list(r, 4, "--regions");
    if (v[2] <= 0 || v[3] <= 0) {
      throw InputError("", "--regions", fmt::format("a box needs a size above 0, got '{}'", r));
    }
    request.regions.push_back({v[0], v[1], v[2], v[3]});
  }
  RasterF64 categories;
  if (!a.categories.empty()) {
    categories = same_size_raster(a.categories, img, "--categories");
    if (a.categories_band < 1 || a.categories_band > categories.bands) {
      throw InputError(
          a.categories, "--categories-band",
          fmt::format("band {} asked for, the raster has {}", a.categories_band, categories.bands));
    }
    const std::size_t plane =
        static_cast<std::size_t>(img.cols) * static_cast<std::size_t>(img.rows);
    request.categories =
        std::span<const double>(categories.data.data() + plane * (a.categories_band - 1), plane);
  }
  for (const std::string& t : a.targets) {
    const std::vector<int> v = int_list(t, 2, "--target");
    if (v[0] < 0 || v[0] >= img.rows || v[1] < 0 || v[1] >= img.cols) {
      throw InputError("", "--target",
                       fmt::format("line {} bin {} is outside the {} x {} image", v[0], v[1],
                                   img.rows, img.cols));
    }
    request.targets.emplace_back(v[0], v[1]);
  }
  if (!request.targets.empty()) {
    const auto size = [&](const char* item, double fallback) {
      const auto it = img.metadata.find(item);
      return it != img.metadata.end() ? std::stod(it->second) : fallback;
    };
    request.range_bin_m = size("RIS_RANGE_BIN_M", 1.0);
    request.line_spacing_m = size("RIS_LINE_SPACING_M", 1.0);
  }

  nlohmann::json out;
  out["image"] = {{"path", a.image},
                  {"source", img.source},
                  {"cols", img.cols},
                  {"rows", img.rows},
                  {"read_as", img.read_as}};
  out.update(quality_measures(IntensityView{img.intensity, img.cols, img.rows, mask}, request));
  if (a.json) {
    fmt::print("{}\n", out.dump(1));
    return;
  }
  print_quality(out, img, a.mask_bit);
}

void add_quality(CLI::App& app) {
  auto a = std::make_shared<QualityArgs>();
  auto* cmd = app.add_subcommand(
      "quality", "Objective image-quality measures of one image (simulated or real)");
  cmd->add_option("image", a->image,
                  "Image: a raster (GeoTIFF, PNG, ...) or a NISAR/UAVSAR RSLC .h5 product")
      ->required();
  cmd->add_option("--band", a->band, "Band (raster) or SLC layer (product), from 1")
      ->capture_default_str();
  cmd->add_option("--scale", a->scale,
                  "What the pixel values are: auto (float = power, integer = amplitude, complex "
                  "= |z|^2), power, amplitude or db")
      ->capture_default_str();
  cmd->add_option("--regions", a->regions,
                  "Homogeneous boxes COL0,ROW0,COLS,ROWS in pixels (repeatable); default: "
                  "found automatically (docs/quality.md)");
  cmd->add_option("--window", a->window, "Window of the automatic homogeneous regions, pixels")
      ->capture_default_str();
  cmd->add_option("--mask", a->mask,
                  "Mask raster of the image's size (e.g. mask_slant.tif): non-zero pixels are "
                  "left out of the speckle statistics; edges of --mask-bit are measured");
  cmd->add_option("--mask-bit", a->mask_bit, "Mask bit whose edges are measured (1: shadow)")
      ->capture_default_str();
  cmd->add_option("--categories", a->categories,
                  "Category raster of the image's size: per-category statistics and pair "
                  "separability");
  cmd->add_option("--categories-band", a->categories_band, "Band of --categories")
      ->capture_default_str();
  cmd->add_option("--target", a->targets,
                  "Point target at LINE,BIN: impulse response (repeatable)");
  cmd->add_flag("--json", a->json, "Print the measures as JSON");
  cmd->callback([a] { run_quality(*a); });
}

const Registration reg{"quality", add_quality};

}  // namespace
}  // namespace ris::app
