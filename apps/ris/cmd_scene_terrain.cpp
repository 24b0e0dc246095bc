// `ris scene import` and `ris scene fractal`: scenes from real DEMs and land
// cover, and seeded fractal relief (docs/terrain.md). These attach to the
// `scene` command group (apps/ris/cmd_scene.cpp); registered under a name that
// sorts after "scene" so that the group exists first (and is created here
// when it does not).
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "command_registry.h"
#include "ris/io/safe_paths.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/fractal_scene.h"
#include "ris/scene/landcover.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"
#include "ris/util/progress.h"
#include "ris/util/units.h"
#include "seed_option.h"

namespace {

CLI::App* scene_group(CLI::App& app) {
  auto found = app.get_subcommands([](CLI::App* sub) { return sub->get_name() == "scene"; });
  if (!found.empty()) return found.front();
  auto* scene = app.add_subcommand("scene", "Build, import and inspect scenes");
  scene->require_subcommand(1);
  return scene;
}

// A quantity option: a bare number in the default unit or "<number> <unit>".
double parse_option(const std::string& text, ris::Quantity q, const std::string& key) {
  try {
    return ris::parse_quantity(text, q);
  } catch (const std::invalid_argument& e) {
    throw ris::InputError("", key, e.what());
  }
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto b = item.find_first_not_of(' ');
    const auto e = item.find_last_not_of(' ');
    if (b != std::string::npos) out.push_back(item.substr(b, e - b + 1));
  }
  return out;
}

// The category of every cell of a scene made without one (a bare DEM, a
// fractal without --category or --patches): ris::kDefaultCategory, grass of
// the shipped generic-terrain library, which the scene then names for `ris
// simulate` (docs/terrain.md, "Categories").
using ris::kDefaultCategoryName;
constexpr const char* kDefaultLibrary = ris::kDefaultCategoryLibrary;

void say_default_category(const std::string& library) {
  spdlog::info(
      "no --category: every cell is {} of {} (`ris simulate` takes that library for this "
      "scene unless given --backscatter); --category chooses another",
      kDefaultCategoryName, library);
}

// Names of categories in a library, empty when the library is absent and
// not needed (ids only).
std::map<std::string, std::uint16_t> names_if_present(const std::string& library,
                                                      bool explicit_library) {
  if (explicit_library || ris::path_exists(library)) {
    return ris::read_category_names(library);
  }
  return {};
}

// Records the library (RIS_BACKSCATTER_LIBRARY, for `ris simulate`) when it
// defines every category the scene uses: ids given bare (`--patches
// 1,2,3`) may be another library's, and then none is recorded.
void record_library(ris::RasterMetadata& metadata, const std::string& library,
                    const std::map<std::string, std::uint16_t>& names,
                    const std::set<std::uint16_t>& used) {
  if (names.empty()) return;
  for (const std::uint16_t c : used) {
    const auto defines = [c](const auto& name_id) { return name_id.second == c; };
    if (std::none_of(names.begin(), names.end(), defines)) return;
  }
  for (auto& [k, v] : ris::backscatter_library_metadata(library)) metadata[k] = v;
}

// Legend labels (RIS_CATEGORY_NAMES, ris/scene/scene_source.h) of the
// categories a scene uses, from a library's names.
ris::RasterMetadata category_labels(const std::string& scene_name, const ris::Scene& scene,
                                    const std::map<std::string, std::uint16_t>& names) {
  std::set<std::uint16_t> used;
  for (std::size_t i = 0; i < scene.size(); ++i)
    if (scene.valid[i]) used.insert(scene.category[i]);
  return ris::category_label_metadata(scene_name, used, names);
}

// ---- ris scene import --------------------------------------------------

struct ImportArgs {
  std::string dem;
  std::string output;
  std::string cell_size;
  std::string crs;
  std::string landcover;
  std::string mapping;
  std::string default_category;
  std::string category;
  std::string library;
};

