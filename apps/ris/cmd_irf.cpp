// `ris irf IMAGE.tif --line L --bin B`: the impulse-response quality of a
// point target in a power image (ris/image/impulse_response.h): 3 dB widths
// in range and azimuth, PSLR and ISLR. For ris's slant-range products the
// pixel sizes come from the file (RIS_RANGE_BIN_M, RIS_LINE_SPACING_M);
// any other single-band power raster needs --range-pixel and
// --azimuth-pixel. `ris simulate --targets` measures every target itself;
// this re-measures a saved image, e.g. at another target or with another
// interpolation.
#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command_registry.h"
#include "ris/image/impulse_response.h"
#include "ris/io/atomic_file.h"
#include "ris/io/raster_io.h"
#include "ris/util/error.h"

namespace ris::app {
namespace {

struct IrfOptions {
  std::string image;
  int line = -1, bin = -1;
  int search_px = 3, half_cut_px = 24;
  std::string interpolation = "sinc";
  double range_pixel_m = 0.0, azimuth_pixel_m = 0.0;
  std::string json_path;
};

// A pixel size from the option, else from the file's metadata item.
double pixel_size(const RasterF64& r, const IrfOptions& o, double given, const char* item,
                  const char* option) {
  if (given > 0.0) return given;
  const auto it = r.metadata.find(item);
  if (it != r.metadata.end()) {
    try {
      const double v = std::stod(it->second);
      if (v > 0.0 && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
  }
  throw InputError(o.image, option,
                   fmt::format("the image has no {} metadata item; give the pixel size with {} "
                               "(metres, > 0)",
                               item, option));
}

void run_irf(const IrfOptions& o) {
  if (o.interpolation != "sinc" && o.interpolation != "linear") {
    throw InputError("", "--interpolation",
                     fmt::format("expected sinc or linear, got '{}'", o.interpolation));
  }
  if (o.search_px < 0 || o.half_cut_px < 2) {
    throw InputError("", "--search/--half-length",
                     "expected a search radius >= 0 and a half cut length >= 2 pixels");
  }
  const RasterF64 r = read_raster_f64(o.image);
  if (r.bands != 1) {
    throw InputError(o.image, "", fmt::format("expected one band of power, got {}", r.bands));
  }
  if (o.line < 0 || o.line >= r.rows || o.bin < 0 || o.bin >= r.cols) {
    throw InputError(o.image, "--line/--bin",
                     fmt::format("pixel (line {}, bin {}) is outside the {} x {} image", o.line,
                                 o.bin, r.rows, r.cols));
  }
  const double dr = pixel_size(r, o, o.range_pixel_m, "RIS_RANGE_BIN_M", "--range-pixel");
  const double ds = pixel_size(r, o, o.azimuth_pixel_m, "RIS_LINE_SPACING_M", "--azimuth-pixel");
  std::vector<float> power(r.data.size());
  for (std::size_t i = 0; i < power.size(); ++i) {
    const double v = r.data[i];
    power[i] =
        (!std::isfinite(v) || (r.nodata && v == *r.nodata)) ? std::nanf("") : static_cast<float>(v);
  }
  const IrfMeasurement m =
      measure_irf(power, r.rows, r.cols, ds, dr, o.line, o.bin, o.search_px, o.half_cut_px,
                  o.interpolation == "sinc" ? IrfInterpolation::sinc : IrfInterpolation::linear);
  fmt::print("peak at line {}, bin {}: {:.4g} W\n", m.peak_line, m.peak_bin, m.peak_power_w);
  fmt::print("  3 dB width   range {:.3f} m, azimuth {:.3f} m\n", m.range.width_m,
             m.azimuth.width_m);
  fmt::print("  PSLR         range {:.2f} dB, azimuth {:.2f} dB\n", m.range.pslr_db,
             m.azimuth.pslr_db);
  fmt::print("  ISLR         range {:.2f} dB, azimuth {:.2f} dB\n", m.range.islr_db,
             m.azimuth.islr_db);
  if (!o.json_path.empty()) {
    nlohmann::json j = irf_to_json(m);
    j["image"] = o.image;
    j["interpolation"] = o.interpolation;
    write_text_file_atomic(o.json_path, j.dump(2) + "\n");
  }
}

void add_irf(CLI::App& app) {
  auto o = std::make_shared<IrfOptions>();
  auto* cmd = app.add_subcommand(
      "irf", "Measure a point target's impulse response (3 dB widths, PSLR, ISLR) in an image");
  cmd->add_option("image", o->image, "Power image (e.g. out/speckled_power_slant.tif)")->required();
  cmd->add_option("--line", o->line, "Azimuth line (row) near the target")->required();
  cmd->add_option("--bin", o->bin, "Range bin (column) near the target")->required();
  cmd->add_option("--search", o->search_px, "Look for the peak within this many pixels")
      ->capture_default_str();
  cmd->add_option("--half-length", o->half_cut_px, "Pixels each side of the peak in each cut")
      ->capture_default_str();
  cmd->add_option("--interpolation", o->interpolation,
                  "sinc (coherent images) or linear (box responses)")
      ->capture_default_str();
  cmd->add_option("--range-pixel", o->range_pixel_m, "Range pixel size, m (default: from file)");
  cmd->add_option("--azimuth-pixel", o->azimuth_pixel_m,
                  "Azimuth pixel size, m (default: from file)");
  cmd->add_option("--json", o->json_path, "Also write the measurement as JSON");
  cmd->callback([o] { run_irf(*o); });
}

const Registration reg{"irf", add_irf};

}  // namespace
}  // namespace ris::app
