// A fractal scene written to a file, as `ris scene fractal` makes it
// (docs/terrain.md): the grid in a local frame or placed on the Earth, the
// generator (spectral synthesis in memory, ris/scene/fractal_terrain.h, or
// octaves of value noise made and written a block of rows at a time,
// ris/scene/fractal_noise.h: any size in bounded memory), the file's
// metadata and legend, and the output checks before any work.
//
// Example:
//   ris::FractalSceneRequest r;
//   r.params.cols = r.params.rows = 40000;  r.params.seed = 7;
//   r.generator = ris::FractalGenerator::noise;
//   ris::FractalSceneWritten w = ris::write_fractal_scene("alps.tif", r);
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include "ris/scene/fractal_terrain.h"
#include "ris/scene/scene.h"

namespace ris {

enum class FractalGenerator {
  automatic,  // spectral when it fits in memory (spectral_synthesis_fits), else noise
  spectral,
  noise,
};

struct FractalSceneRequest {
  FractalParams params;
  FractalGenerator generator = FractalGenerator::automatic;
  // Where the scene's centre lies (latitude, longitude, degrees): the grid
  // is then in the WGS 84 UTM zone there, aligned to whole cells. None: the
  // local frame of Scene::flat (south-west corner at 0, 0).
  std::optional<std::pair<double, double>> centre_lat_lon_deg;
  // Added to the file's metadata (e.g. the backscatter library it names).
  std::map<std::string, std::string> metadata;
  // The category library's names, for the legend of the categories used
  // (RIS_CATEGORY_NAMES); empty: ids only.
  std::map<std::string, std::uint16_t> category_names;
  // Called with the rows made so far by the streamed generator.
  std::function<void(int rows)> rows_done;
};

struct FractalSceneWritten {
  bool streamed = false;        // made by the noise generator, a block of rows at a time
  double hurst_estimate = 0.0;  // spectral: the variogram's estimate (NaN when too small)
};

// Which generator a request runs: noise when asked, or automatic and the
// spectral synthesis does not fit in memory.
bool fractal_streams(const FractalSceneRequest& request);

// The scene's grid (no arrays): rows, cols, cell size, origin and CRS.
Scene fractal_grid(const FractalSceneRequest& request);

// Writes the scene (.tif, or the VRT form for .vrt) with its metadata.
// Throws InputError for out-of-range parameters, an unsafe output path, or
// too little room for the file (about 4 bytes a cell), before any work.
FractalSceneWritten write_fractal_scene(const std::filesystem::path& path,
                                        const FractalSceneRequest& request);

}  // namespace ris