void run_import(const ImportArgs& args) {
  if (args.landcover.empty() != args.mapping.empty()) {
    throw ris::InputError("", args.landcover.empty() ? "--mapping" : "--landcover",
                          "--landcover and --mapping go together (a land-cover raster and the "
                          "file mapping its codes to categories)");
  }
  if (!args.default_category.empty() && args.mapping.empty()) {
    throw ris::InputError("", "--default-category", "needs --landcover and --mapping");
  }
  // Check the mapping before the (slower) DEM import.
  std::optional<ris::LandCoverMapping> mapping;
  if (!args.mapping.empty()) {
    mapping = ris::read_landcover_mapping(args.mapping);
    if (!args.default_category.empty()) {
      mapping->default_category =
          ris::resolve_category(*mapping, args.default_category, "--default-category");
    }
  }
  ris::require_regular_input(args.dem);
  ris::require_safe_output_file(args.output, "--output");  // before the import's work
  const std::string library =
      args.library.empty() ? ris::app::data_path(kDefaultLibrary) : args.library;
  std::string category = args.category;
  if (category.empty() && !mapping) {
    category = kDefaultCategoryName;
    say_default_category(library);
  }
  ris::DemImportOptions options;
  if (!args.cell_size.empty()) {
    options.cell_size_m = parse_option(args.cell_size, ris::Quantity::length, "--cell-size");
  }
  if (!args.crs.empty()) options.crs = args.crs;
  if (!category.empty()) {
    if (mapping) {
      throw ris::InputError("", "--category",
                            "--category is for DEMs without land cover (use the mapping's "
                            "default or fill, or --default-category)");
    }
    options.category = ris::parse_category(
        category, names_if_present(library, !args.library.empty()), "--category");
  }
  ris::ImportedDem dem = ris::import_dem(args.dem, options);
  ris::RasterMetadata metadata = dem.metadata;
  std::map<std::string, std::uint16_t> names;
  if (mapping && !mapping->library.empty()) {
    names = ris::read_category_names(mapping->library);
    for (auto& [k, v] : ris::backscatter_library_metadata(mapping->library)) metadata[k] = v;
  } else if (!category.empty()) {
    names = names_if_present(library, !args.library.empty());
    record_library(metadata, library, names, {options.category});
  }
  std::string landcover_note;
  if (mapping) {
    ris::LandCoverStats st = ris::apply_landcover(dem.scene, args.landcover, *mapping);
    metadata.insert(st.metadata.begin(), st.metadata.end());
    // Cells without land cover may have been masked: recount.
    metadata["RIS_NODATA_CELLS"] = std::to_string(ris::count_nodata(dem.scene));
    landcover_note =
        fmt::format("; land cover: {} cells mapped, {} defaulted, {} without cover",
                    st.mapped_cells, st.default_cells, st.fill_cells + st.unfilled_cells);
  }
  for (auto& [k, v] :
       category_labels(std::filesystem::path(args.dem).stem().string(), dem.scene, names))
    metadata[k] = v;
  ris::write_scene_geotiff(dem.scene, args.output, metadata);
  fmt::print("{}: {} x {} cells of {} m in {}; {} no-data cells; heights: {}{}\n", args.output,
             dem.scene.cols, dem.scene.rows, dem.scene.dx_m, dem.frame,
             ris::count_nodata(dem.scene), dem.vertical_datum, landcover_note);
}

// ---- ris scene fractal -------------------------------------------------

struct FractalArgs {
  std::string output;
  std::string size = "512";
  std::string cell_size = "30 m";
  std::string relief = "1000 m";
  std::string base = "0 m";
  double hurst = 0.8;
  std::uint64_t seed = 1;
  std::string category;  // default: kDefaultCategory
  std::string patches;
  std::string patch_size = "500 m";
  std::string library;
  std::string centre;
  std::string generator = "auto";
  bool quiet = false;
};

std::pair<int, int> parse_size(const std::string& text) {
  int cols = 0, rows = 0;
  char x = 0;
  std::istringstream in(text);
  if (text.find('x') != std::string::npos) {
    in >> cols >> x >> rows;
  } else {
    in >> cols;
    rows = cols;
  }
  if (in.fail() || !in.eof() || cols < 2 || rows < 2) {
    throw ris::InputError(
        "", "--size", fmt::format("expected COLSxROWS or N (cells, at least 2), got \"{}\"", text));
  }
  return {cols, rows};
}

