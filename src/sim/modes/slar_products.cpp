#include "ris/sim/slar_products.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <type_traits>

#include "ris/image/geocode.h"
#include "ris/image/geocoded_grey.h"
#include "ris/image/radiometric_calibration.h"
#include "ris/image/shadow_map.h"
#include "ris/image/slant_georef.h"
#include "ris/io/atomic_file.h"
#include "ris/io/compression_preset.h"
#include "ris/io/raster_io.h"
#include "ris/scene/geo_frame.h"
#include "ris/sensor/radar_json.h"
#include "ris/sim/run_metadata.h"
#include "ris/sim/sar_coherent.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/util/concurrent_tasks.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

using nlohmann::json;

constexpr Backscatter kCalibratedBackscatter[] = {Backscatter::sigma0, Backscatter::beta0,
                                                  Backscatter::gamma0};

json track_json(const Track& t, const Scene& scene) {
  json j = {{"start_x_m", t.start_x_m},
            {"start_y_m", t.start_y_m},
            {"along_x", t.along_x},
            {"along_y", t.along_y},
            {"cross_x", t.cross_x},
            {"cross_y", t.cross_y},
            {"length_m", t.length_m},
            {"altitude_m", t.altitude_m},
            {"heading_deg", rad_to_deg(std::atan2(t.along_x, t.along_y))},
            {"look_side", t.look_side == LookSide::right ? "right" : "left"}};
  // The track's ends in latitude/longitude when the scene has a CRS
  // (ris/scene/geo_frame.h).
  if (!scene.crs_wkt.empty()) {
    try {
      const GeoFrame frame(scene.crs_wkt, "scene");
      const auto [lon0, lat0] = frame.lonlat_from_scene(t.start_x_m, t.start_y_m);
      const auto [x1, y1] = t.world_from_along_cross(t.length_m, 0.0);
      const auto [lon1, lat1] = frame.lonlat_from_scene(x1, y1);
      j["start_latlon"] = {lat0, lon0};
      j["end_latlon"] = {lat1, lon1};
      j["geographic_crs"] = frame.geographic_crs_name();
    } catch (const InputError&) {
      // A scene CRS that is not metric has no latitude/longitude to add.
    }
  }
  return j;
}

}  // namespace

