// `ris scene classify IMAGE --classes N --out CLASSES.tif`: a land-cover
// raster from an image (issue 34 item 4, docs/classify.md): any raster GDAL
// reads (a real or simulated SAR image, a NISAR/UAVSAR RSLC product's SLC
// layer) read as intensity (ris/io/intensity_image.h), classified into N
// classes by k-means over smoothed dB (ris/image/land_cover_classify.h) or,
// with --training POLYGONS, into the polygons' categories by the nearest
// mean. Writes a Byte GeoTIFF of class codes (0 = no data) on the image's
// grid and georeferencing, and a JSON summary per class (pixels, mean
// intensity in dB, ENL); both or neither.
//
//   ris scene classify IMAGE --out CLASSES.tif (--classes N | --training POLYGONS)
//                      [--attribute category] [--band B ...] [--scale auto|power|amplitude|db]
//                      [--smooth PX] [--seed S] [--summary CLASSES.json] [--quiet]
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command_registry.h"
#include "ris/image/land_cover_classify.h"
#include "ris/io/atomic_file.h"
#include "ris/io/intensity_image.h"
#include "ris/io/raster_io.h"
#include "ris/io/safe_paths.h"
#include "ris/io/training_polygons.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "seed_option.h"

namespace ris::app {
namespace {

struct ClassifyArgs {
  std::string image, out, summary, training, attribute = "category", scale = "auto";
  int classes = 0;
  std::vector<int> bands;
  double smooth_px = 1.0;
  double looks = 0.0;  // > 0: report each class's K-distribution shape for L looks
  std::uint64_t seed = 1;
  bool quiet = false;
};

CLI::App* scene_group(CLI::App& app) {
  auto found = app.get_subcommands([](CLI::App* sub) { return sub->get_name() == "scene"; });
  if (!found.empty()) return found.front();
  auto* scene = app.add_subcommand("scene", "Build, import and inspect scenes");
  scene->require_subcommand(1);
  return scene;
}

std::string lower_extension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}

// Everything that needs no image: options and output paths.
void check_options(ClassifyArgs& a) {
  if (a.training.empty() && a.classes == 0)
    throw InputError("", "--classes", "give the number of classes (2..255) or --training");
  if (a.classes != 0 && (a.classes < 2 || a.classes > 255))
    throw InputError("", "--classes", fmt::format("expected 2..255 classes, got {}", a.classes));
  if (!(a.looks >= 0.0 && a.looks <= 1e6))
    throw InputError("", "--looks",
                     fmt::format("expected a number of looks above 0, got {}", a.looks));
  if (!(a.smooth_px >= 0.0 && a.smooth_px <= 50.0))
    throw InputError("", "--smooth", fmt::format("expected 0..50 pixels, got {}", a.smooth_px));
  const std::string ext = lower_extension(a.out);
  if (ext != ".tif" && ext != ".tiff")
    throw InputError(a.out, "--out", "expected a GeoTIFF (.tif or .tiff) for the class raster");
  if (a.summary.empty()) a.summary = std::filesystem::path(a.out).replace_extension(".json");
  if (lower_extension(a.summary) != ".json")
    throw InputError(a.summary, "--summary", "expected a .json file");
  if (std::filesystem::path(a.summary) == std::filesystem::path(a.out))
    throw InputError(a.summary, "--summary", "the same file as --out");
  require_safe_output_file(a.out, "--out");
  require_safe_output_file(a.summary, "--summary");
  if (a.bands.empty()) a.bands = {1};
}

struct Input {
  IntensityImage first;  // band 1's image: size, georeferencing, what it was read as
  ClassifyRequest req;
  std::size_t with_data = 0;
};

// The classification's memory, checked once the image's size is known and
// before its other bands are read: per pixel and band, its intensity (4
// bytes), dB, validity weight and blur buffer (12) and the sample matrix
// (4); per pixel, the validity, training and output codes (3), the sample
// index (8), k-means' labels (4) and the burnt polygons (1), rounded up.
void require_classify_memory(const ClassifyArgs& a, int cols, int rows) {
  const auto nb = static_cast<std::int64_t>(a.bands.size());
  const std::int64_t pixels = checked_mul(cols, rows, a.image, "");
  require_memory(checked_mul(pixels, 20 * nb + 20, a.image, ""), a.image, "",
                 fmt::format("classifying the {} x {} image on {} band(s)", cols, rows, nb));
}

// A dB image read as power has most of its values at or below zero (no
// data to the classifier): refused with the hint, rather than classifying
// the few positive dB values as power.
void refuse_negative_power(const ClassifyArgs& a, int band, const IntensityImage& img) {
  if (img.read_as != "power") return;
  std::size_t finite = 0, not_positive = 0;
  for (const float v : img.intensity) {
    finite += std::isfinite(v);
    not_positive += std::isfinite(v) && v <= 0.0f;
  }
  if (finite > 0 && 2 * not_positive > finite)
    throw InputError(a.image, "--scale",
                     fmt::format("band {} read as power has {} of its {} values at or below 0: "
                                 "for an image in dB give --scale db",
                                 band, not_positive, finite));
}

Input read_input(const ClassifyArgs& a) {
  const PixelScale scale = parse_pixel_scale(a.scale, "--scale");
  Input in;
  for (const int b : a.bands) {
    IntensityImage img = read_intensity_image(a.image, b, scale);
    if (in.req.bands.empty()) {
      in.req.rows = img.rows, in.req.cols = img.cols;
      require_classify_memory(a, img.cols, img.rows);
    } else if (img.rows != in.req.rows || img.cols != in.req.cols) {
      throw InputError(a.image, "--band",
                       fmt::format("band {} is {} x {} pixels, band {} {} x {}", b, img.cols,
                                   img.rows, a.bands[0], in.req.cols, in.req.rows));
    }
    refuse_negative_power(a, b, img);
    in.req.bands.push_back(std::move(img.intensity));
    if (in.req.bands.size() == 1) in.first = std::move(img);
  }
  const std::size_t n = in.req.bands[0].size();
  in.req.valid.assign(n, 1);
  for (const auto& band : in.req.bands)
    for (std::size_t i = 0; i < n; ++i)
      if (!(band[i] > 0.0f && std::isfinite(band[i]))) in.req.valid[i] = 0;
  in.with_data = static_cast<std::size_t>(std::count(in.req.valid.begin(), in.req.valid.end(), 1));
  if (in.with_data == 0)
    throw InputError(a.image, "", "no pixel has data (all no-data, non-finite or not above 0)");
  in.req.smooth_sigma_px = a.smooth_px;
  in.req.seed = a.seed;
  in.req.classes = a.classes;
  return in;
}

bool georeferenced(const IntensityImage& img) {
  return img.has_geotransform || !img.georef.gcps.empty();
}

ClassifyResult classify(const ClassifyArgs& a, Input& in, TrainingPixels& training) {
  if (a.training.empty()) {
    if (in.with_data < static_cast<std::size_t>(a.classes))
      throw InputError(
          a.image, "--classes",
          fmt::format("{} classes asked for, {} pixels have data", a.classes, in.with_data));
    return classify_unsupervised(in.req);
  }
  if (!georeferenced(in.first))
    throw InputError(a.image, "--training",
                     "the image has neither a geotransform nor ground control points, so "
                     "polygons cannot be placed on it");
  training = rasterize_training_polygons(a.training, a.attribute, in.first.georef, in.req.cols,
                                         in.req.rows);
  std::map<int, std::size_t> with_data;  // category -> training pixels that have data
  for (std::size_t i = 0; i < training.codes.size(); ++i)
    if (training.codes[i] != 0 && in.req.valid[i] != 0) ++with_data[training.codes[i]];
  if (with_data.size() < 2) {
    std::string have;
    for (const auto& [code, n] : training.pixels)
      have += fmt::format("{}category {}: {} pixels, {} with data", have.empty() ? "" : "; ", code,
                          n, with_data.count(code) != 0 ? with_data[code] : 0);
    throw InputError(a.training, "--training",
                     "supervised classification needs polygons of 2 or more categories over "
                     "pixels with data; " +
                         have);
  }
  ClassifyResult res = classify_nearest_mean(in.req, training.codes);
  if (a.classes != 0 && static_cast<std::size_t>(a.classes) != res.codes.size())
    throw InputError(a.training, "--classes",
                     fmt::format("{} classes asked for, the polygons give {} categories", a.classes,
                                 res.codes.size()));
  return res;
}

// Per band, the K-distribution shape nu by the method of moments
// (k_shape_moments); null where the class is no rougher than L-look speckle
// (nu infinite: JSON has no infinity).
nlohmann::json k_shape_json(const ClassStatistics& s, double looks) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t b = 0; b < s.m1.size(); ++b) {
    const double nu = s.m1[b] > 0.0 ? k_shape_moments(s.m1[b], s.m2[b], looks)
                                    : std::numeric_limits<double>::infinity();
    out.push_back(std::isfinite(nu) ? nlohmann::json(nu) : nlohmann::json(nullptr));
  }
  return out;
}

