#include "ris/sim/slar_stream.h"

#include <fmt/format.h>
#include <gdal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <limits>
#include <tuple>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/geocode.h"
#include "ris/image/greytone.h"
#include "ris/image/ground_range.h"
#include "ris/image/shadow_map.h"
#include "ris/image/slar_azimuth_integrator.h"
#include "ris/image/speckle.h"
#include "ris/image/thermal_noise.h"
#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/scene/scene_stream.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/util/error.h"
#include "ris/util/progress.h"
#include "ris/util/rank_select.h"

namespace ris {

namespace {

constexpr std::int64_t kGdalCacheBytes = std::int64_t(256) << 20;
constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

// Reads rows [row0, row0 + rows) x all columns of band 1 of an open raster.
template <typename T>
void read_rows(GDALDatasetH ds, int row0, int rows, T* out, GDALDataType type,
               const std::string& path) {
  const int cols = GDALGetRasterXSize(ds);
  if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, row0, cols, rows, out, cols, rows, type, 0,
                   0) != CE_None) {
    throw InputError(path, "", "cannot read back: " + last_gdal_error());
  }
}

// A window of band 1: rows [row0, row0 + rows) x columns [col0, col0 + cols).
template <typename T>
void read_window(GDALDatasetH ds, int row0, int rows, int col0, int cols, T* out, GDALDataType type,
                 const std::string& path) {
  if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, col0, row0, cols, rows, out, cols, rows, type,
                   0, 0) != CE_None) {
    throw InputError(path, "", "cannot read back: " + last_gdal_error());
  }
}

// Pass 0: what simulate_slar learns from the whole scene before it starts.
struct SceneSummary {
  std::int64_t valid_cells = 0;
  std::int64_t nodata_cells = 0;
  std::vector<std::uint16_t> categories;  // of the cells with data, sorted
  float h_min = std::numeric_limits<float>::infinity();
  float h_max = -std::numeric_limits<float>::infinity();
  int max_row = -1, max_col = -1;  // the first highest cell with data
  FloatRankSelect elevation;       // pass 1 of the median elevation
};

SceneSummary summarise_scene(const SceneStreamReader& in, int block_rows, ProgressBar& bar) {
  const Scene& g = in.grid();
  SceneSummary s;
  std::vector<std::uint8_t> seen(65536, 0);
  const std::size_t cap = sz(block_rows) * sz(g.cols);
  std::vector<float> z(cap);
  std::vector<std::uint16_t> cat(cap);
  std::vector<std::uint8_t> ok(cap);
  for (int r0 = 0; r0 < g.rows; r0 += block_rows) {
    const int n = std::min(block_rows, g.rows - r0);
    in.read(r0, n, 0, g.cols, z.data(), cat.data(), ok.data());
    const std::size_t cells = sz(n) * sz(g.cols);
    for (std::size_t i = 0; i < cells; ++i) {
      if (!ok[i]) {
        ++s.nodata_cells;
        continue;
      }
      ++s.valid_cells;
      seen[cat[i]] = 1;
      const float h = z[i];
      if (h < s.h_min) s.h_min = h;
      if (h > s.h_max) {
        s.h_max = h;
        s.max_row = r0 + static_cast<int>(i / sz(g.cols));
        s.max_col = static_cast<int>(i % sz(g.cols));
      }
      if (std::isfinite(h)) s.elevation.count(h);
    }
    bar.advance(static_cast<std::int64_t>(cells));
  }
  for (std::size_t c = 0; c < seen.size(); ++c)
    if (seen[c]) s.categories.push_back(static_cast<std::uint16_t>(c));
  return s;
}

// Exact median of the values counted in pass 1 and refined in pass 2: the
// upper median (nth_element at n / 2) or, with both_middles, the mean of the
// two middle values for an even count (median_valid_power_w).
std::vector<std::uint64_t> median_ranks(std::uint64_t n, bool both_middles) {
  if (both_middles && n % 2 == 0) return {n / 2 - 1, n / 2};
  return {n / 2};
}

