// `ris scene import` and `ris scene fractal`: scenes from real DEMs and land
// cover, and seeded fractal relief (docs/terrain.md). These attach to the
// `scene` command group (apps/ris/cmd_scene.cpp); registered under a name that
// sorts after "scene" so that group exists first.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <optional>
#include <string>

#include "command_registry.h"
#include "ris/io/dem_import.h"
#include "ris/io/scene_io.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace {

// The `scene` group, created here when cmd_scene.cpp has not made it.
CLI::App* scene_group(CLI::App& app) {
  auto found = app.get_subcommands([](CLI::App* sub) { return sub->get_name() == "scene"; });
  if (!found.empty()) return found.front();
  auto* scene = app.add_subcommand("scene", "Build, import and inspect scenes");
  scene->require_subcommand(1);
  return scene;
}

// A length option: a bare number in metres or "<number> <unit>".
double parse_length(const std::string& text, const std::string& key) {
  try {
    return ris::parse_quantity(text, ris::Quantity::length);
  } catch (const std::invalid_argument& e) {
    throw ris::InputError("", key, e.what());
  }
}

struct ImportArgs {
  std::string dem;
  std::string output;
  std::string cell_size;
  std::string crs;
};

void run_import(const ImportArgs& args) {
  ris::DemImportOptions options;
  if (!args.cell_size.empty()) options.cell_size_m = parse_length(args.cell_size, "--cell-size");
  if (!args.crs.empty()) options.crs = args.crs;
  ris::ImportedDem dem = ris::import_dem(args.dem, options);
  ris::write_scene_geotiff(dem.scene, args.output, dem.metadata);
  fmt::print("{}: {} x {} cells of {} m in {}; {} no-data cells; heights: {}\n", args.output,
             dem.scene.cols, dem.scene.rows, dem.scene.dx_m, dem.frame, dem.nodata_cells,
             dem.vertical_datum);
}

void add_scene_terrain(CLI::App& app) {
  CLI::App* scene = scene_group(app);

  auto args = std::make_shared<ImportArgs>();
  auto* import = scene->add_subcommand(
      "import",
      "Import a DEM (any GDAL raster; geographic DEMs are reprojected into the UTM zone of "
      "their centre) as a scene GeoTIFF");
  import->add_option("dem", args->dem, "Elevation raster (GeoTIFF, SRTM .hgt, ...)")->required();
  import->add_option("-o,--output", args->output, "Scene GeoTIFF to write")->required();
  import->add_option("--cell-size", args->cell_size,
                     "Output cell size (\"30\", \"30 m\", \"100 ft\"); default: the DEM's "
                     "posting in metres, rounded to two significant digits");
  import->add_option("--crs", args->crs,
                     "CRS of the DEM when the file has none (EPSG:4326, WKT, PROJ string)");
  import->callback([args] { run_import(*args);
});
}  // namespace

const ris::app::Registration reg{"scene_terrain", add_scene_terrain};

}  // namespace