ris::FractalGenerator parse_generator(const std::string& text) {
  if (text == "auto") return ris::FractalGenerator::automatic;
  if (text == "spectral") return ris::FractalGenerator::spectral;
  if (text == "noise") return ris::FractalGenerator::noise;
  throw ris::InputError("", "--generator",
                        fmt::format("expected auto, spectral or noise, got \"{}\"", text));
}

// --centre LAT,LON in degrees.
std::pair<double, double> parse_centre(const std::string& text) {
  const auto parts = split_list(text);
  double lat = NAN, lon = NAN;
  if (parts.size() == 2) {
    lat = parse_option(parts[0], ris::Quantity::dimensionless, "--centre");
    lon = parse_option(parts[1], ris::Quantity::dimensionless, "--centre");
  }
  if (!(std::abs(lat) <= 90.0) || !(std::abs(lon) <= 180.0)) {
    throw ris::InputError("", "--centre", "expected LAT,LON in degrees (e.g. --centre 46.5,8.0)");
  }
  return {lat, lon};
}

// The options as a request of ris/scene/fractal_scene.h (the library
// checks the output and writes).
ris::FractalSceneRequest fractal_request(const FractalArgs& args, const std::string& library) {
  ris::FractalSceneRequest r;
  ris::FractalParams& p = r.params;
  p.source = "ris scene fractal";
  std::tie(p.cols, p.rows) = parse_size(args.size);
  p.cell_m = parse_option(args.cell_size, ris::Quantity::length, "--cell-size");
  p.relief_m = parse_option(args.relief, ris::Quantity::length, "--relief");
  p.base_m = parse_option(args.base, ris::Quantity::length, "--base");
  p.hurst = args.hurst;
  p.seed = args.seed;
  r.category_names = names_if_present(library, !args.library.empty());
  const bool default_category = args.category.empty() && args.patches.empty();
  p.category = ris::parse_category(args.category.empty() ? kDefaultCategoryName : args.category,
                                   r.category_names, "--category");
  if (default_category) say_default_category(library);
  for (const std::string& item : split_list(args.patches)) {
    p.patch_categories.push_back(ris::parse_category(item, r.category_names, "--patches"));
  }
  if (!p.patch_categories.empty()) {
    p.patch_size_m = parse_option(args.patch_size, ris::Quantity::length, "--patch-size");
  }
  r.generator = parse_generator(args.generator);
  if (!args.centre.empty()) r.centre_lat_lon_deg = parse_centre(args.centre);
  record_library(r.metadata, library, r.category_names,
                 p.patch_categories.empty() ? std::set<std::uint16_t>{p.category}
                                            : std::set<std::uint16_t>(p.patch_categories.begin(),
                                                                      p.patch_categories.end()));
  return r;
}

void run_fractal(const FractalArgs& args) {
  const std::string library =
      args.library.empty() ? ris::app::data_path(kDefaultLibrary) : args.library;
  ris::FractalSceneRequest r = fractal_request(args, library);
  const ris::FractalParams& p = r.params;
  std::optional<ris::ProgressBar> bar;
  if (ris::fractal_streams(r)) {  // made a block of rows at a time: show them
    bar.emplace("scene fractal", p.rows, "rows", args.quiet);
    r.rows_done = [&bar, done = 0](int rows) mutable {
      bar->advance(rows - done);
      done = rows;
    };
  }
  const ris::FractalSceneWritten w = ris::write_fractal_scene(args.output, r);
  if (w.streamed) {
    bar->finish();
    fmt::print(
        "{}: {} x {} cells of {} m, heights {} to {} m, Hurst exponent {} (fBm as octaves "
        "of value noise, made in blocks of rows{}), seed {}\n",
        args.output, p.cols, p.rows, p.cell_m, p.base_m, p.base_m + p.relief_m, p.hurst,
        args.generator == "auto" ? ": too large for spectral synthesis in memory" : "", p.seed);
    return;
  }
  fmt::print(
      "{}: {} x {} cells of {} m, heights {} to {} m, Hurst exponent {} (variogram "
      "estimate {:.2f}), seed {}\n",
      args.output, p.cols, p.rows, p.cell_m, p.base_m, p.base_m + p.relief_m, p.hurst,
      w.hurst_estimate, p.seed);
}

