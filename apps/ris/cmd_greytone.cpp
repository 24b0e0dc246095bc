// `ris greytone POWER.tif`: re-runs the image chain after the mean power
// (fading, equation 15, film) on a saved slant-range mean-power GeoTIFF, with
// another seed, film or reference, without recomputing geometry: the seed's
// SLAR Greytone program run again on one geometry tape.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "command_registry.h"
#include "ris/image/greytone_image.h"
#include "ris/io/raster_io.h"
#include "ris/sensor/one_channel_radar.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"
#include "seed_option.h"

namespace ris::app {
namespace {

struct GreytoneOptions {
  std::string power_path;
  std::string radar_path = default_radar_path();
  std::string out_path = "greytone.png";
  std::string speckled_path;
  std::uint64_t seed = 1;
};

void run_greytone(const GreytoneOptions& o) {
  const RadarParams radar = load_one_channel_radar(o.radar_path, "ris greytone");
  RasterF64 power = [&] {
    try {
      return read_raster_f64(o.power_path);
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw InputError(o.power_path, "", e.what());
    }
  }();
  if (power.bands != 1 || power.cols != radar.range_bins) {
    throw InputError(
        o.power_path, "",
        fmt::format("expected a single-band slant-range power raster with {} columns "
                    "(the radar's range bins, {}), got {} band(s) of {} x {}",
                    radar.range_bins, o.radar_path, power.bands, power.cols, power.rows));
  }
  std::vector<float> p(power.data.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double v = power.data[i];
    const bool no_data = !std::isfinite(v) || (power.nodata && v == *power.nodata);
    p[i] = no_data ? std::nanf("") : static_cast<float>(v);
  }
  const GreytoneImage g = make_greytone_image(radar, p, power.rows, power.cols,
                                              radar.near_slant_range_m, radar.range_bin_m, o.seed);
  write_png_gray(o.out_path, g.greytone.data(), power.cols, power.rows);
  if (!o.speckled_path.empty()) {
    write_geotiff<float>(o.speckled_path, g.speckled_power_w.data(), power.cols, power.rows,
                         power.has_geotransform ? &power.georef : nullptr, std::nan(""),
                         {{"ris_fading_seed", std::to_string(o.seed)}}, "speckled power (W)");
  }
  fmt::print(
      "greytone {}: P_ref = {:.4g} W -> G_ref = {:.0f}, {:.1f} greytones per decade, {} "
      "fading{}\n",
      o.out_path, g.map.reference_power_w(), g.map.reference_greytone(),
      g.map.greytones_per_decade(),
      radar.fading == FadingLaw::exact_gamma ? "exact" : "seed (eq. 21)",
      radar.switches.fading ? fmt::format(", seed {}", o.seed) : std::string(" off"));
}

void add_greytone(CLI::App& app) {
  auto o = std::make_shared<GreytoneOptions>();
  auto* cmd = app.add_subcommand(
      "greytone", "Fading and film greytones from a saved slant-range mean-power GeoTIFF");
  cmd->add_option("power", o->power_path, "Mean power (W), lines x range bins, float GeoTIFF")
      ->required();
  cmd->add_option("--radar", o->radar_path, "Radar description (TOML): film, reference, fading")
      ->capture_default_str();
  cmd->add_option("--out", o->out_path, "Greytone PNG to write")->capture_default_str();
  cmd->add_option("--speckled", o->speckled_path, "Also write the speckled power (GeoTIFF)");
  add_seed_option(cmd, o->seed, "Fading seed");
  cmd->callback([o] { run_greytone(*o); });
}

const Registration reg{"greytone", add_greytone};

}  // namespace
}  // namespace ris::app
