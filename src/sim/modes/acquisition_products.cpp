#include "ris/sim/acquisition_products.h"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <limits>
#include <type_traits>

#include "ris/io/atomic_file.h"
#include "ris/io/compression_preset.h"
#include "ris/io/raster_io.h"
#include "ris/sensor/radar_json.h"
#include "ris/sim/run_metadata.h"
#include "ris/sim/slar_products.h"
#include "ris/util/concurrent_tasks.h"

namespace ris {

using nlohmann::json;

namespace {

const char* earth_name(EarthModel e) {
  return e == EarthModel::flat ? "flat" : "ellipsoid";
}

}  // namespace

RasterMetadata acquisition_grid_metadata(const AcquisitionSimulation& a) {
  const RadarGrid& g = a.grid;
  const GridWindow& w = a.window;
  return {{"RIS_ACQUISITION", a.acquisition_source},
          {"RIS_GRID_LINES", std::to_string(g.lines)},
          {"RIS_GRID_BINS", std::to_string(g.bins)},
          {"RIS_WINDOW_FIRST_LINE", std::to_string(w.line0)},
          {"RIS_WINDOW_FIRST_BIN", std::to_string(w.bin0)},
          {"RIS_FIRST_LINE_TIME_S", fmt::format("{:.9f}", g.time_of_line(w.line0))},
          {"RIS_LINE_INTERVAL_S", fmt::format("{:.12g}", g.line_interval_s)},
          {"RIS_NEAR_RANGE_M", fmt::format("{:.6f}", g.range_of_bin(w.bin0))},
          {"RIS_RANGE_SPACING_M", fmt::format("{:.6f}", g.range_spacing_m)},
          {"RIS_EARTH_MODEL", earth_name(a.earth)}};
}

SlarRasterSpec acquisition_raster_spec(const std::string& file, const AcquisitionSimulation& a,
                                       const SlarImage& img) {
  SlarRasterSpec spec;
  if (file == "local_incidence.tif") {
    spec.metadata = {{"RIS_PRODUCT", "local incidence of the terrain at each bin"},
                     {"RIS_UNITS", "degrees"}};
    spec.band = "local_incidence_deg";
    spec.nodata = std::numeric_limits<double>::quiet_NaN();
  } else if (file == "layover_shadow_mask.tif") {
    spec.metadata = {{"RIS_PRODUCT", "layover/shadow mask: 0 none, 1 shadow, 2 layover, 3 both"}};
    spec.band = "layover_shadow_mask";
  } else {
    spec = slar_raster_spec(file, img);
  }
  spec.georeferenced = false;  // the grid's axes, no map georeferencing
  const RasterMetadata grid_md = acquisition_grid_metadata(a);
  spec.metadata.insert(grid_md.begin(), grid_md.end());
  return spec;
}

const std::vector<std::string_view>& acquisition_product_stems() {
  static const std::vector<std::string_view> stems = {
      "slant_range",     "ground_range",    "mean_power_slant",    "speckled_power_slant",
      "mask_slant",      "local_incidence", "layover_shadow_mask", "sigma0_slant",
      "sigma0_slant_db", "beta0_slant",     "beta0_slant_db",      "gamma0_slant",
      "gamma0_slant_db"};
  return stems;
}

json acquisition_metadata(const AcquisitionSimulation& a, const SlarSimulation& sim,
                          const SlarPictures& pic, const SlarRunInfo& info) {
  const RadarGrid& g = a.grid;
  const GridWindow& w = a.window;
  const SlarImage& img = sim.image;
  const SlarGeometry& geo = sim.geometry;
  json out = run_header_json(sim.radar.mode == RadarMode::sar ? "sar" : "slar");
  out["earth_model"] = earth_name(a.earth);
  if (!sim.warnings.empty()) out["warnings"] = sim.warnings;
  out["acquisition"] = {
      {"path", a.acquisition_source},
      {"format", a.acquisition_format},
      {"mission", a.mission},
      {"polarisation", a.polarisation},
      {"notes", a.acquisition_notes},
      {"grid",
       {{"lines", g.lines},
        {"bins", g.bins},
        {"first_line_time_s", g.sensing_start_s},
        {"line_interval_s", g.line_interval_s},
        {"near_range_m", g.near_range_m},
        {"range_spacing_m", g.range_spacing_m},
        {"look_side", g.look_side == LookSide::left ? "left" : "right"},
        {"wavelength_m", g.wavelength_m}}},
      {"window",
       {{"first_line", w.line0}, {"lines", w.lines}, {"first_bin", w.bin0}, {"bins", w.bins}}}};
  out["inputs"] = {
      {"dem",
       {{"path", a.dem_source},
        {"vertical", a.dem_vertical_note},
        {"height_min_m", a.dem_min_m},
        {"height_max_m", a.dem_max_m},
        {"category", a.category},
        {"land_cover", a.land_cover_source.empty() ? nlohmann::json(nullptr)
                                                   : nlohmann::json(a.land_cover_source)}}},
      {"radar", radar_to_json(sim.radar)},
      {"backscatter",
       {{"path", info.backscatter_path}, {"description", sim.backscatter_description}}},
      {"seed", info.seed},
      {"threads", info.threads}};
  out["derived"] = {{"geometry",
                     {{"line_source", "terrain profile in each line's zero-Doppler plane"},
                      {"profile_points_per_line", a.profile_points},
                      {"sensor_height_m", a.sensor_height_m},
                      {"ground_azimuth_spacing_m", a.ground_azimuth_spacing_m},
                      {"nodata_samples", geo.nodata_samples},
                      {"shadow_samples", geo.shadow_samples},
                      {"back_facing_samples", geo.back_facing_samples},
                      {"layover_samples", geo.layover_samples}}},
                    {"image", slar_image_json(sim)},
                    {"greytone", greytone_json(pic)}};
  out["products"] = selected_products(
      {{picture_file("slant_range", img.bins, img.lines, info.max_png_pixels),
        "greytones on the acquisition's grid window: rows its lines, columns its range bins"},
       {picture_file("ground_range", sim.ground_grid.count, img.lines, info.max_png_pixels),
        "greytones, ground range over the DEM's mid height (flat Earth)"},
       {"mean_power_slant.tif", "float32 mean received power (W) before speckle"},
       {"speckled_power_slant.tif", "float32 received power (W) after fading"},
       {"mask_slant.tif", "uint8 image mask: 1 shadow, 2 layover, 4 no data"},
       {"local_incidence.tif", "float32 local incidence (degrees) of the terrain at each bin"},
       {"layover_shadow_mask.tif", "uint8 0 none, 1 shadow, 2 layover, 3 both (as ris topo)"},
       {"metadata.json", "this file"}},
      info.products);
  add_calibrated_descriptions(out["products"], sim, info);
  return out;
}

void write_acquisition_products(const std::filesystem::path& out_dir,
                                const AcquisitionSimulation& a, const SlarSimulation& sim,
                                const SlarPictures& pic, const SlarRunInfo& info) {
  StagedDirectory dir(out_dir);
  const SlarImage& img = sim.image;
  const ProductSelection& want = info.products;
  // As a scene run's products (write_slar_products): the preset, overviews
  // on request.
  const GeoTiffCompression float_tif = product_tiff_settings(info, true);
  const GeoTiffCompression int_tif = product_tiff_settings(info, false);
  std::vector<std::function<void()>> tasks;
  // A raster (no map geotransform: its axes are the grid's); on the
  // window's grid it carries the window's GCPs (ris/image/acquisition_georef.h).
  const Georef* gcps = a.georef.gcps.empty() ? nullptr : &a.georef;
  const auto raster_with = [&](const Georef* georef, const std::string& stem,
                               const std::string& file, const auto* data, int cols, int rows) {
    if (!want.wants(stem)) return;
    tasks.emplace_back([&, georef, file, data, cols, rows] {
      const SlarRasterSpec spec = acquisition_raster_spec(file, a, img);
      using T = std::remove_cvref_t<decltype(*data)>;
      write_geotiff(dir.path(file), data, cols, rows, georef, spec.nodata, spec.metadata, spec.band,
                    BlockOrder::top_down, std::is_floating_point_v<T> ? &float_tif : &int_tif);
    });
  };
  const auto raster = [&](const std::string& stem, const std::string& file, const auto* data,
                          int cols, int rows) { raster_with(gcps, stem, file, data, cols, rows); };
  const auto& slant = raster;
  // The ground-range picture is not on the window's grid: no GCPs.
  const auto picture = [&](const std::string& stem, const std::uint8_t* grey, int cols, int rows,
                           const Georef* georef) {
    const std::string file = picture_file(stem, cols, rows, info.max_png_pixels);
    if (file.ends_with(".png")) {
      if (!want.wants(stem)) return;
      tasks.emplace_back([&, file, grey, cols, rows] {
        write_png_gray(dir.path(file), grey, cols, rows, png_compression_level(info.compression));
      });
    } else {
      raster_with(georef, stem, file, grey, cols, rows);
    }
  };
  // No-data pixels are NaN in the mean power (the file's no-data value).
  std::vector<float> mean(img.mean_power_w.begin(), img.mean_power_w.end());
  for (std::size_t i = 0; i < mean.size(); ++i)
    if (img.mask[i] & pixel_flag::kNoData) mean[i] = std::numeric_limits<float>::quiet_NaN();
  slant("mean_power_slant", "mean_power_slant.tif", mean.data(), img.bins, img.lines);
  slant("speckled_power_slant", "speckled_power_slant.tif", pic.speckled_power_w.data(), img.bins,
        img.lines);
  slant("mask_slant", "mask_slant.tif", img.mask.data(), img.bins, img.lines);
  add_calibrated_tasks(tasks, sim, pic, info, [&](const std::string& file, const float* v) {
    const SlarRasterSpec spec = acquisition_raster_spec(file, a, img);
    write_geotiff(dir.path(file), v, img.bins, img.lines, gcps, spec.nodata, spec.metadata,
                  spec.band, BlockOrder::top_down, &float_tif);
  });
  picture("slant_range", pic.slant_grey.data(), img.bins, img.lines, gcps);
  picture("ground_range", pic.ground_grey.data(), sim.ground_grid.count, img.lines, nullptr);
  const GridWindow& w = a.window;
  raster("local_incidence", "local_incidence.tif", a.local_incidence_deg.data(), w.bins, w.lines);
  raster("layover_shadow_mask", "layover_shadow_mask.tif", a.layover_shadow_mask.data(), w.bins,
         w.lines);
  tasks.emplace_back([&] {
    write_text_file_atomic(dir.path("metadata.json"),
                           acquisition_metadata(a, sim, pic, info).dump(2) + "\n");
  });
  run_concurrently(tasks, info.threads);
  dir.commit();
}

}  // namespace ris