double median_value(const FloatRankSelect& sel, std::uint64_t n, bool both_middles) {
  const double upper = sel.value(both_middles && n % 2 == 0 ? 1 : 0);
  if (!(both_middles && n % 2 == 0)) return upper;
  const double lower = sel.value(0);
  return 0.5 * (lower + upper);
}

// Whether the track runs along y (lines are cell rows), as fused_slar_applies.
bool along_y_axis(const Track& t) {
  return std::abs(std::abs(t.along_y) - 1.0) < 1e-9;
}

// A pixel counted by the auto greytone reference (ris/image/greytone.h).
inline bool valid_power(float p, std::uint8_t mask) {
  return std::isfinite(p) && p > 0.0f && !(mask & pixel_flag::kNoData);
}

}  // namespace

bool scene_needs_streaming(std::int64_t rows, std::int64_t cols) {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  const double physical = (pages > 0 && page_size > 0) ? double(pages) * double(page_size) : 8e9;
  // An in-memory run holds the scene (7 bytes a cell), its scene-grid maps
  // (5), the geocoded products and their copies while writing: its peak RSS
  // was 27.6 bytes a cell on an 8,000^2 scene (docs/performance.md).
  constexpr double kInMemoryBytesPerCell = 28.0;
  return double(rows) * double(cols) * kInMemoryBytesPerCell > physical / 2.0;
}