nlohmann::json summary_json(const ClassifyArgs& a, const Input& in, const ClassifyResult& res,
                            const TrainingPixels& training) {
  nlohmann::json j;
  j["image"] = {{"path", a.image},
                {"source", in.first.source},
                {"read_as", in.first.read_as},
                {"bands", a.bands},
                {"cols", in.req.cols},
                {"rows", in.req.rows},
                {"georeferenced", in.first.has_geotransform       ? "geotransform"
                                  : !in.first.georef.gcps.empty() ? "ground control points"
                                                                  : "no"}};
  j["pixels_with_data"] = in.with_data;
  j["no_data_pixels"] = in.req.valid.size() - in.with_data;
  j["method"] = a.training.empty() ? "k-means" : "nearest mean";
  j["smooth_sigma_px"] = a.smooth_px;
  if (a.training.empty()) j["seed"] = a.seed;
  if (a.looks > 0.0) j["looks"] = a.looks;
  if (!a.training.empty()) {
    nlohmann::json px = nlohmann::json::object();
    for (const auto& [code, n] : training.pixels) px[std::to_string(code)] = n;
    j["training"] = {{"path", a.training},
                     {"attribute", a.attribute},
                     {"features", training.features},
                     {"pixels", px}};
  }
  j["output"] = a.out;
  j["classes"] = nlohmann::json::array();
  const std::vector<ClassStatistics> stats = class_statistics(in.req, res);
  for (std::size_t c = 0; c < stats.size(); ++c) {
    const ClassStatistics& s = stats[c];
    nlohmann::json cls = {{"code", s.code},
                          {"pixels", s.pixels},
                          {"fraction", double(s.pixels) / double(in.with_data)},
                          {"mean_sigma0_db", s.mean_db},
                          {"enl", s.enl},
                          {"mean_smoothed_db", res.means[c]}};
    if (a.looks > 0.0) cls["k_shape_nu"] = k_shape_json(s, a.looks);
    j["classes"].push_back(cls);
  }
  return j;
}

