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
#include "ris/scene/scene_source.h"
#include "ris/sensors_eo/camera_view.h"
#include "ris/sensors_eo/eo_place.h"
#include "ris/sensors_eo/eo_preview.h"
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

void write_preview(const std::filesystem::path& path, const std::vector<std::string>& names,
                   const std::vector<std::vector<float>>& bands, int cols, int rows) {
  const ris::EoPreview p = ris::eo_preview(names, bands);
  if (p.channels == 3) {
    ris::write_png_rgb(path, p.pixels.data(), cols, rows);
  } else {
    ris::write_png_gray(path, p.pixels.data(), cols, rows);
  }
}

nlohmann::json metadata(const SensorArgs& a, const ris::EoSensorConfig& cfg,
                        const ris::EoImage& img) {
  nlohmann::json md;
  md["sensor_kind"] = a.kind;
  md["scene"] = a.scene;
  md["sensor_file"] = a.sensor;
  md["surface_table"] = a.table.empty() ? ris::default_eo_surface_table(a.scene) : a.table;
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

// The scene-grid image the camera looks at: without noise (the camera adds
// its own per pixel); the same image when the sensor has none.
ris::EoImage noise_free(const ris::Scene& scene, const ris::EoSensorConfig& cfg,
                        const ris::EoSurfaceTable& table, const ris::EoImage& img, double lat,
                        double lon, const ris::EoTerrain& terrain) {
  if (cfg.noise == 0) return img;
  ris::EoSensorConfig quiet = cfg;
  quiet.noise = 0;
  return ris::render_eo(scene, quiet, table, lat, lon, &terrain);
}

// camera_*.tif (GCPs in the scene's CRS from the rays' ground points, so
// gdalwarp -tps places the picture), camera_preview.png; returns the
// metadata's camera block.
nlohmann::json write_camera_products(ris::StagedDirectory& out, const ris::Scene& scene,
                                     const ris::EoSensorConfig& cfg, const ris::EoImage& grid,
                                     const ris::EoTerrain& terrain) {
  const ris::FrameCamera& cam = *cfg.camera;
  const ris::CameraImage img =
      ris::view_through_camera(scene, grid, cfg, cam, cfg.detector, &terrain);
  ris::Georef georef;
  georef.crs_wkt = scene.crs_wkt;
  georef.gcps = img.gcps;
  const ris::Georef* geo = img.gcps.size() >= 3 ? &georef : nullptr;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<ris::BandView<float>> views;
  for (std::size_t b = 0; b < img.bands.size(); ++b) {
    views.push_back({img.bands[b].data(), img.band_names[b] + " (" + img.unit + ")"});
  }
  const bool thermal = cfg.kind == ris::EoKind::thermal;
  const ris::RasterMetadata md{{"RIS_SENSOR", thermal ? "thermal camera" : "optical camera"},
                               {"RIS_UNIT", img.unit}};
  ris::write_geotiff_bands<float>(
      out.path(thermal ? "camera_brightness_temperature.tif" : "camera_radiance.tif"), views,
      img.cols, img.rows, geo, nan, md);
  ris::write_geotiff<float>(out.path("camera_range_m.tif"), img.range_m.data(), img.cols, img.rows,
                            geo, nan, {{"RIS_UNIT", "m"}});
  ris::write_geotiff<float>(out.path("camera_footprint_area_m2.tif"), img.footprint_area_m2.data(),
                            img.cols, img.rows, geo, nan, {{"RIS_UNIT", "m2"}});
  if (!img.digital_numbers.empty()) {
    std::vector<ris::BandView<std::uint16_t>> dn;
    for (std::size_t b = 0; b < img.digital_numbers.size(); ++b) {
      dn.push_back({img.digital_numbers[b].data(), img.band_names[b] + " (DN)"});
    }
    ris::write_geotiff_bands<std::uint16_t>(out.path("camera_digital_number.tif"), dn, img.cols,
                                            img.rows, geo, std::nullopt, {{"RIS_UNIT", "DN"}});
  }
  write_preview(out.path("camera_preview.png"), img.band_names, img.bands, img.cols, img.rows);
  return {{"position_m", {cam.x_m, cam.y_m}},
          {"altitude_m", cam.altitude_m},
          {"heading_deg", cam.heading_deg},
          {"depression_deg", cam.depression_deg},
          {"fov_deg", cam.fov_deg},
          {"columns", cam.cols},
          {"rows", cam.rows},
          {"samples", cam.samples},
          {"mtf_at_nyquist", cam.mtf_at_nyquist},
          {"empty_pixels", img.empty_pixels},
          {"gcps", img.gcps.size()},
          {"digital_numbers", !img.digital_numbers.empty()}};
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
  const std::string table_path = a.table.empty() ? ris::default_eo_surface_table(a.scene) : a.table;
  const ris::EoSurfaceTable table = ris::load_eo_surface_table(table_path);
  const ris::LoadedScene loaded = ris::load_scene_source(a.scene);
  const ris::Scene& scene = loaded.scene;
  const auto [lat, lon] = ris::eo_place(scene, cfg, a.scene);
  const ris::EoTerrain terrain = ris::build_eo_terrain(scene);  // for the sun and the camera
  const ris::EoImage img = ris::render_eo(scene, cfg, table, lat, lon, &terrain);
  if (img.night && !thermal) {
    spdlog::warn(
        "{}: the sun is below the horizon (elevation {:.2f} deg) at {} UTC hour {:.3f}: rendering "
        "night (path radiance only)",
        a.sensor, img.sun.elevation_deg,
        fmt::format("{:04d}-{:02d}-{:02d}", cfg.when.year, cfg.when.month, cfg.when.day),
        cfg.when.hour);
  }

  ris::StagedDirectory out(a.out);
  nlohmann::json md_json = metadata(a, cfg, img);
  const ris::Georef georef(scene.geotransform(), scene.crs_wkt);
  std::vector<ris::BandView<float>> views;
  for (std::size_t b = 0; b < img.bands.size(); ++b) {
    views.push_back({img.bands[b].data(), img.band_names[b] + " (" + img.unit + ")"});
  }
  ris::RasterMetadata md{{"RIS_SENSOR", a.kind}, {"RIS_UNIT", img.unit}};
  const std::string name = thermal ? "brightness_temperature.tif" : "radiance.tif";
  ris::write_geotiff_bands<float>(out.path(name), views, img.cols, img.rows, &georef,
                                  std::numeric_limits<double>::quiet_NaN(), md);
  write_preview(out.path("preview.png"), img.band_names, img.bands, img.cols, img.rows);
  if (cfg.camera) {
    md_json["camera"] = write_camera_products(
        out, scene, cfg, noise_free(scene, cfg, table, img, lat, lon, terrain), terrain);
  }
  ris::write_text_file_atomic(out.path("metadata.json"), md_json.dump(2) + "\n");
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
  cmd->add_option("--table", a->table,
                  "Per-category surface table (CSV; default: data/sensors_eo/<the scene's "
                  "backscatter library>-eo.csv, else generic-terrain-eo.csv)");
  cmd->add_option("--out,-o", a->out, "Output folder")->required();
  cmd->add_option("--threads", a->threads, "Threads (0: all)")->capture_default_str();
  cmd->add_flag("--quiet,-q", a->quiet, "Print nothing");
  cmd->callback([a] { run_sensor(*a); });
}

const ris::app::Registration reg{"sensor", add_sensor};

}  // namespace