SlarStreamSummary simulate_slar_streamed(const std::filesystem::path& scene_path,
                                         const RadarParams& radar_in, const Sigma0Source& sigma0,
                                         const SlarRunInfo& info,
                                         const std::filesystem::path& out_dir,
                                         const SlarStreamOptions& options) {
  bound_gdal_cache(kGdalCacheBytes);
  const SceneStreamReader in(scene_path);
  SlarStreamSummary summary;
  summary.grid = in.grid();
  const Scene& grid = summary.grid;
  SlarSimulation& sim = summary.sim;
  sim.radar = radar_in;
  RadarParams& radar = sim.radar;
  sim.derived = derive(radar);
  const std::string backscatter_file =
      info.backscatter_path.empty() ? sigma0.description() : info.backscatter_path;

  // What the stream runs: SLAR along a grid axis (the fused engine).
  if (!(radar.mode == RadarMode::slar || (radar.mode == RadarMode::sar && !radar.sar.coherent))) {
    throw InputError(radar.source_file, "mode",
                     "a streamed run simulates SLAR and the incoherent SAR; the coherent SAR and "
                     "PPI need the scene in memory (run without --stream on a scene that fits)");
  }
  sim.track = resolve_track(radar.track, grid, radar.source_file);
  const SlarGeometry layout = slar_geometry_layout(grid, sim.track, radar.azimuth_line_spacing_m);
  if (!fused_slar_applies(grid, layout)) {
    throw InputError(radar.source_file, "track",
                     "a streamed run needs a track along a grid axis (heading 0, 90, 180 or "
                     "270 deg) with one azimuth line per cell row or column (azimuth line "
                     "spacing = the cell size); oblique tracks need the scene in memory");
  }

  const std::int64_t cells = std::int64_t(grid.rows) * grid.cols;
  std::chrono::steady_clock::time_point mark;
  ProgressBar bar("simulate (streamed)", 3 * cells, "cells", options.quiet);

  // Pass 0: scene statistics.
  const int cross_cells = along_y_axis(sim.track) ? grid.cols : grid.rows;
  const int lines = layout.lines;
  const int bins = sim.derived.range_bins;
  const std::int64_t per_line =
      std::int64_t(cross_cells) * 18 + std::int64_t(std::max(bins, 1)) * 72;
  const int block_lines =
      options.block_lines > 0
          ? std::min(options.block_lines, lines)
          : static_cast<int>(std::clamp<std::int64_t>(options.memory_budget_bytes / per_line, 16,
                                                      std::max(lines, 16)));
  summary.block_lines = std::min(block_lines, lines);
  // Scene rows read at a time by the passes over whole rows.
  const int scene_block_rows = std::min(grid.rows, std::max(in.block_rows(), 256));
  const auto stage = [&](const std::string& name) {
    summary.stage_seconds.emplace_back(name, 0.0);
    bar.set_stage(name);
    mark = std::chrono::steady_clock::now();
  };
  const auto stage_done = [&] {
    summary.stage_seconds.back().second =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - mark).count();
  };
  stage("scene statistics");
  SceneSummary ss = summarise_scene(in, scene_block_rows, bar);
  stage_done();
  if (ss.valid_cells == 0) throw InputError("scene", "", "the scene has no cell with data");
  check_terrain_below_sensor(ss.h_max, ss.max_row, ss.max_col, sim.track.altitude_m,
                             radar.source_file);
  sim.geometry = layout;
  SlarGeometry& g = sim.geometry;

  // sigma0 for every category the scene uses, as simulate_slar.
  RadiometrySetup rs =
      prepare_radiometry(ss.categories, radar, sim.derived, sigma0, backscatter_file);
  sim.categories = rs.categories;
  sim.category_names = rs.category_names;
  sim.backscatter_description = rs.backscatter_description;
  SlarImagingParams& imaging = rs.imaging;
  // SAR: its windows, warnings and thermal noise, as simulate_slar.
  set_sar_windows(radar, layout.line_spacing_m, imaging);
  sim.warnings = sar_resolution_warnings(grid, layout, radar);
  sim.noise_power_w = sar_noise_power_w(radar, imaging, layout.altitude_m);
  RIS_CHECK(imaging.range.count == bins && bins > 0);
  const std::uint64_t n_elev = ss.elevation.total();
  ss.elevation.select(median_ranks(n_elev, false));

  // The image's layout (for the products' metadata and geocoding).
  SlarImage& img = sim.image;
  img.lines = lines;
  img.bins = bins;
  img.range = imaging.range;
  img.line_spacing_m = g.line_spacing_m;

  StagedDirectory dir(out_dir);
  const Georef georef{grid.geotransform(), grid.crs_wkt};
  const auto open_writer = [&](const std::string& file, int cols, int rows, auto sample,
                               BlockOrder order = BlockOrder::top_down) {
    using T = decltype(sample);
    const SlarRasterSpec spec = slar_raster_spec(file, img);
    return std::make_unique<GeoTiffBlockWriter<T>>(
        dir.path(file), cols, rows, std::vector<std::string>{spec.band},
        spec.georeferenced ? &georef : nullptr, spec.nodata, spec.metadata, GeoTiffCompression{},
        order);
  };

  // ---- Pass 1: lines in blocks ------------------------------------------
  {
    const SlarLineEngine engine(grid, layout, rs.lut, imaging, radar.source_file);
    SlarAzimuthIntegrator az(imaging, g.line_spacing_m, lines, bins);
    const bool cross_is_x = along_y_axis(sim.track);
    const BlockOrder line_order = scene_line_order(sim.track);
    auto mean_out = open_writer("mean_power_slant.tif", bins, lines, float{});
    auto speckled_out = open_writer("speckled_power_slant.tif", bins, lines, float{});
    auto mask_out = open_writer("mask_slant.tif", bins, lines, std::uint8_t{});
    auto scene_mask_out =
        open_writer("scene_mask.tif", grid.cols, grid.rows, std::uint8_t{}, line_order);
    auto incidence_out =
        open_writer("local_incidence_deg.tif", grid.cols, grid.rows, float{}, line_order);
    std::ofstream shadow_text(dir.path("shadowmap.txt"), std::ios::binary);
    if (!shadow_text) throw InputError(dir.path("shadowmap.txt").string(), "", "cannot write");

    // N per range bin, as make_greytone_image.
    std::vector<double> looks(sz(bins));
    for (int k = 0; k < bins; ++k)
      looks[sz(k)] = independent_samples(radar, imaging.range.centre_m(k));

    const std::size_t win_cap = sz(summary.block_lines + 2) * sz(cross_cells);
    std::vector<float> z(win_cap), incidence(win_cap);
    std::vector<std::uint16_t> cat(win_cap);
    std::vector<std::uint8_t> ok(win_cap), scene_mask(win_cap);
    SlarLineProfiles prof;
    SlarLineCounts counts;
    std::int64_t samples_in_swath = 0;
    FloatRankSelect power;  // pass 1 of the median mean power
    std::vector<float> mean, area, speckled;
    std::vector<std::uint8_t> mask;
    std::string text;

    // The image lines the integrator has ready: switch corrections, NaN for
    // no data, fading, written out (render_slar + write_slar_products).
    const auto emit_ready = [&] {
      const int n = az.lines_ready();
      if (n == 0) return;
      const int k0 = az.lines_emitted();
      const std::size_t np = sz(n) * sz(bins);
      SlarImage block;
      block.lines = n;
      block.bins = bins;
      block.range = imaging.range;
      block.mean_power_w.resize(np);
      block.area_m2.resize(np);
      mask.resize(np);
      az.emit(n, block.mean_power_w.data(), block.area_m2.data(), mask.data());
      std::tie(sim.range_corrected, sim.area_corrected) = apply_switch_corrections(block, rs.terms);
      if (!sim.noise_power_w.empty()) add_noise_power(block, sim.noise_power_w);
      mean.assign(block.mean_power_w.begin(), block.mean_power_w.end());
      for (std::size_t i = 0; i < np; ++i) {
        if (valid_power(mean[i], mask[i])) power.count(mean[i]);
        if (mask[i] & pixel_flag::kNoData) mean[i] = kNaNf;
      }
      speckled = mean;
      if (radar.switches.fading)
        apply_fading(speckled, n, bins, looks, radar.fading, info.seed, k0);
      mean_out->write(mean.data(), n);
      speckled_out->write(speckled.data(), n);
      mask_out->write(mask.data(), n);
    };

    stage("geometry, image formation, scene maps, fading (pass 1)");
    for (int l0 = 0; l0 < lines; l0 += summary.block_lines) {
      const int l1 = std::min(lines, l0 + summary.block_lines);
      int row0 = 0, rows = 0, col0 = 0, cols = 0;
      engine.window_for_lines(l0, l1, row0, rows, col0, cols);
      in.read(row0, rows, col0, cols, z.data(), cat.data(), ok.data());
      const SceneWindow win{row0, col0, rows, cols, z.data(), cat.data(), ok.data()};
      const SceneMapsWindow maps{row0, col0, rows, cols, scene_mask.data(), incidence.data()};
      prof.allocate(l1 - l0, bins, l0);
      engine.run(l0, l1, win, prof, maps, counts);
      samples_in_swath += prof.samples_in_swath;

      // The block's own cells (its lines' rows or columns, without the halo):
      // scene-grid maps out, the median elevation's second pass.
      const int c_a = engine.cell_of_line(l0), c_b = engine.cell_of_line(l1 - 1);
      RIS_CHECK(c_a >= 0 && c_b >= 0 && std::abs(c_b - c_a) == l1 - l0 - 1);
      const int lo = std::min(c_a, c_b), count = l1 - l0;
      if (cross_is_x) {
        const std::size_t at = sz(lo - row0) * sz(cols);
        scene_mask_out->write(scene_mask.data() + at, count);
        incidence_out->write(incidence.data() + at, count);
        for (std::size_t i = at; i < at + sz(count) * sz(cols); ++i)
          if (ok[i] && std::isfinite(z[i])) ss.elevation.refine(z[i]);
      } else {
        const std::size_t at = sz(lo - col0);
        scene_mask_out->write(scene_mask.data() + at, count, sz(cols));
        incidence_out->write(incidence.data() + at, count, sz(cols));
        for (int r = 0; r < rows; ++r) {
          for (int c = lo; c < lo + count; ++c) {
            const std::size_t i = sz(r) * sz(cols) + sz(c - col0);
            if (ok[i] && std::isfinite(z[i])) ss.elevation.refine(z[i]);
          }
        }
      }

      // The seed's shadow map, line by line (ris/image/shadow_map.h).
      text.clear();
      for (int line = l0; line < l1; ++line) {
        for (int b = 0; b < bins; ++b) {
          const std::size_t i = prof.index(line, b);
          text.push_back(shadow_map_char(prof.mapped_count[i], prof.visible_count[i]));
        }
        text.push_back('\n');
      }
      shadow_text.write(text.data(), static_cast<std::streamsize>(text.size()));

      az.push(prof, l1 - l0);
      emit_ready();
      bar.advance(std::int64_t(l1 - l0) * cross_cells);
      ++summary.blocks;
    }
    RIS_CHECK(az.lines_emitted() == lines);

    g.nodata_samples = counts.nodata;
    g.shadow_samples = counts.shadow;
    g.back_facing_samples = counts.back_facing;
    g.layover_samples = counts.layover;
    g.nodata_cells = ss.nodata_cells;
    img.samples_in_swath = samples_in_swath;
    if (img.samples_in_swath == 0) {
      // As form_slar_image_fused.
      throw InputError(
          radar.source_file, "sweep_delay",
          fmt::format("the swath (slant range {:.1f} to {:.1f} m) misses the "
                      "scene, which spans slant range {:.1f} to {:.1f} m; expected "
                      "a sweep delay and length (or near range and range bins) "
                      "that overlap it",
                      imaging.range.near_m, imaging.range.far_m(), counts.r_min_m, counts.r_max_m));
    }
    mean_out->close();
    speckled_out->close();
    mask_out->close();
    scene_mask_out->close();
    incidence_out->close();
    shadow_text.close();
    if (!shadow_text) throw InputError(dir.path("shadowmap.txt").string(), "", "write failed");
    stage_done();

    // ---- Pass 1b: the median mean power (auto greytone reference) -------
    double median_power = std::numeric_limits<double>::quiet_NaN();
    const std::uint64_t n_power = power.total();
    if (radar.reference.automatic && n_power > 0) {
      stage("median mean power (pass 1b)");
      power.select(median_ranks(n_power, true));
      GdalDataset mean_ds = open_raster(dir.path("mean_power_slant.tif").string());
      GdalDataset mask_ds = open_raster(dir.path("mask_slant.tif").string());
      for (int k0 = 0; k0 < lines; k0 += summary.block_lines) {
        const int n = std::min(summary.block_lines, lines - k0);
        const std::size_t np = sz(n) * sz(bins);
        mean.resize(np);
        mask.resize(np);
        read_rows(handle(mean_ds), k0, n, mean.data(), GDT_Float32, "mean_power_slant.tif");
        read_rows(handle(mask_ds), k0, n, mask.data(), GDT_Byte, "mask_slant.tif");
        for (std::size_t i = 0; i < np; ++i)
          if (valid_power(mean[i], mask[i])) power.refine(mean[i]);
      }
      median_power = median_value(power, n_power, true);
      stage_done();
    }
    // (make_greytone_image's map and N per bin, for the metadata.)
    const GreytoneMap map = make_greytone_map_for_median(radar, median_power);
    SlarPictures pic_meta;
    pic_meta.seed = info.seed;
    pic_meta.looks = looks;
    pic_meta.reference_power_w = map.reference_power_w();
    pic_meta.reference_greytone = map.reference_greytone();
    pic_meta.greytones_per_decade = map.greytones_per_decade();
    pic_meta.film_offset = map.film_offset();

    // The ground-range grid over the median elevation (simulate_slar).
    const double h_ref = options.reference_height_m
                             ? *options.reference_height_m
                             : (n_elev > 0 ? double(ss.elevation.value(0)) : 0.0);
    sim.ground_grid = ground_range_grid(img.range, g.altitude_m, h_ref, img.line_spacing_m);
    const GroundRangeGrid& gg = sim.ground_grid;

    // ---- Pass 2: greytones, ground range, PNGs ----------------------------
    stage("greytones, ground range, PNGs (pass 2)");
    {
      GdalDataset sp_ds = open_raster(dir.path("speckled_power_slant.tif").string());
      GdalDataset mask_ds = open_raster(dir.path("mask_slant.tif").string());
      // The pictures: a tiled GeoTIFF when too large for a PNG
      // (picture_file), else through a tiled temporary in the staging folder
      // (removed before it is committed), then to PNG row by row.
      const std::string slant_file = picture_file("slant_range", bins, lines, info.max_png_pixels);
      const std::string ground_file =
          picture_file("ground_range", gg.count, lines, info.max_png_pixels);
      const auto picture_path = [&](const std::string& file) {
        return file.ends_with(".png") ? dir.path("." + file + ".tmp.tif") : dir.path(file);
      };
      {
        const auto open_picture = [&](const std::string& file, int cols) {
          const SlarRasterSpec spec =
              file.ends_with(".png") ? SlarRasterSpec{} : slar_raster_spec(file, img);
          return std::make_unique<GeoTiffBlockWriter<std::uint8_t>>(
              picture_path(file), cols, lines, std::vector<std::string>{spec.band}, nullptr,
              spec.nodata, spec.metadata);
        };
        auto slant_grey_out = open_picture(slant_file, bins);
        auto ground_grey_out = open_picture(ground_file, gg.count);
        std::vector<std::uint8_t> no_data, grey, ground_no_data, ground_grey;
        for (int k0 = 0; k0 < lines; k0 += summary.block_lines) {
          const int n = std::min(summary.block_lines, lines - k0);
          const std::size_t np = sz(n) * sz(bins);
          speckled.resize(np);
          mask.resize(np);
          read_rows(handle(sp_ds), k0, n, speckled.data(), GDT_Float32, "speckled_power_slant.tif");
          read_rows(handle(mask_ds), k0, n, mask.data(), GDT_Byte, "mask_slant.tif");
          no_data.resize(np);
          for (std::size_t i = 0; i < np; ++i) no_data[i] = (mask[i] & pixel_flag::kNoData) ? 1 : 0;
          grey.resize(np);
          greytones(speckled, grey, map, no_data);
          slant_grey_out->write(grey.data(), n);
          // Ground range (render_slar).
          const std::vector<float> ground_power = to_ground_range(speckled, n, img.range, gg);
          const std::vector<std::uint8_t> ground_mask =
              to_ground_range_nearest(mask, n, img.range, gg, pixel_flag::kNoData);
          ground_no_data.resize(ground_mask.size());
          for (std::size_t i = 0; i < ground_mask.size(); ++i)
            ground_no_data[i] = (ground_mask[i] & pixel_flag::kNoData) ? 1 : 0;
          ground_grey.resize(ground_power.size());
          greytones(ground_power, ground_grey, map, ground_no_data);
          ground_grey_out->write(ground_grey.data(), n);
          bar.advance(0);
        }
        slant_grey_out->close();
        ground_grey_out->close();
      }
      for (const std::string& file : {slant_file, ground_file}) {
        if (!file.ends_with(".png")) continue;
        write_png_gray_from_raster(dir.path(file), picture_path(file));
        std::filesystem::remove(picture_path(file));
      }
      stage_done();

      // ---- Pass 2b: geocoded products, scene rows top down ---------------
      stage("geocoded products (pass 2b)");
      auto power_out = open_writer("geocoded_power.tif", grid.cols, grid.rows, float{});
      auto grey_out = open_writer("geocoded_grey.tif", grid.cols, grid.rows, std::uint8_t{});
      // Free pass 1's window, read scene rows a tile row at a time.
      std::vector<float>().swap(incidence);
      std::vector<std::uint8_t>().swap(scene_mask);
      const int block_rows = scene_block_rows;
      const std::size_t cap = sz(block_rows) * sz(grid.cols);
      z.resize(std::max(z.size(), cap));
      cat.resize(z.size());
      ok.resize(z.size());
      std::vector<std::int32_t> pix_line(cap), pix_bin(cap);
      std::vector<float> out_power(cap);
      std::vector<std::uint8_t> out_grey(cap), no_data, grey;
      for (int r0 = 0; r0 < grid.rows; r0 += block_rows) {
        const int n = std::min(block_rows, grid.rows - r0);
        const std::size_t nc = sz(n) * sz(grid.cols);
        in.read(r0, n, 0, grid.cols, z.data(), cat.data(), ok.data());
        // Each cell's pixel, and the window of the image they need.
        int l_lo = lines, l_hi = -1, b_lo = bins, b_hi = -1;
        for (int r = r0; r < r0 + n; ++r) {
          for (int c = 0; c < grid.cols; ++c) {
            const std::size_t i = sz(r - r0) * sz(grid.cols) + sz(c);
            int line = -1, bin = -1;
            if (!(ok[i] && geocode_pixel(grid, sim.track, img, r, c, z[i], line, bin))) {
              line = -1;
            } else {
              l_lo = std::min(l_lo, line);
              l_hi = std::max(l_hi, line);
              b_lo = std::min(b_lo, bin);
              b_hi = std::max(b_hi, bin);
            }
            pix_line[i] = line;
            pix_bin[i] = bin;
          }
        }
        std::fill(out_power.begin(), out_power.begin() + static_cast<std::ptrdiff_t>(nc), kNaNf);
        std::fill(out_grey.begin(), out_grey.begin() + static_cast<std::ptrdiff_t>(nc),
                  std::uint8_t{0});
        if (l_hi >= 0) {
          const int wl = l_hi - l_lo + 1, wb = b_hi - b_lo + 1;
          const std::size_t np = sz(wl) * sz(wb);
          speckled.resize(np);
          mask.resize(np);
          read_window(handle(sp_ds), l_lo, wl, b_lo, wb, speckled.data(), GDT_Float32,
                      "speckled_power_slant.tif");
          read_window(handle(mask_ds), l_lo, wl, b_lo, wb, mask.data(), GDT_Byte, "mask_slant.tif");
          no_data.resize(np);
          for (std::size_t i = 0; i < np; ++i) no_data[i] = (mask[i] & pixel_flag::kNoData) ? 1 : 0;
          grey.resize(np);
          greytones(speckled, grey, map, no_data);
          for (std::size_t i = 0; i < nc; ++i) {
            if (pix_line[i] < 0) continue;
            const std::size_t p = sz(pix_line[i] - l_lo) * sz(wb) + sz(pix_bin[i] - b_lo);
            out_power[i] = speckled[p];
            out_grey[i] = grey[p];
          }
        }
        power_out->write(out_power.data(), n);
        grey_out->write(out_grey.data(), n);
        bar.advance(static_cast<std::int64_t>(nc));
      }
      power_out->close();
      grey_out->close();
      stage_done();
    }

    // ---- metadata.json ----------------------------------------------------
    write_text_file_atomic(
        dir.path("metadata.json"),
        slar_metadata(grid, ss.h_min, ss.h_max, sim, pic_meta, info).dump(2) + "\n");
  }
  bar.finish();
  dir.commit();
  return summary;
}

}  // namespace ris