SlarRasterSpec slar_raster_spec(const std::string& file, const SlarImage& img) {
  // Slant-range rasters carry no map georeferencing (their axes are azimuth
  // line and slant range); their geometry goes into the file's metadata.
  const auto slant_meta = [&img](const std::string& product, const std::string& units) {
    return RasterMetadata{{"RIS_PRODUCT", product},
                          {"RIS_UNITS", units},
                          {"RIS_ROWS", "azimuth lines, track start first"},
                          {"RIS_COLUMNS", "slant-range bins, near range first"},
                          {"RIS_NEAR_SLANT_RANGE_M", fmt::format("{:.6f}", img.range.near_m)},
                          {"RIS_RANGE_BIN_M", fmt::format("{:.6f}", img.range.bin_m)},
                          {"RIS_LINE_SPACING_M", fmt::format("{:.6f}", img.line_spacing_m)},
                          {"RIS_VERSION", RIS_VERSION}};
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (file == "mean_power_slant.tif")
    return {slant_meta("mean power before speckle", "W"), "mean_power_w", nan, false};
  if (file == "speckled_power_slant.tif")
    return {slant_meta("power after fading", "W"), "speckled_power_w", nan, false};
  for (const Backscatter b : kCalibratedBackscatter) {
    const std::string name(backscatter_name(b));
    for (const bool db : {false, true}) {
      if (file != calibrated_product_stem(b, db) + ".tif") continue;
      return {slant_meta(fmt::format("{}{} after fading, calibrated over the reference height",
                                     name, db ? " in dB" : ""),
                         db ? "dB" : "m^2/m^2"),
              db ? name + "_db" : name, nan, false};
    }
  }
  if (file == "mask_slant.tif")
    return {slant_meta("mask: 1 shadow, 2 layover, 4 no data", "bits"), "mask", std::nullopt,
            false};
  if (file == "scene_mask.tif") {
    return {{{"RIS_PRODUCT",
              "scene geometry mask: 1 shadow, 2 layover, 4 no data, 8 back-facing, 16 outside "
              "swath"},
             {"RIS_VERSION", RIS_VERSION}},
            "mask",
            std::nullopt,
            true};
  }
  if (file == "local_incidence_deg.tif") {
    return {{{"RIS_PRODUCT", "local incidence angle"},
             {"RIS_UNITS", "degrees"},
             {"RIS_VERSION", RIS_VERSION}},
            "local_incidence_deg",
            nan,
            true};
  }
  if (file == "geocoded_power.tif") {
    return {{{"RIS_PRODUCT", "power after fading, geocoded onto the scene grid (nearest pixel)"},
             {"RIS_UNITS", "W"},
             {"RIS_VERSION", RIS_VERSION}},
            "speckled_power_w",
            nan,
            true};
  }
  if (file == "slant_range.tif" || file == "ground_range.tif") {
    const bool slant = file == "slant_range.tif";
    RasterMetadata m =
        slant ? slant_meta("greytones, slant range", "greytone")
              : RasterMetadata{{"RIS_PRODUCT", "greytones, ground range over the reference height"},
                               {"RIS_ROWS", "azimuth lines, track start first"},
                               {"RIS_COLUMNS", "ground-range pixels, near range first"},
                               {"RIS_VERSION", RIS_VERSION}};
    return {m, "greytone", std::nullopt, false};
  }
  RIS_CHECK(file == "geocoded_grey.tif");
  return {{{"RIS_PRODUCT",
            "slant-range greytones geocoded onto the scene grid (nearest pixel); the mask "
            "band marks the cells with a pixel (0 is black, not no data)"},
           {"RIS_VERSION", RIS_VERSION}},
          "greytone",
          std::nullopt,
          true,
          true};
}

std::string picture_file(const std::string& stem, int cols, int rows, std::int64_t max_png_pixels) {
  return stem + (std::int64_t(cols) * rows <= max_png_pixels ? ".png" : ".tif");
}

BlockOrder scene_line_order(const Track& t) {
  // As fused_slar_applies: along y when |along_y| is 1 to 1e-9.
  if (std::abs(std::abs(t.along_y) - 1.0) < 1e-9)
    return t.along_y > 0.0 ? BlockOrder::bottom_up : BlockOrder::top_down;
  if (std::abs(std::abs(t.along_x) - 1.0) < 1e-9)
    return t.along_x > 0.0 ? BlockOrder::left_right : BlockOrder::right_left;
  return BlockOrder::top_down;
}

BlockOrder scene_maps_order(const Scene& grid, const SlarGeometry& layout) {
  return fused_slar_applies(grid, layout) ? scene_line_order(layout.track) : BlockOrder::top_down;
}

json slar_image_json(const SlarSimulation& sim) {
  const SlarImage& img = sim.image;
  return {{"lines", img.lines},
          {"range_bins", img.bins},
          {"near_slant_range_m", img.range.near_m},
          {"range_bin_m", img.range.bin_m},
          {"line_spacing_m", img.line_spacing_m},
          {"samples_in_swath", img.samples_in_swath},
          {"azimuth_footprint", sim.radar.mode == RadarMode::sar
                                    ? "SAR: constant, azimuth_looks * azimuth_resolution"
                                    : "w(R) = R * azimuth_beamwidth at the bin centre"},
          {"range_switch_applied", sim.range_corrected},
          {"area_switch_applied", sim.area_corrected}};
}

json greytone_json(const SlarPictures& pic) {
  return {{"reference_power_w", pic.reference_power_w},
          {"reference_greytone", pic.reference_greytone},
          {"greytones_per_decade", pic.greytones_per_decade},
          {"film_offset", pic.film_offset}};
}

json slar_metadata(const Scene& scene, const SlarSimulation& sim, const SlarPictures& pic,
                   const SlarRunInfo& info, const json& extra) {
  const SceneSummary sum = summarise_scene(scene);
  json out = slar_metadata(scene, sum.elevation_min_m, sum.elevation_max_m, sim, pic, info);
  out.update(extra);
  return out;
}

json slar_metadata(const Scene& scene, float h_min, float h_max, const SlarSimulation& sim,
                   const SlarPictures& pic, const SlarRunInfo& info) {
  const SlarGeometry& g = sim.geometry;
  const SlarImage& img = sim.image;
  const GroundRangeGrid& gr = sim.ground_grid;
  const auto [looks_min, looks_max] = std::minmax_element(pic.looks.begin(), pic.looks.end());
  json out = run_header_json(sim.radar.mode == RadarMode::sar ? "sar" : "slar");
  if (!sim.warnings.empty()) out["warnings"] = sim.warnings;
  if (sim.radar.mode == RadarMode::sar) {
    const bool coherent = sim.radar.sar.coherent;
    out["sar"] = {
        {"coherent", coherent},
        {"impulse_response",
         coherent ? fmt::format("sinc(0.886 x / rho), truncated at {} null spacings each side",
                                kSincSupportNulls)
                  : std::string("box of the multilooked resolution")},
        {"noise_power_w_first_last_bin",
         sim.noise_power_w.empty() ? json(nullptr)
                                   : json({sim.noise_power_w.front(), sim.noise_power_w.back()})}};
  }
  out["inputs"] = run_inputs_json({scene, h_min, h_max, g.nodata_cells}, sim.radar, sim.categories,
                                  sim.category_names, sim.backscatter_description, info);
  out.update(json{
      {"derived",
       {{"radar", derived_to_json(sim.derived)},
        {"track", track_json(sim.track, scene)},
        {"geometry",
         {{"sampling", g.direct_sampling ? "direct (track along a grid axis: one sample per cell)"
                                         : "bilinear (elevation and slope), nearest category"},
          {"slope", "central differences of the elevation (one-sided next to no data)"},
          {"lines", g.lines},
          {"samples_per_line", g.samples},
          {"line_spacing_m", g.line_spacing_m},
          {"sample_step_m", g.sample_step_m},
          {"first_sample_ground_range_m", g.first_sample_u_m},
          {"nodata_samples", g.nodata_samples},
          {"shadow_samples", g.shadow_samples},
          {"back_facing_samples", g.back_facing_samples},
          {"layover_samples", g.layover_samples}}},
        {"image", slar_image_json(sim)},
        {"ground_range",
         {{"reference_height_m", gr.reference_height_m},
          {"near_ground_range_m", gr.near_m},
          {"pixel_m", gr.spacing_m},
          {"pixels", gr.count}}},
        {"fading",
         {{"applied", sim.radar.switches.fading},
          {"law", sim.radar.fading == FadingLaw::exact_gamma ? "Gamma(N, 1/N)" : "equation 21"},
          {"independent_samples_min", pic.looks.empty() ? 0.0 : *looks_min},
          {"independent_samples_max", pic.looks.empty() ? 0.0 : *looks_max}}},
        {"greytone", greytone_json(pic)}}},
      {"products",
       {{picture_file("slant_range", img.bins, img.lines, info.max_png_pixels),
         "greytones, slant range: rows azimuth lines (track start first), "
         "columns range bins (near first)"},
        {picture_file("ground_range", gr.count, img.lines, info.max_png_pixels),
         "greytones, ground range over the reference height"},
        {"mean_power_slant.tif", "float32 mean received power (W) before speckle, slant range"},
        {"speckled_power_slant.tif", "float32 received power (W) after fading, slant range"},
        {"mask_slant.tif", "uint8 slant-range mask: 1 shadow, 2 layover, 4 no data"},
        {"scene_mask.tif",
         "uint8 on the scene grid: 1 shadow, 2 layover, 4 no data, "
         "8 back-facing, 16 outside swath"},
        {"local_incidence_deg.tif", "float32 local incidence angle (degrees) on the scene grid"},
        {"geocoded_power.tif",
         "float32 power after fading on the scene grid (map geometry, scene CRS), NaN where no "
         "pixel"},
        {"geocoded_grey.tif",
         "uint8 greytones on the scene grid (map geometry, scene CRS); its mask band marks the "
         "cells with a pixel"},
        {"geocoded_grey.png",
         "the same greytones as a picture (no georeferencing; cells without a pixel black)"},
        {"shadowmap.txt", "the seed's shadow map: 9 no data, 0 shadow, 1-8 count, # more"},
        {"metadata.json", "this file"}}}});
  if (picture_file("geocoded_grey", scene.cols, scene.rows, info.max_png_pixels) !=
      "geocoded_grey.png")
    out["products"].erase("geocoded_grey.png");  // too large for a PNG: the .tif alone
  add_calibrated_descriptions(out["products"], sim, info);
  out["products"] = selected_products(out["products"], info.products);
  return out;
}

std::string calibrated_product_stem(Backscatter b, bool decibels) {
  return std::string(backscatter_name(b)) + (decibels ? "_slant_db" : "_slant");
}

const std::vector<std::string_view>& slar_product_stems() {
  static const std::vector<std::string_view> stems = {
      "slant_range",   "ground_range",   "mean_power_slant",    "speckled_power_slant",
      "mask_slant",    "scene_mask",     "local_incidence_deg", "geocoded_power",
      "geocoded_grey", "shadowmap",      "sigma0_slant",        "sigma0_slant_db",
      "beta0_slant",   "beta0_slant_db", "gamma0_slant",        "gamma0_slant_db"};
  return stems;
}

bool names_calibrated(const ProductSelection& selection) {
  for (const Backscatter b : kCalibratedBackscatter) {
    for (const bool db : {false, true}) {
      const std::string stem = calibrated_product_stem(b, db);
      if (std::find(selection.stems.begin(), selection.stems.end(), stem) != selection.stems.end())
        return true;
    }
  }
  return false;
}

void add_calibrated_descriptions(json& products, const SlarSimulation& sim,
                                 const SlarRunInfo& info) {
  for (const Backscatter b : kCalibratedBackscatter) {
    for (const bool db : {false, true}) {
      const std::string stem = calibrated_product_stem(b, db);
      if (!wants_calibrated(info, stem)) continue;
      products[stem + ".tif"] = fmt::format(
          "float32 {}{} of the power after fading, slant range, calibrated over the reference "
          "height {:.1f} m (docs/outputs.md, \"Calibrated products\"); NaN where no data{}",
          backscatter_name(b), db ? " in dB" : "", sim.calibration.reference_height_m,
          db ? " or zero power" : "");
    }
  }
}

void add_calibrated_tasks(std::vector<std::function<void()>>& tasks, const SlarSimulation& sim,
                          const SlarPictures& pic, const SlarRunInfo& info,
                          const std::function<void(const std::string&, const float*)>& write) {
  for (const Backscatter b : kCalibratedBackscatter) {
    for (const bool db : {false, true}) {
      const std::string stem = calibrated_product_stem(b, db);
      if (!wants_calibrated(info, stem)) continue;
      RIS_CHECK(!sim.calibration.empty());  // refused before the run (run.cpp)
      tasks.emplace_back([&sim, &pic, write, b, db, stem] {
        std::vector<float> v(pic.speckled_power_w.size());
        calibrate_slant_image(pic.speckled_power_w, sim.image.bins, sim.calibration, b, db, v);
        write(stem + ".tif", v.data());
      });
    }
  }
}

bool wants_calibrated(const SlarRunInfo& info, std::string_view stem) {
  if (info.calibrated) return info.products.wants(stem);
  const std::vector<std::string>& named = info.products.stems;
  return std::find(named.begin(), named.end(), stem) != named.end();
}

void write_slar_products(const std::filesystem::path& out_dir, const Scene& scene,
                         const SlarSimulation& sim, const SlarPictures& pic,
                         const SlarRunInfo& info, const json& extra_metadata) {
  StagedDirectory dir(out_dir);
  const SlarImage& img = sim.image;
  const ProductSelection& want = info.products;
  const int png_level = png_compression_level(info.compression);
  const GeoTiffCompression float_tif = product_tiff_settings(info, true);
  const GeoTiffCompression int_tif = product_tiff_settings(info, false);
  // One task per file, run concurrently (each opens its own GDAL dataset),
  // the largest first; every file is complete before the folder commits.
  std::vector<std::function<void()>> tasks;
  // The slant-range rasters' GCPs (ris/image/slant_georef.h).
  const Georef slant_gcps = slant_georef(scene, sim.track, img);
  // The pictures: PNG, or a tiled GeoTIFF when too large for one.
  const auto picture = [&](const std::string& stem, const std::uint8_t* grey, int cols, int rows) {
    if (!want.wants(stem)) return;
    tasks.emplace_back([&, stem, grey, cols, rows] {
      const std::string file = picture_file(stem, cols, rows, info.max_png_pixels);
      if (file.ends_with(".png")) {
        write_png_gray(dir.path(file), grey, cols, rows, png_level);
      } else {
        const SlarRasterSpec spec = slar_raster_spec(file, img);
        write_geotiff(dir.path(file), grey, cols, rows,
                      file == "slant_range.tif" ? &slant_gcps : nullptr, spec.nodata, spec.metadata,
                      spec.band, BlockOrder::top_down, &int_tif);
      }
    });
  };
  const Georef georef{scene.geotransform(), scene.crs_wkt};
  const auto write = [&](const std::string& file, const auto* data, int cols, int rows,
                         BlockOrder order = BlockOrder::top_down) {
    const SlarRasterSpec spec = slar_raster_spec(file, img);
    using T = std::remove_cvref_t<decltype(*data)>;
    write_geotiff(dir.path(file), data, cols, rows, spec.georeferenced ? &georef : &slant_gcps,
                  spec.nodata, spec.metadata, spec.band, order,
                  std::is_floating_point_v<T> ? &float_tif : &int_tif);
  };
  const auto task = [&](const std::string& stem, std::function<void()> f) {
    if (want.wants(stem)) tasks.push_back(std::move(f));
  };
  // The scene-grid products first (the scene is usually the largest grid).
  const GeocodeResampling resampling = info.geocode_resampling;
  task("geocoded_power", [&] {
    write("geocoded_power.tif",
          geocode_slant_image(scene, sim.track, img, pic.speckled_power_w, resampling).data(),
          scene.cols, scene.rows);
  });
  task("geocoded_grey", [&] {
    // Its mask band: the cells whose power has data (ris/image/geocoded_grey.h).
    const GeocodedGrey g =
        geocoded_grey(scene, sim.track, img, pic.slant_grey, pic.speckled_power_w, resampling);
    const SlarRasterSpec spec = slar_raster_spec("geocoded_grey.tif", img);
    write_geotiff_masked(dir.path("geocoded_grey.tif"), g.grey.data(), g.valid.data(), scene.cols,
                         scene.rows, &georef, spec.metadata, spec.band, &int_tif);
    if (picture_file("geocoded_grey", scene.cols, scene.rows, info.max_png_pixels) ==
        "geocoded_grey.png")
      write_png_gray(dir.path("geocoded_grey.png"), g.grey.data(), scene.cols, scene.rows,
                     png_level);
  });
  // Scene-grid maps in the order a streamed run computes them (line by line).
  const BlockOrder line_order = scene_maps_order(scene, sim.geometry);
  task("local_incidence_deg", [&] {
    write("local_incidence_deg.tif", sim.scene_maps.local_incidence_deg.data(), scene.cols,
          scene.rows, line_order);
  });
  task("scene_mask", [&] {
    write("scene_mask.tif", sim.scene_maps.mask.data(), scene.cols, scene.rows, line_order);
  });
  task("mean_power_slant", [&] {
    // No-data pixels are NaN in the power rasters (the files' no-data value).
    std::vector<float> mean(img.mean_power_w.begin(), img.mean_power_w.end());
    for (std::size_t i = 0; i < mean.size(); ++i)
      if (img.mask[i] & pixel_flag::kNoData) mean[i] = std::numeric_limits<float>::quiet_NaN();
    write("mean_power_slant.tif", mean.data(), img.bins, img.lines);
  });
  task("speckled_power_slant", [&] {
    write("speckled_power_slant.tif", pic.speckled_power_w.data(), img.bins, img.lines);
  });
  add_calibrated_tasks(tasks, sim, pic, info, [&](const std::string& file, const float* v) {
    write(file, v, img.bins, img.lines);
  });
  picture("slant_range", pic.slant_grey.data(), img.bins, img.lines);
  picture("ground_range", pic.ground_grey.data(), sim.ground_grid.count, img.lines);
  task("mask_slant", [&] { write("mask_slant.tif", img.mask.data(), img.bins, img.lines); });
  task("shadowmap",
       [&] { write_text_file_atomic(dir.path("shadowmap.txt"), shadow_map_text(img)); });
  tasks.emplace_back([&] {
    write_text_file_atomic(dir.path("metadata.json"),
                           slar_metadata(scene, sim, pic, info, extra_metadata).dump(2) + "\n");
  });
  run_concurrently(tasks, info.threads);  // --threads bounds the writers too
  dir.commit();
}

}  // namespace ris