void print_summary(const nlohmann::json& j) {
  fmt::print("{}: {} x {} pixels read as {}, {} with data; {} classes by {}\n",
             j["image"]["path"].get<std::string>(), j["image"]["cols"].get<int>(),
             j["image"]["rows"].get<int>(), j["image"]["read_as"].get<std::string>(),
             j["pixels_with_data"].get<std::size_t>(), j["classes"].size(),
             j["method"].get<std::string>());
  fmt::print("{:>6} {:>10} {:>9} {:>14} {:>8}\n", "class", "pixels", "fraction", "mean dB (b1)",
             "ENL (b1)");
  for (const auto& c : j["classes"])
    fmt::print("{:>6} {:>10} {:>9.4f} {:>14.2f} {:>8.3f}\n", c["code"].get<int>(),
               c["pixels"].get<std::size_t>(), c["fraction"].get<double>(),
               c["mean_sigma0_db"][0].get<double>(), c["enl"][0].get<double>());
}

void run_classify(ClassifyArgs a) {
  check_options(a);
  Input in = read_input(a);
  TrainingPixels training;
  const ClassifyResult res = classify(a, in, training);
  const nlohmann::json j = summary_json(a, in, res, training);
  // Both files or neither: each written under a temporary name, renamed
  // only when both are complete.
  AtomicPath tif(a.out), json(a.summary);
  const RasterMetadata md{{"RIS_CLASSIFY_METHOD", j["method"].get<std::string>()},
                          {"RIS_CLASSIFY_SOURCE", a.image},
                          {"RIS_CLASSIFY_CLASSES", std::to_string(res.codes.size())}};
  write_geotiff<std::uint8_t>(tif.temp_path(), res.labels.data(), in.req.cols, in.req.rows,
                              georeferenced(in.first) ? &in.first.georef : nullptr, 0.0, md,
                              "class code (0 = no data)");
  write_text_file_atomic(json.temp_path(), j.dump(1) + "\n");
  tif.commit();
  json.commit();
  if (!a.quiet) {
    print_summary(j);
    fmt::print("wrote {} and {}\n", a.out, a.summary);
  }
}

