#include "ris/scene/fractal_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

#include "ris/io/raster_io.h"
#include "ris/io/safe_paths.h"
#include "ris/scene/fractal_noise.h"
#include "ris/scene/geo_frame.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/util/resource_guard.h"

namespace ris {

namespace {

// Rows made and written at a time by the streamed generator.
constexpr int kBlockRows = 256;

std::set<std::uint16_t> categories_used(const FractalParams& p) {
  return p.patch_categories.empty()
             ? std::set<std::uint16_t>{p.category}
             : std::set<std::uint16_t>(p.patch_categories.begin(), p.patch_categories.end());
}

std::set<std::uint16_t> categories_used(const Scene& scene) {
  std::set<std::uint16_t> used;
  for (std::size_t i = 0; i < scene.size(); ++i)
    if (scene.valid[i]) used.insert(scene.category[i]);
  return used;
}

// The file's metadata: how it was made, the request's, and the legend of
// the categories used.
RasterMetadata fractal_metadata(const FractalSceneRequest& r, bool streamed,
                                const std::set<std::uint16_t>& used) {
  const FractalParams& p = r.params;
  std::string patch_list;
  for (auto c : p.patch_categories)
    patch_list += (patch_list.empty() ? "" : ",") + std::to_string(c);
  RasterMetadata metadata = {
      {"RIS_GENERATOR", streamed ? "ris scene fractal (fBm as octaves of value noise, streamed)"
                                 : "ris scene fractal (spectral synthesis of fBm)"},
      {"RIS_FRACTAL", fmt::format("seed={} hurst={} relief_m={} base_m={} cell_m={} size={}x{}",
                                  p.seed, p.hurst, p.relief_m, p.base_m, p.cell_m, p.cols, p.rows)},
      {"RIS_FRACTAL_CATEGORIES",
       patch_list.empty() ? std::to_string(p.category)
                          : fmt::format("patches of {} m from {}", p.patch_size_m, patch_list)},
      {"RIS_VERTICAL_DATUM", "local: elevation above the scene's flat datum"},
      {"RIS_NODATA_CELLS", "0"},
  };
  for (const auto& [k, v] : r.metadata) metadata[k] = v;
  const std::string label = fmt::format("fractal terrain (seed {}, H = {})", p.seed, p.hurst);
  for (auto& [k, v] : category_label_metadata(label, used, r.category_names)) metadata[k] = v;
  return metadata;
}

// The noise generator's scene, made and written a block of rows at a time:
// any size in bounded memory, tiled and ZSTD-compressed.
void write_streamed(const std::filesystem::path& path, const FractalSceneRequest& r,
                    const Scene& grid) {
  const FractalParams& p = r.params;
  const FractalNoise gen(p);
  SceneGeoTiffWriter out(path, grid, fractal_metadata(r, true, categories_used(p)),
                         {"ZSTD", 1, 3, true});
  const std::size_t n = std::size_t(kBlockRows) * std::size_t(p.cols);
  std::vector<float> z(n);
  std::vector<std::uint16_t> cat(n);
  const std::vector<std::uint8_t> valid(n, 1);
  for (int r0 = 0; r0 < p.rows; r0 += kBlockRows) {
    const int rows = std::min(kBlockRows, p.rows - r0);
    gen.rows(r0, rows, z.data(), cat.data());
    out.write_rows(z.data(), cat.data(), valid.data(), rows);
    if (r.rows_done) r.rows_done(r0 + rows);
  }
  out.close();
}

}  // namespace

bool fractal_streams(const FractalSceneRequest& r) {
  return r.generator == FractalGenerator::noise ||
         (r.generator == FractalGenerator::automatic && !spectral_synthesis_fits(r.params));
}

Scene fractal_grid(const FractalSceneRequest& r) {
  const FractalParams& p = r.params;
  Scene grid;
  grid.rows = p.rows;
  grid.cols = p.cols;
  grid.dx_m = grid.dy_m = p.cell_m;
  grid.origin_y_m = p.rows * p.cell_m;
  if (r.centre_lat_lon_deg) {
    const auto [lat, lon] = *r.centre_lat_lon_deg;
    grid.crs_wkt = utm_wkt_for(lon, lat);
    auto [x, y] = GeoFrame(grid.crs_wkt, "--centre").scene_from_lonlat(lon, lat);
    grid.origin_x_m = std::round((x - 0.5 * grid.cols * p.cell_m) / p.cell_m) * p.cell_m;
    grid.origin_y_m = std::round((y + 0.5 * grid.rows * p.cell_m) / p.cell_m) * p.cell_m;
  }
  return grid;
}

FractalSceneWritten write_fractal_scene(const std::filesystem::path& path,
                                        const FractalSceneRequest& r) {
  const FractalParams& p = r.params;
  check_fractal_params(p);
  require_safe_output_file(path, "--output");
  // The file before any work: about 4 bytes a cell once compressed (a float
  // elevation that compresses little, categories and mask that compress to
  // almost nothing); --size 1000000 once ran silently towards 4 TB.
  const std::int64_t cells = checked_mul(p.rows, p.cols, "", "--size");
  require_disk(checked_mul(cells, 4, "", "--size"), std::filesystem::absolute(path).parent_path(),
               "", "--size", fmt::format("a scene of {} x {} cells", p.cols, p.rows));
  const Scene grid = fractal_grid(r);
  FractalSceneWritten written{fractal_streams(r), std::numeric_limits<double>::quiet_NaN()};
  if (written.streamed) {
    write_streamed(path, r, grid);
    return written;
  }
  Scene scene = fractal_terrain(p);
  scene.crs_wkt = grid.crs_wkt;
  scene.origin_x_m = grid.origin_x_m;
  scene.origin_y_m = grid.origin_y_m;
  const int max_lag = std::min(64, std::min(p.rows, p.cols) / 8);
  if (max_lag >= 16) written.hurst_estimate = estimate_hurst(scene, 8, max_lag);
  write_scene_geotiff(scene, path, fractal_metadata(r, false, categories_used(scene)));
  return written;
}

}  // namespace ris
