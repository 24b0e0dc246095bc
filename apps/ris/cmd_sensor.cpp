// ris sensor optical|thermal: an optical or thermal image of a scene on its
// own grid (one pixel per scene cell, the scene's geotransform and CRS, so it
// overlays the radar's scene-grid products in a GIS). docs/sensors.md.
//
//   ris sensor optical scene.tif --sensor data/sensors_eo/optical.toml -o out/
//   ris sensor thermal scene.tif --sensor data/sensors_eo/thermal.toml -o out/
//
// Products: radiance.tif (optical, float32 per band, W m-2 sr-1 um-1) or
// brightness_temperature.tif (thermal, K), preview.png, metadata.json; all or
// none (a staged folder).
#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "command_registry.h"
#include "ris/io/atomic_file.h"
#include "ris/io/raster_io.h"
#include "ris/scene/geo_frame.h"
#include "ris/scene/scene_source.h"
#include "ris/sensors_eo/eo_render.h"
#include "ris/util/error.h"

namespace {

using ris::InputError;

struct SensorArgs {
  std::string kind;
  std::string scene;
  std::string sensor;
  std::string table;
  std::string out;
  int threads = 0;
  bool quiet = false;
};

// The place the sun is computed for: the scene's centre through its CRS, or
// the sensor file's latitude/longitude (which win when given).
std::pair<double, double> scene_lat_lon(const ris::Scene& scene, const ris::EoSensorConfig& cfg,
                                        const std::string& scene_path) {
  if (cfg.latitude_deg && cfg.longitude_deg) return {*cfg.latitude_deg, *cfg.longitude_deg};
  if (scene.crs_wkt.empty()) {
    throw InputError(cfg.path, "latitude",
                     "the scene " + scene_path + " has no CRS: give latitude and longitude");
  }
  const ris::GeoFrame frame(scene.crs_wkt, scene_path);
  const auto [x, y] = scene.world_from_grid(scene.cols / 2.0, scene.rows / 2.0);
  const auto [lon, lat] = frame.lonlat_from_scene(x, y);
  return {lat, lon};
}

// 8-bit preview: RGB from red/green/blue when all three are imaged, else the
// first band in grey; each stretched linearly between its 2nd and 98th
// percentiles (NaN black).
std::vector<std::uint8_t> stretch(const std::vector<float>& v) {
  std::vector<float> finite;
  for (float x : v) {
    if (std::isfinite(x)) finite.push_back(x);
  }
  std::vector<std::uint8_t> out(v.size(), 0);
  if (finite.empty()) return out;
  std::sort(finite.begin(), finite.end());
  const float lo = finite[finite.size() * 2 / 100];
  const float hi = finite[std::min(finite.size() - 1, finite.size() * 98 / 100)];
  const float span = hi > lo ? hi - lo : 1.0f;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::isfinite(v[i]))
      out[i] =
          static_cast<std::uint8_t>(std::clamp((v[i] - lo) / span, 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  return out;
}

void write_preview(const std::filesystem::path& path, const ris::EoImage& img) {
  auto find = [&](const char* n) {
    const auto it = std::find(img.band_names.begin(), img.band_names.end(), n);
    return it == img.band_names.end() ? -1 : static_cast<int>(it - img.band_names.begin());
  };
  const int r = find("red"), g = find("green"), b = find("blue");
  if (r < 0 || g < 0 || b < 0) {
    ris::write_png_gray(path, stretch(img.bands[0]).data(), img.cols, img.rows);
    return;
  }
  const auto sr = stretch(img.bands[r]), sg = stretch(img.bands[g]), sb = stretch(img.bands[b]);
  std::vector<std::uint8_t> rgb(sr.size() * 3);
  for (std::size_t i = 0; i < sr.size(); ++i) {
    rgb[3 * i] = sr[i];
    rgb[3 * i + 1] = sg[i];
    rgb[3 * i + 2] = sb[i];
  }
  ris::write_png_rgb(path, rgb.data(), img.cols, img.rows);
}

nlohmann::json metadata(const SensorArgs& a, const ris::EoSensorConfig& cfg,
                        const ris::EoImage& img) {
  nlohmann::json md;
  md["sensor_kind"] = a.kind;
  md["scene"] = a.scene;
  md["sensor_file"] = a.sensor;
  md["surface_table"] = a.table;
  md["rows"] = img.rows;
  md["cols"] = img.cols;
  md["bands"] = img.band_names;
  md["unit"] = img.unit;
  md["utc"] = fmt::format("{:04d}-{:02d}-{:02d}T{:09.6f}h", cfg.when.year, cfg.when.month,
                          cfg.when.day, cfg.when.hour);
  md["latitude_deg"] = img.latitude_deg;
  md["longitude_deg"] = img.longitude_deg;
  md["sun"] = {{"zenith_deg", img.sun.zenith_deg},
               {"azimuth_deg", img.sun.azimuth_deg},
               {"elevation_deg", img.sun.elevation_deg},
               {"earth_sun_distance_au", img.sun.earth_sun_distance_au}};
  md["night"] = img.night;
  md["shadowed_cells"] = img.shadowed_cells;
  md["noise"] = cfg.noise;
  md["seed"] = cfg.seed;
  md["sun_algorithm"] = "NOAA solar calculator (Meeus 1991)";
  return md;
}

void run_sensor(const SensorArgs& a) {
  if (a.threads > 0) omp_set_num_threads(a.threads);
  const ris::EoSensorConfig cfg = ris::load_eo_sensor(a.sensor);
  const bool thermal = cfg.kind == ris::EoKind::thermal;
  if ((a.kind == "thermal") != thermal) {
    throw InputError(a.sensor, "kind",
                     fmt::format("the file is a {} sensor but the command is `ris sensor {}`",
                                 thermal ? "thermal" : "optical", a.kind));
  }
  const ris::EoSurfaceTable table = ris::load_eo_surface_table(a.table);
  const ris::LoadedScene loaded = ris::load_scene_source(a.scene);
  const ris::Scene& scene = loaded.scene;
  const auto [lat, lon] = scene_lat_lon(scene, cfg, a.scene);
  const ris::EoImage img = ris::render_eo(scene, cfg, table, lat, lon);
  if (img.night && !thermal) {
    spdlog::warn(
        "{}: the sun is below the horizon (elevation {:.2f} deg) at {} UTC hour {:.3f}: rendering "
        "night (path radiance only)",
        a.sensor, img.sun.elevation_deg,
        fmt::format("{:04d}-{:02d}-{:02d}", cfg.when.year, cfg.when.month, cfg.when.day),
        cfg.when.hour);
  }

  ris::StagedDirectory out(a.out);
  const ris::Georef georef(scene.geotransform(), scene.crs_wkt);
  std::vector<ris::BandView<float>> views;
  for (std::size_t b = 0; b < img.bands.size(); ++b) {
    views.push_back({img.bands[b].data(), img.band_names[b] + " (" + img.unit + ")"});
  }
  ris::RasterMetadata md{{"RIS_SENSOR", a.kind}, {"RIS_UNIT", img.unit}};
  const std::string name = thermal ? "brightness_temperature.tif" : "radiance.tif";
  ris::write_geotiff_bands<float>(out.path(name), views, img.cols, img.rows, &georef,
                                  std::numeric_limits<double>::quiet_NaN(), md);
  write_preview(out.path("preview.png"), img);
  ris::write_text_file_atomic(out.path("metadata.json"), metadata(a, cfg, img).dump(2) + "\n");
  out.commit();
  if (!a.quiet) {
    fmt::print(
        "{} image {} x {} ({}), sun zenith {:.3f} deg azimuth {:.3f} deg, {} shadowed cells; wrote "
        "{}\n",
        a.kind, img.cols, img.rows, fmt::join(img.band_names, ","), img.sun.zenith_deg,
        img.sun.azimuth_deg, img.shadowed_cells, a.out);
  }
}

void add_sensor(CLI::App& app) {
  auto a = std::make_shared<SensorArgs>();
  auto* cmd = app.add_subcommand("sensor", "An optical or thermal image of a scene on its grid");
  cmd->add_option("kind", a->kind, "optical or thermal")
      ->required()
      ->check(CLI::IsMember({"optical", "thermal"}));
  cmd->add_option("scene", a->scene, "Scene file")->required();
  cmd->add_option("--sensor", a->sensor, "Sensor TOML (data/sensors_eo/optical.toml, thermal.toml)")
      ->required();
  a->table = ris::app::data_path("sensors_eo/generic-terrain-eo.csv");
  cmd->add_option("--table", a->table, "Per-category surface table (CSV)")->capture_default_str();
  cmd->add_option("--out,-o", a->out, "Output folder")->required();
  cmd->add_option("--threads", a->threads, "Threads (0: all)")->capture_default_str();
  cmd->add_flag("--quiet,-q", a->quiet, "Print nothing");
  cmd->callback([a] { run_sensor(*a); });
}

const ris::app::Registration reg{"sensor", add_sensor};

}  // namespace
