#include "ris/scene/scene_builder.h"

#include <cpl_conv.h>
#include <fmt/format.h>
#include <ogr_srs_api.h>
#include <spdlog/spdlog.h>

#include <charconv>
#include <climits>
#include <cmath>

#include "ris/io/config_table.h"
#include "ris/io/gdal_util.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"
#include "scene/objects/paint_cells.h"

namespace ris {

namespace {

// A CRS written any way GDAL understands ("EPSG:32614", WKT, PROJ string) as WKT.
std::string crs_to_wkt(const std::string& text, ConfigTable& grid) {
  ensure_gdal_writers_registered();
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  std::string wkt;
  if (OSRSetFromUserInput(srs, text.c_str()) == OGRERR_NONE) {
    char* out = nullptr;
    if (OSRExportToWkt(srs, &out) == OGRERR_NONE && out != nullptr) wkt = out;
    CPLFree(out);
  }
  OSRDestroySpatialReference(srs);
  if (wkt.empty()) {
    grid.fail("crs", fmt::format("cannot interpret \"{}\" as a coordinate reference system "
                                 "(e.g. \"EPSG:32614\")",
                                 text));
  }
  return wkt;
}

int grid_count(ConfigTable& grid, const std::string& key) {
  const std::int64_t n = grid.get_int(key);
  if (n <= 0 || n > INT_MAX) {
    grid.fail(key, fmt::format("must be an integer between 1 and {}, got {}", INT_MAX, n));
  }
  return static_cast<int>(n);
}

GridSpec parse_grid(ConfigTable& grid) {
  GridSpec g;
  // Sizes first, and the memory estimate before anything else is checked, so
  // an impossible grid is refused with its estimate.
  const std::int64_t rows = grid.get_int("rows");
  const std::int64_t cols = grid.get_int("cols");
  if (rows > 0 && cols > 0) check_scene_fits_in_memory(rows, cols, grid.file(), "grid");
  g.rows = grid_count(grid, "rows");
  g.cols = grid_count(grid, "cols");
  g.cell_m = object_params::positive_length_m(grid, "cell_size");
  const double base_m = grid.get_quantity_or("base_elevation", Quantity::length, 0.0);
  if (!std::isfinite(base_m) || std::abs(base_m) > 1e6) {
    grid.fail("base_elevation", "must be a finite elevation within +-1000 km");
  }
  g.base_elevation_m = static_cast<float>(base_m);
  g.base_category = grid.has("base_category") ? object_params::category(grid, "base_category") : 0;
  if (grid.has("origin")) {
    const std::vector<double> origin = grid.get_quantity_array("origin", Quantity::length);
    if (origin.size() != 2 || !std::isfinite(origin[0]) || !std::isfinite(origin[1])) {
      grid.fail("origin", "expected [x, y]: world coordinates of the south-west corner");
    }
    g.origin_x_m = origin[0];
    g.origin_y_m = origin[1];
  }
  if (auto crs = grid.get_string_opt("crs")) g.crs_wkt = crs_to_wkt(*crs, grid);
  grid.finish();
  return g;
}

std::map<std::uint16_t, std::string> parse_category_names(ConfigTable& names) {
  std::map<std::uint16_t, std::string> out;
  for (const std::string& key : names.keys()) {
    std::uint16_t id = 0;
    const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), id);
    if (ec != std::errc() || end != key.data() + key.size() || id > kMaxCategory) {
      names.fail(key, fmt::format("expected a category id 0..{} as the key", kMaxCategory));
    }
    out[id] = names.get_string(key);
  }
  names.finish();
  return out;
}

}  // namespace

SceneDescription parse_scene_description(const toml::table& doc, const std::string& source) {
  SceneDescription d;
  d.source = source;
  ConfigTable root(doc, source, "");
  d.name = root.get_string_or("name", "");
  d.description = root.get_string_or("description", "");
  std::optional<ConfigTable> grid = root.subtable("grid");
  if (!grid) root.fail("grid", "missing required table [grid] (rows, cols, cell_size)");
  d.grid = parse_grid(*grid);
  if (std::optional<ConfigTable> names = root.subtable("category_names")) {
    d.category_names = parse_category_names(*names);
  }
  const GridExtent extent{d.grid.cols * d.grid.cell_m, d.grid.rows * d.grid.cell_m};
  std::vector<ConfigTable> objects = root.table_array("object");
  for (std::size_t i = 0; i < objects.size(); ++i) {
    std::unique_ptr<SceneObject> object = parse_scene_object(objects[i], extent);
    d.object_labels.push_back(fmt::format("object[{}] ({})", i, object->type()));
    d.objects.push_back(std::move(object));
  }
  root.finish();
  return d;
}