void add_scene_classify(CLI::App& app) {
  CLI::App* scene = scene_group(app);
  auto a = std::make_shared<ClassifyArgs>();
  auto* cmd = scene->add_subcommand(
      "classify",
      "Classify an image (any GDAL raster, a real or simulated SAR image) into a land-cover "
      "raster: k-means over smoothed dB, or the nearest mean of training polygons");
  cmd->add_option("image", a->image,
                  "Image: a raster (GeoTIFF, ...) or a NISAR/UAVSAR RSLC .h5 product")
      ->required();
  cmd->add_option("--out", a->out, "Class raster to write (GeoTIFF .tif: Byte, 0 = no data)")
      ->required();
  cmd->add_option("--classes", a->classes,
                  "Number of classes, 2..255 (unsupervised); with --training, if given, the "
                  "number of categories the polygons must give");
  cmd->add_option("--training", a->training,
                  "Training polygons (GeoJSON, GeoPackage, ... any CRS) with an integer "
                  "category attribute: supervised, by the nearest mean");
  cmd->add_option("--attribute", a->attribute, "The polygons' category attribute")
      ->capture_default_str();
  cmd->add_option("--band", a->bands,
                  "Band(s) or SLC layer(s) to classify on, from 1 (repeatable; default 1)");
  cmd->add_option("--scale", a->scale,
                  "What the pixel values are: auto (float = power, integer = amplitude, complex "
                  "= |z|^2), power, amplitude or db")
      ->capture_default_str();
  cmd->add_option("--smooth", a->smooth_px,
                  "Gaussian smoothing of the dB image before classifying, sigma in pixels")
      ->capture_default_str();
  add_seed_option(cmd, a->seed, "Seed of the k-means++ initialisation");
  cmd->add_option("--looks", a->looks,
                  "The image's number of looks L: also report each class's K-distribution "
                  "shape nu (method of moments; docs/classify.md)");
  cmd->add_option("--summary", a->summary, "JSON summary per class (default: --out with .json)");
  cmd->add_flag("--quiet", a->quiet, "Print nothing on success");
  cmd->callback([a] { run_classify(*a); });
}

}  // namespace

const Registration reg{"scene_classify", add_scene_classify};

}  // namespace ris::app
