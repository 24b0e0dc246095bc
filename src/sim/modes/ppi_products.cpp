#include "ris/sim/ppi_products.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string_view>
#include <vector>

#include "ris/io/atomic_file.h"
#include "ris/io/compression_preset.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/io/raster_io.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_json.h"
#include "ris/sim/run_metadata.h"
#include "ris/util/concurrent_tasks.h"
#include "ris/util/units.h"

namespace ris {

nlohmann::json ppi_metadata(const Scene& scene, const PpiSimulation& sim, const PpiPictures& pic,
                            const SlarRunInfo& info) {
  return ppi_metadata(summarise_scene(scene), sim, pic, info);
}

nlohmann::json ppi_metadata(const SceneSummary& scene, const PpiSimulation& sim,
                            const PpiPictures& pic, const SlarRunInfo& info) {
  using nlohmann::json;
  const PpiGeometry& g = sim.geometry;
  const PpiScopeGrid& sg = sim.scope_grid;
  json out = run_header_json("ppi");
  out["inputs"] = run_inputs_json(scene, sim.radar, sim.categories, sim.category_names,
                                  sim.backscatter_description, info);
  out.update(
      json{{"derived",
            {{"radar", derived_to_json(sim.derived)},
             {"site",
              {{"x_m", g.site_x_m},
               {"y_m", g.site_y_m},
               {"terrain_height_m", g.site_ground_m},
               {"antenna_altitude_m", g.altitude_m}}},
             {"rays",
              {{"in_sector", g.scan_rays},
               {"padding_each_side", g.pad},
               {"spacing_deg", rad_to_deg(g.ray_spacing_rad)},
               {"first_ray_centre_deg", rad_to_deg(g.azimuth_rad(g.pad))},
               {"beamwidth_in_rays", sim.beam_rays},
               {"samples_per_ray", g.rays.samples},
               {"sample_step_m", g.rays.sample_step_m},
               {"shadow_samples", g.rays.shadow_samples},
               {"layover_samples", g.rays.layover_samples},
               {"back_facing_samples", g.rays.back_facing_samples}}},
             {"scope",
              {{"pixels", sg.size},
               {"pixel_m", sg.pixel_m},
               {"presentation",
                sg.presentation == PpiPresentation::slant ? "slant range" : "ground range"},
               {"range_rings_m", sim.radar.ppi.ring_spacing_m},
               {"resampling", "nearest ray and range bin"}}},
             {"targets", {{"seen", sim.point_returns.size()}, {"hidden", sim.hidden_targets}}},
             {"greytone",
              {{"reference_power_w", pic.reference_power_w},
               {"reference_greytone", pic.reference_greytone},
               {"greytones_per_decade", pic.greytones_per_decade}}}}},
           {"products",
            {{"ppi_scope.png", "greytones, scope centred on the radar, north up"},
             {"ppi_scope_power.tif", "float32 speckled power on the scope (W)"},
             {"ppi_scope_mask.tif", "uint8 scope mask: 1 shadow, 2 layover, 4 no data"},
             {"bscope.png", "greytones, rays (rows, clockwise from the scan start) x slant range"},
             {"mean_power_bscope.tif", "float32 mean power before speckle (W)"},
             {"speckled_power_bscope.tif", "float32 power after fading (W)"},
             {"mask_bscope.tif", "uint8 B-scope mask: 1 shadow, 2 layover, 4 no data"},
             {"metadata.json", "this file"}}}});
  out["products"] = selected_products(out["products"], info.products);
  return out;
}

const std::vector<std::string_view>& ppi_product_stems() {
  static const std::vector<std::string_view> stems = {
      "ppi_scope",         "ppi_scope_power",       "ppi_scope_mask", "bscope",
      "mean_power_bscope", "speckled_power_bscope", "mask_bscope"};
  return stems;
}

PpiProductSize ppi_product_size(const RadarParams& radar) {
  const RadarDerived d = derive(radar);
  const PpiParams& p = radar.ppi;
  // The B-scope (ppi_rays_layout's scan rays) and the scope (ppi_scope_grid
  // with no depth: its largest radius), in doubles (no overflow).
  PpiProductSize z;
  z.rays = std::max(1.0, std::round(p.scan_width_rad / p.ray_spacing_rad));
  z.bins = std::max(1, d.range_bins);
  const double far_m = d.near_slant_range_m + z.bins * d.range_bin_m;  // the B-scope's far end
  const double pixel_m = p.scope_pixel_m > 0.0 ? p.scope_pixel_m : d.range_bin_m;
  z.scope_pixels = 2.0 * std::max(1.0, std::ceil(far_m / pixel_m));
  const auto tiff = [](double cols, double rows, double bytes_per_pixel) {
    const double tiled = std::ceil(cols / 256.0) * 256.0 * std::ceil(rows / 256.0) * 256.0;
    const bool overviews = std::max(cols, rows) > double(kOverviewTilePixels);
    return tiled * bytes_per_pixel * (overviews ? 4.0 / 3.0 : 1.0);
  };
  // A PNG stored without compression: a filter byte a row, 5 bytes a 64 KiB
  // deflate block.
  const auto png = [](double cols, double rows) { return (cols + 1.0) * rows * 1.001 + 1024.0; };
  z.bscope_bytes = tiff(z.bins, z.rays, 9.0) + png(z.bins, z.rays) + tiff(z.bins, z.rays, 1.0);
  const double side = z.scope_pixels;
  z.scope_bytes = tiff(side, side, 5.0) + png(side, side) + tiff(side, side, 1.0);
  z.bytes =
      static_cast<std::int64_t>(std::min(z.bscope_bytes + z.scope_bytes + double(1 << 20), 0x1p62));
  return z;
}

PpiRasterSpecs ppi_raster_specs(const Scene& grid, const PpiSimulation& sim) {
  const SlarImage& b = sim.bscope;
  const PpiScopeGrid& sg = sim.scope_grid;
  PpiRasterSpecs s;
  s.bscope = {{"RIS_ROWS", "rays, clockwise from the scan start"},
              {"RIS_COLUMNS", "slant-range bins, near first"},
              {"RIS_NEAR_SLANT_RANGE_M", fmt::format("{:.6f}", b.range.near_m)},
              {"RIS_RANGE_BIN_M", fmt::format("{:.6f}", b.range.bin_m)},
              {"RIS_VERSION", RIS_VERSION}};
  // The ground presentation is a map: georeference it like the scene.
  const double half = 0.5 * sg.size * sg.pixel_m;
  s.georef = Georef{{sim.geometry.site_x_m - half, sg.pixel_m, 0.0, sim.geometry.site_y_m + half,
                     0.0, -sg.pixel_m},
                    grid.crs_wkt};
  s.scope_georeferenced = sg.presentation == PpiPresentation::ground;
  s.scope = {
      {"RIS_PRESENTATION", sg.presentation == PpiPresentation::slant ? "radius = slant range"
                                                                     : "radius = ground range"},
      {"RIS_PIXEL_M", fmt::format("{:.6f}", sg.pixel_m)},
      {"RIS_VERSION", RIS_VERSION}};
  return s;
}

void write_ppi_products(const std::filesystem::path& out_dir, const Scene& scene,
                        const PpiSimulation& sim, const PpiPictures& pic, const SlarRunInfo& info) {
  StagedDirectory dir(out_dir);
  const SlarImage& b = sim.bscope;
  const PpiScopeGrid& sg = sim.scope_grid;
  const int png_level = png_compression_level(info.compression);
  const GeoTiffCompression float_tif = product_tiff_settings(info, true);
  const GeoTiffCompression int_tif = product_tiff_settings(info, false);
  const PpiRasterSpecs specs = ppi_raster_specs(scene, sim);
  const RasterMetadata& bmeta = specs.bscope;
  const RasterMetadata& smeta = specs.scope;
  const Georef* scope_ref = specs.scope_georeferenced ? &specs.georef : nullptr;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // One task per file, run concurrently (each opens its own GDAL dataset).
  std::vector<std::function<void()>> tasks;
  const auto task = [&](std::string_view stem, std::function<void()> f) {
    if (info.products.wants(stem)) tasks.push_back(std::move(f));
  };
  task("ppi_scope", [&] {
    write_png_gray(dir.path("ppi_scope.png"), pic.scope_grey.data(), sg.size, sg.size, png_level);
  });
  task("bscope", [&] {
    write_png_gray(dir.path("bscope.png"), pic.bscope_grey.data(), b.bins, b.lines, png_level);
  });
  task("mean_power_bscope", [&] {
    std::vector<float> mean(b.mean_power_w.begin(), b.mean_power_w.end());
    for (std::size_t i = 0; i < mean.size(); ++i)
      if (b.mask[i] & pixel_flag::kNoData) mean[i] = std::numeric_limits<float>::quiet_NaN();
    write_geotiff<float>(dir.path("mean_power_bscope.tif"), mean.data(), b.bins, b.lines, nullptr,
                         nan, bmeta, "mean_power_w", BlockOrder::top_down, &float_tif);
  });
  task("speckled_power_bscope", [&] {
    write_geotiff<float>(dir.path("speckled_power_bscope.tif"), pic.speckled_power_w.data(), b.bins,
                         b.lines, nullptr, nan, bmeta, "speckled_power_w", BlockOrder::top_down,
                         &float_tif);
  });
  task("mask_bscope", [&] {
    write_geotiff<std::uint8_t>(dir.path("mask_bscope.tif"), b.mask.data(), b.bins, b.lines,
                                nullptr, std::nullopt, bmeta, "mask", BlockOrder::top_down,
                                &int_tif);
  });
  task("ppi_scope_power", [&] {
    write_geotiff<float>(dir.path("ppi_scope_power.tif"), pic.scope_power_w.data(), sg.size,
                         sg.size, scope_ref, nan, smeta, "speckled_power_w", BlockOrder::top_down,
                         &float_tif);
  });
  task("ppi_scope_mask", [&] {
    write_geotiff<std::uint8_t>(dir.path("ppi_scope_mask.tif"), pic.scope_mask.data(), sg.size,
                                sg.size, scope_ref, std::nullopt, smeta, "mask",
                                BlockOrder::top_down, &int_tif);
  });
  tasks.emplace_back([&] {
    write_text_file_atomic(dir.path("metadata.json"),
                           ppi_metadata(scene, sim, pic, info).dump(2) + "\n");
  });
  run_concurrently(tasks, info.threads);  // --threads bounds the writers too
  dir.commit();
}

}  // namespace ris