std::vector<CulturalObject> cultural_objects(const SceneDescription& d) {
  std::vector<CulturalObject> out;
  const double w = d.grid.cols * d.grid.cell_m;
  const double h = d.grid.rows * d.grid.cell_m;
  for (std::size_t i = 0; i < d.objects.size(); ++i) {
    std::optional<CulturalObject> c = d.objects[i]->cultural(d.grid.base_elevation_m);
    const Bounds b = d.objects[i]->bounds();
    if (!c || b.x_max_m < 0.0 || b.y_max_m < 0.0 || b.x_min_m > w || b.y_min_m > h) continue;
    c->label = d.object_labels[i];
    out.push_back(std::move(*c));
  }
  move_to_world(out, d.grid.origin_x_m, d.grid.origin_y_m);
  return out;
}

SceneDescription read_scene_description(const std::string& path) {
  const toml::table doc = parse_toml_file(path);
  return parse_scene_description(doc, path);
}

namespace {

// The least work the objects of any scene may ask for: 4e9 cell tests, a
// few seconds on two cores; a larger grid may take 16 full passes.
constexpr std::int64_t kMinPaintSteps = 4'000'000'000;
constexpr std::int64_t kPaintPassesPerGrid = 16;

// The objects' cell tests (each visits every cell of its clipped bounding
// box), counted before any is painted: a file of 0.3 MB holding 5,000
// full-grid patches over a 3,000^2 grid would ask for 4.5e10.
void require_paint_work(const SceneDescription& d) {
  const GridSpec& g = d.grid;
  std::int64_t steps = 0;
  for (const std::unique_ptr<SceneObject>& object : d.objects) {
    const detail::CellRange r =
        detail::cell_range(g.rows, g.cols, g.cell_m, g.cell_m, object->bounds());
    steps = checked_add(steps, r.cells(), d.source, "object");
  }
  const std::int64_t cells = checked_mul(g.rows, g.cols, d.source, "grid");
  const std::int64_t max_steps =
      std::max(kMinPaintSteps, checked_mul(kPaintPassesPerGrid, cells, d.source, "grid"));
  require_work(steps, max_steps, d.source, "object",
               fmt::format("the {} objects' cell tests (each object visits every cell of its "
                           "bounding box)",
                           d.objects.size()));
}

}  // namespace

Scene build_scene(const SceneDescription& d) {
  const GridSpec& g = d.grid;
  require_paint_work(d);
  Scene scene = Scene::flat(g.rows, g.cols, g.cell_m, g.base_elevation_m, g.base_category);
  // Scene stores the north-west corner; the file gives the south-west one.
  scene.origin_x_m = g.origin_x_m;
  scene.origin_y_m = g.origin_y_m + g.rows * g.cell_m;
  scene.crs_wkt = g.crs_wkt;
  const double width_m = g.cols * g.cell_m;
  const double height_m = g.rows * g.cell_m;
  for (std::size_t i = 0; i < d.objects.size(); ++i) {
    const SceneObject& object = *d.objects[i];
    const Bounds b = object.bounds();
    const bool outside =
        b.x_max_m < 0.0 || b.y_max_m < 0.0 || b.x_min_m > width_m || b.y_min_m > height_m;
    if (outside) {
      spdlog::warn("{}: {} lies wholly outside the grid (x 0..{:g} m, y 0..{:g} m); ignored",
                   d.source, d.object_labels[i], width_m, height_m);
      continue;
    }
    if (object.paint(scene, g.base_elevation_m) == 0) {
      spdlog::warn("{}: {} covers no cell centre of the grid; ignored", d.source,
                   d.object_labels[i]);
    } else if (object.smallest_feature_m() < g.cell_m) {
      spdlog::warn(
          "{}: {} has details of {:g} m, smaller than a cell ({:g} m): each cell takes the "
          "object at its centre only, so its shape is lost (a checkerboard's squares alias "
          "into a pattern that is not the board's); use cells of {:g} m or less",
          d.source, d.object_labels[i], object.smallest_feature_m(), g.cell_m,
          object.smallest_feature_m() / 2.0);
    }
  }
  scene.validate(d.source);
  return scene;
}

Scene build_scene_file(const std::string& path) {
  return build_scene(read_scene_description(path));
}

}  // namespace ris
