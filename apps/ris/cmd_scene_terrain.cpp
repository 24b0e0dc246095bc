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
#include "ris/scene/fractal_noise.h"
#include "ris/scene/fractal_terrain.h"
#include "ris/scene/geo_frame.h"
#include "ris/scene/landcover.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"
#include "ris/util/progress.h"
#include "ris/util/resource_guard.h"
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
ris::RasterMetadata category_labels(const std::string& scene_name,
                                    const std::set<std::uint16_t>& used,
                                    const std::map<std::string, std::uint16_t>& names) {
  std::map<std::uint16_t, std::string> labels;
  for (const auto& [name, id] : names)
    if (used.count(id) != 0) labels[id] = name;
  return ris::scene_label_metadata(scene_name, labels);
}

ris::RasterMetadata category_labels(const std::string& scene_name, const ris::Scene& scene,
                                    const std::map<std::string, std::uint16_t>& names) {
  std::set<std::uint16_t> used;
  for (std::size_t i = 0; i < scene.size(); ++i)
    if (scene.valid[i]) used.insert(scene.category[i]);
  return category_labels(scene_name, used, names);
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

void run_fractal(const FractalArgs& args) {
  ris::FractalParams p;
  p.source = "ris scene fractal";
  std::tie(p.cols, p.rows) = parse_size(args.size);
  p.cell_m = parse_option(args.cell_size, ris::Quantity::length, "--cell-size");
  p.relief_m = parse_option(args.relief, ris::Quantity::length, "--relief");
  p.base_m = parse_option(args.base, ris::Quantity::length, "--base");
  p.hurst = args.hurst;
  p.seed = args.seed;
  const std::string library =
      args.library.empty() ? ris::app::data_path(kDefaultLibrary) : args.library;
  const auto names = names_if_present(library, !args.library.empty());
  const bool default_category = args.category.empty() && args.patches.empty();
  p.category = ris::parse_category(args.category.empty() ? kDefaultCategoryName : args.category,
                                   names, "--category");
  if (default_category) say_default_category(library);
  for (const std::string& item : split_list(args.patches)) {
    p.patch_categories.push_back(ris::parse_category(item, names, "--patches"));
  }
  if (!p.patch_categories.empty()) {
    p.patch_size_m = parse_option(args.patch_size, ris::Quantity::length, "--patch-size");
  }
  if (args.generator != "auto" && args.generator != "spectral" && args.generator != "noise") {
    throw ris::InputError(
        "", "--generator",
        fmt::format("expected auto, spectral or noise, got \"{}\"", args.generator));
  }
  ris::check_fractal_params(p);
  ris::require_safe_output_file(args.output, "--output");
  // The file before any work: about 4 bytes a cell once compressed (a float
  // elevation that compresses little, categories and mask that compress to
  // almost nothing); --size 1000000 once ran silently towards 4 TB.
  const std::int64_t cells = ris::checked_mul(p.rows, p.cols, "", "--size");
  ris::require_disk(ris::checked_mul(cells, 4, "", "--size"),
                    std::filesystem::absolute(args.output).parent_path(), "", "--size",
                    fmt::format("a scene of {} x {} cells", p.cols, p.rows));
  const bool noise =
      args.generator == "noise" || (args.generator == "auto" && !ris::spectral_synthesis_fits(p));

  // The grid in the local frame of Scene::flat, optionally placed on the
  // Earth: centred on a latitude/longitude in the WGS 84 UTM zone there, on
  // a grid aligned to whole cells.
  ris::Scene grid;
  grid.rows = p.rows;
  grid.cols = p.cols;
  grid.dx_m = grid.dy_m = p.cell_m;
  grid.origin_y_m = p.rows * p.cell_m;
  if (!args.centre.empty()) {
    const auto parts = split_list(args.centre);
    double lat = NAN, lon = NAN;
    if (parts.size() == 2) {
      lat = parse_option(parts[0], ris::Quantity::dimensionless, "--centre");
      lon = parse_option(parts[1], ris::Quantity::dimensionless, "--centre");
    }
    if (!(std::abs(lat) <= 90.0) || !(std::abs(lon) <= 180.0)) {
      throw ris::InputError("", "--centre", "expected LAT,LON in degrees (e.g. --centre 46.5,8.0)");
    }
    grid.crs_wkt = ris::utm_wkt_for(lon, lat);
    auto [x, y] = ris::GeoFrame(grid.crs_wkt, "--centre").scene_from_lonlat(lon, lat);
    grid.origin_x_m = std::round((x - 0.5 * grid.cols * p.cell_m) / p.cell_m) * p.cell_m;
    grid.origin_y_m = std::round((y + 0.5 * grid.rows * p.cell_m) / p.cell_m) * p.cell_m;
  }

  std::string patch_list;
  for (auto c : p.patch_categories)
    patch_list += (patch_list.empty() ? "" : ",") + std::to_string(c);
  ris::RasterMetadata metadata = {
      {"RIS_GENERATOR", noise ? "ris scene fractal (fBm as octaves of value noise, streamed)"
                              : "ris scene fractal (spectral synthesis of fBm)"},
      {"RIS_FRACTAL", fmt::format("seed={} hurst={} relief_m={} base_m={} cell_m={} size={}x{}",
                                  p.seed, p.hurst, p.relief_m, p.base_m, p.cell_m, p.cols, p.rows)},
      {"RIS_FRACTAL_CATEGORIES",
       patch_list.empty() ? std::to_string(p.category)
                          : fmt::format("patches of {} m from {}", p.patch_size_m, patch_list)},
      {"RIS_VERTICAL_DATUM", "local: elevation above the scene's flat datum"},
      {"RIS_NODATA_CELLS", "0"},
  };
  record_library(metadata, library, names,
                 p.patch_categories.empty() ? std::set<std::uint16_t>{p.category}
                                            : std::set<std::uint16_t>(p.patch_categories.begin(),
                                                                      p.patch_categories.end()));
  const std::string label = fmt::format("fractal terrain (seed {}, H = {})", p.seed, p.hurst);

  if (noise) {
    // Made and written a block of rows at a time (ris/scene/fractal_noise.h):
    // a scene of any size in bounded memory, tiled and ZSTD-compressed.
    const ris::FractalNoise gen(p);
    const std::set<std::uint16_t> used =
        p.patch_categories.empty()
            ? std::set<std::uint16_t>{p.category}
            : std::set<std::uint16_t>(p.patch_categories.begin(), p.patch_categories.end());
    for (auto& [k, v] : category_labels(label, used, names)) metadata[k] = v;
    ris::SceneGeoTiffWriter out(args.output, grid, metadata, {"ZSTD", 1, 3, true});
    constexpr int kBlockRows = 256;
    const std::size_t n = std::size_t(kBlockRows) * std::size_t(p.cols);
    std::vector<float> z(n);
    std::vector<std::uint16_t> cat(n);
    const std::vector<std::uint8_t> valid(n, 1);
    ris::ProgressBar bar("scene fractal", p.rows, "rows", args.quiet);
    for (int r0 = 0; r0 < p.rows; r0 += kBlockRows) {
      const int rows = std::min(kBlockRows, p.rows - r0);
      gen.rows(r0, rows, z.data(), cat.data());
      out.write_rows(z.data(), cat.data(), valid.data(), rows);
      bar.advance(rows);
    }
    out.close();
    bar.finish();
    fmt::print(
        "{}: {} x {} cells of {} m, heights {} to {} m, Hurst exponent {} (fBm as octaves "
        "of value noise, made in blocks of rows{}), seed {}\n",
        args.output, p.cols, p.rows, p.cell_m, p.base_m, p.base_m + p.relief_m, p.hurst,
        args.generator == "auto" ? ": too large for spectral synthesis in memory" : "", p.seed);
    return;
  }

  ris::Scene scene = ris::fractal_terrain(p);
  scene.crs_wkt = grid.crs_wkt;
  scene.origin_x_m = grid.origin_x_m;
  scene.origin_y_m = grid.origin_y_m;
  const int max_lag = std::min(64, std::min(p.rows, p.cols) / 8);
  const double h_est = max_lag >= 16 ? ris::estimate_hurst(scene, 8, max_lag) : NAN;
  for (auto& [k, v] : category_labels(label, scene, names)) metadata[k] = v;
  ris::write_scene_geotiff(scene, args.output, metadata);
  fmt::print(
      "{}: {} x {} cells of {} m, heights {} to {} m, Hurst exponent {} (variogram "
      "estimate {:.2f}), seed {}\n",
      args.output, p.cols, p.rows, p.cell_m, p.base_m, p.base_m + p.relief_m, p.hurst, h_est,
      p.seed);
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