void add_scene_terrain(CLI::App& app) {
  CLI::App* scene = scene_group(app);

  auto ia = std::make_shared<ImportArgs>();
  auto* import_cmd = scene->add_subcommand(
      "import",
      "Import a DEM (any GDAL raster; geographic DEMs are reprojected into the UTM zone of "
      "their centre) and optional land cover as a scene GeoTIFF");
  import_cmd->add_option("dem", ia->dem, "Elevation raster (GeoTIFF, SRTM .hgt, ...)")->required();
  import_cmd
      ->add_option(
          "-o,--output", ia->output,
          "Scene to write: GeoTIFF (.tif) or, with .vrt, a VRT with an integer category band")
      ->required();
  import_cmd->add_option("--cell-size", ia->cell_size,
                         "Output cell size (\"30\", \"30 m\", \"100 ft\"); default: the DEM's "
                         "posting in metres, rounded to two significant digits");
  import_cmd->add_option("--crs", ia->crs,
                         "CRS of the DEM when the file has none (EPSG:4326, WKT, PROJ string)");
  import_cmd->add_option("--landcover", ia->landcover,
                         "Categorical land-cover raster (any CRS), resampled by nearest neighbour");
  import_cmd->add_option(
      "--mapping", ia->mapping,
      "TOML file mapping land-cover codes to categories (data/landcover/*.toml)");
  import_cmd->add_option("--default-category", ia->default_category,
                         "Category (name or id) of land-cover codes the mapping does not list");
  import_cmd->add_option("--category", ia->category,
                         "Category (name or id) of every cell when there is no land cover "
                         "(default: grass of generic-terrain)");
  import_cmd->add_option("--library", ia->library,
                         "Category library for --category names (default: data/backscatter/"
                         "generic-terrain.toml)");
  import_cmd->callback([ia] { run_import(*ia); });

  auto fa = std::make_shared<FractalArgs>();
  auto* fractal = scene->add_subcommand(
      "fractal", "Generate seeded fractal terrain (fBm with a Hurst exponent) as a scene GeoTIFF");
  fractal
      ->add_option(
          "-o,--output", fa->output,
          "Scene to write: GeoTIFF (.tif) or, with .vrt, a VRT with an integer category band")
      ->required();
  fractal->add_flag("--quiet", fa->quiet, "No progress (a bar on a terminal, else log lines)");
  fractal->add_option("--size", fa->size, "Cells: N (square) or COLSxROWS")->capture_default_str();
  fractal->add_option("--cell-size", fa->cell_size, "Cell size")->capture_default_str();
  fractal->add_option("--relief", fa->relief, "Highest minus lowest elevation")
      ->capture_default_str();
  fractal->add_option("--base", fa->base, "Lowest elevation")->capture_default_str();
  fractal
      ->add_option("--hurst", fa->hurst,
                   "Hurst exponent in (0, 1): 0.9 smooth hills, 0.3 rough ground")
      ->capture_default_str();
  ris::app::add_seed_option(fractal, fa->seed, "Random seed (same seed, same scene)");
  fractal->add_option("--category", fa->category,
                      "Category of every cell (name or id; default: grass of generic-terrain)");
  fractal->add_option("--patches", fa->patches,
                      "Land-cover patches: comma-separated categories (names or ids)");
  fractal->add_option("--patch-size", fa->patch_size, "Mean patch spacing")->capture_default_str();
  fractal->add_option("--library", fa->library,
                      "Category library for names (default: data/backscatter/"
                      "generic-terrain.toml)");
  fractal->add_option("--centre", fa->centre,
                      "LAT,LON: place the scene there, in the WGS 84 UTM zone (default: a "
                      "local frame with the south-west corner at 0,0)");
  fractal
      ->add_option("--generator", fa->generator,
                   "auto (spectral when it fits in memory, else noise), spectral (spectral "
                   "synthesis, whole grid in memory) or noise (octaves of value noise, made "
                   "and written in blocks of rows: any size)")
      ->capture_default_str();
  fractal->callback([fa] { run_fractal(*fa); });
}  // namespace

const ris::app::Registration reg{"scene_terrain", add_scene_terrain};

}  // namespace
