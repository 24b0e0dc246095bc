#include "ris/scene/landcover.h"

#include <fmt/format.h>
#include <gdal.h>
#include <ogr_spatialref.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "ris/io/config_table.h"
#include "ris/io/gdal_util.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"

namespace ris {

namespace {

namespace fs = std::filesystem;

// Code written into warped cells that no land-cover pixel covers.
constexpr std::int32_t kNoCover = std::numeric_limits<std::int32_t>::min();

// The library beside the mapping file, else in the ris data folder
// (RIS_DATA overrides the compiled-in one, as for the tool).
fs::path resolve_library(const std::string& library, const fs::path& mapping_path) {
  const fs::path p(library);
  if (p.is_absolute()) return p;
  const fs::path beside = mapping_path.parent_path() / p;
  if (path_exists(beside)) return beside;
  return data_dir() / p;
}

// Name -> id of every [[category]] in a category library (only these two
// keys are read: the models are the backscatter library's business).
std::map<std::string, std::uint16_t> library_names(const fs::path& library,
                                                   const std::string& mapping_file) {
  if (!path_exists(library)) {
    throw InputError(mapping_file, "mapping.library",
                     "the category library " + library.string() + " does not exist");
  }
  return read_category_names(library);
}

}  // namespace

std::map<std::string, std::uint16_t> read_category_names(const fs::path& library) {
  const std::string lib = library.string();
  if (!path_exists(library)) throw InputError(lib, "", "no such category library");
  toml::table doc = parse_toml_file(lib);
  std::map<std::string, std::uint16_t> names;
  const toml::array* cats = doc["category"].as_array();
  if (cats == nullptr) throw InputError(lib, "category", "no [[category]] tables in the library");
  for (std::size_t i = 0; i < cats->size(); ++i) {
    const toml::table* t = (*cats)[i].as_table();
    const auto id = t != nullptr ? (*t)["id"].value<std::int64_t>() : std::nullopt;
    const auto name = t != nullptr ? (*t)["name"].value<std::string>() : std::nullopt;
    if (!id || !name || *id < 0 || *id > kMaxCategory) {
      throw InputError(lib, fmt::format("category[{}]", i),
                       fmt::format("expected an id in 0..{} and a name", kMaxCategory));
    }
    names[*name] = static_cast<std::uint16_t>(*id);
  }
  return names;
}

namespace {

std::string known_names(const std::map<std::string, std::uint16_t>& names) {
  std::string out;
  for (const auto& [n, id] : names)
    out += fmt::format("{}\"{}\" ({})", out.empty() ? "" : ", ", n, id);
  return out;
}

// A category given as an id (integer) or a library name (string).
std::uint16_t category_of(const toml::node* node, const std::map<std::string, std::uint16_t>& names,
                          const std::string& file, const std::string& key) {
  if (node != nullptr && node->is_integer()) {
    const std::int64_t id = *node->value<std::int64_t>();
    if (id < 0 || id > kMaxCategory) {
      throw InputError(file, key, fmt::format("category id {} is outside 0..{}", id, kMaxCategory));
    }
    return static_cast<std::uint16_t>(id);
  }
  if (node != nullptr && node->is_string()) {
    const std::string name = *node->value<std::string>();
    if (names.empty()) {
      throw InputError(file, key,
                       fmt::format("category \"{}\" is a name, but [mapping] names no library "
                                   "to look it up in (set mapping.library, or use ids)",
                                   name));
    }
    const auto it = names.find(name);
    if (it == names.end()) {
      throw InputError(
          file, key,
          fmt::format("unknown category \"{}\"; the library has {}", name, known_names(names)));
    }
    return it->second;
  }
  throw InputError(file, key, "expected a category name (string) or id (integer)");
}

std::int64_t parse_code(const std::string& text, const std::string& file) {
  std::int64_t code = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), code);
  if (ec != std::errc() || end != text.data() + text.size()) {
    throw InputError(file, "classes." + text, "a land-cover code must be an integer");
  }
  return code;
}

}  // namespace

LandCoverMapping read_landcover_mapping(const fs::path& path) {
  const std::string file = path.string();
  if (!path_exists(path)) throw InputError(file, "", "no such file");
  toml::table doc = parse_toml_file(file);
  ConfigTable root(doc, file, "");
  LandCoverMapping m;
  m.source_file = file;
  std::optional<ConfigTable> head = root.subtable("mapping");
  if (!head) root.fail("mapping", "missing the [mapping] table");
  m.name = head->get_string_or("name", path.stem().string());
  std::map<std::string, std::uint16_t> names;
  if (auto lib = head->get_string_opt("library")) {
    m.library = resolve_library(*lib, path).string();
    names = library_names(m.library, file);
  }
  if (head->has("default")) {
    m.default_category = category_of(head->raw("default"), names, file, "mapping.default");
  }
  if (head->has("fill")) {
    m.fill_category = category_of(head->raw("fill"), names, file, "mapping.fill");
  }
  if (head->has("nodata")) {
    for (double v : head->get_double_array("nodata")) {
      // Codes are raster values read as doubles: integers up to 2^53 are
      // exact there, and a larger one (or infinity) has no integer code.
      if (v != std::floor(v) || !(std::fabs(v) <= 9007199254740992.0)) {
        head->fail("nodata", "expected integer codes of at most 2^53 in magnitude");
      }
      m.nodata_codes.insert(static_cast<std::int64_t>(v));
    }
  }
  head->finish();

  std::optional<ConfigTable> classes = root.subtable("classes");
  if (!classes) root.fail("classes", "missing the [classes] table (code = category)");
  const toml::table* table = doc["classes"].as_table();
  for (const auto& [key, node] : *table) {
    const std::string code_text(key.str());
    const std::int64_t code = parse_code(code_text, file);
    classes->mark_used(code_text);
    m.classes[code] = category_of(&node, names, file, "classes." + code_text);
  }
  if (m.classes.empty()) root.fail("classes", "maps no code");
  classes->finish();
  root.finish();
  return m;
}

std::uint16_t resolve_category(const LandCoverMapping& mapping, const std::string& name_or_id,
                               const std::string& key) {
  std::map<std::string, std::uint16_t> names;
  if (!mapping.library.empty()) names = library_names(mapping.library, mapping.source_file);
  return parse_category(name_or_id, names, key);
}

std::uint16_t parse_category(const std::string& name_or_id,
                             const std::map<std::string, std::uint16_t>& names,
                             const std::string& key) {
  std::int64_t id = 0;
  const auto [end, ec] =
      std::from_chars(name_or_id.data(), name_or_id.data() + name_or_id.size(), id);
  if (ec == std::errc() && end == name_or_id.data() + name_or_id.size()) {
    toml::value<std::int64_t> v(id);
    return category_of(&v, names, "", key);
  }
  toml::value<std::string> v(name_or_id);
  return category_of(&v, names, "", key);
}

LandCoverStats apply_landcover(Scene& scene, const fs::path& landcover_path,
                               const LandCoverMapping& mapping) {
  const std::string lc = landcover_path.string();
  if (scene.crs_wkt.empty()) {
    throw InputError(lc, "", "the scene has no CRS, so the land cover cannot be placed on it");
  }
  GdalDataset ds = open_raster(lc);
  const OGRSpatialReferenceH own = GDALGetSpatialRef(handle(ds));
  std::array<double, 6> gt{};
  if (own == nullptr || OGRSpatialReference::FromHandle(own)->IsEmpty() ||
      GDALGetGeoTransform(handle(ds), gt.data()) != CE_None) {
    throw InputError(lc, "crs",
                     "the land cover has no CRS or geotransform, so it cannot be placed on "
                     "the DEM (assign one with gdal_edit.py -a_srs / -a_ullr)");
  }
  OGRSpatialReference lc_srs = *OGRSpatialReference::FromHandle(own);
  lc_srs.StripVertical();
  lc_srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  OGRSpatialReference scene_srs;
  scene_srs.importFromWkt(scene.crs_wkt.c_str());
  scene_srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);

  // Overlap: the land cover's outline in the scene CRS against the scene.
  const int cols = GDALGetRasterXSize(handle(ds)), rows = GDALGetRasterYSize(handle(ds));
  const auto [sx0, sy0, sx1, sy1] = raster_outline(gt, cols, rows);
  std::unique_ptr<OGRCoordinateTransformation> ct(
      OGRCreateCoordinateTransformation(&lc_srs, &scene_srs));
  std::array<double, 4> e{};
  if (!ct || !ct->TransformBounds(sx0, sy0, sx1, sy1, &e[0], &e[1], &e[2], &e[3], 21)) {
    throw InputError(
        lc, "crs",
        "PROJ cannot transform the land cover's CRS into the scene's: " + last_gdal_error());
  }
  const double scene_x1 = scene.origin_x_m + scene.cols * scene.dx_m;
  const double scene_y0 = scene.origin_y_m - scene.rows * scene.dy_m;
  if (e[0] >= scene_x1 || e[2] <= scene.origin_x_m || e[1] >= scene.origin_y_m ||
      e[3] <= scene_y0) {
    throw InputError(lc, "",
                     fmt::format("the land cover does not overlap the DEM: it covers x {:.0f} "
                                 "to {:.0f} m, y {:.0f} to {:.0f} m in the scene CRS, the DEM "
                                 "x {:.0f} to {:.0f} m, y {:.0f} to {:.0f} m",
                                 e[0], e[2], e[1], e[3], scene.origin_x_m, scene_x1, scene_y0,
                                 scene.origin_y_m));
  }

  // Nearest-neighbour resampling of the codes onto the scene grid.
  const WarpGrid grid{scene.crs_wkt, scene.origin_x_m, scene.origin_y_m, scene.dx_m,
                      scene.dy_m,    scene.cols,       scene.rows};
  GdalDataset warped =
      warp_band1(handle(ds), wkt_of(lc_srs), grid, "near", "Int32", std::to_string(kNoCover), lc);
  std::vector<std::int32_t> codes(scene.size());
  if (GDALRasterIO(GDALGetRasterBand(handle(warped), 1), GF_Read, 0, 0, scene.cols, scene.rows,
                   codes.data(), scene.cols, scene.rows, GDT_Int32, 0, 0) != CE_None) {
    throw InputError(lc, "", "cannot read the resampled land cover: " + last_gdal_error());
  }

  // Codes without a category: listed, with cell counts, unless defaulted.
  std::map<std::int64_t, std::size_t> unmapped;
  std::size_t covered = 0;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    const std::int64_t code = codes[i];
    if (code == kNoCover || mapping.nodata_codes.count(code) != 0) continue;
    ++covered;
    if (scene.valid[i] && mapping.classes.count(code) == 0) ++unmapped[code];
  }
  if (covered == 0) {
    throw InputError(lc, "",
                     "the land cover does not overlap the DEM (only no-data where they meet)");
  }
  if (!unmapped.empty() && !mapping.default_category) {
    std::string list;
    for (const auto& [code, n] : unmapped) {
      list += fmt::format("{}{} ({} cells)", list.empty() ? "" : ", ", code, n);
    }
    throw InputError(mapping.source_file, "classes",
                     fmt::format("land-cover codes in {} have no category: {}; add them to "
                                 "[classes] or set [mapping] default",
                                 lc, list));
  }

  // Categories for every valid cell.
  LandCoverStats st;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (!scene.valid[i]) continue;
    const std::int64_t code = codes[i];
    std::uint16_t cat = 0;
    if (code == kNoCover || mapping.nodata_codes.count(code) != 0) {
      if (!mapping.fill_category) {
        scene.valid[i] = 0;
        scene.category[i] = kNoDataCategory;
        ++st.unfilled_cells;
        continue;
      }
      cat = *mapping.fill_category;
      ++st.fill_cells;
    } else if (auto it = mapping.classes.find(code); it != mapping.classes.end()) {
      cat = it->second;
      ++st.mapped_cells;
    } else {
      cat = *mapping.default_category;
      ++st.default_cells;
    }
    scene.category[i] = cat;
    ++st.cells_per_category[cat];
  }
  if (st.unfilled_cells > 0) {
    spdlog::warn(
        "{}: {} DEM cells have no land cover and are masked as no-data (set [mapping] "
        "fill to give them a category)",
        lc, st.unfilled_cells);
  }
  if (st.default_cells > 0) {
    spdlog::info("{}: {} cells of unmapped codes took the default category", lc, st.default_cells);
  }
  st.metadata = {
      {"RIS_LANDCOVER", landcover_path.filename().string()},
      {"RIS_LANDCOVER_MAPPING",
       fmt::format("{} ({})", mapping.name, fs::path(mapping.source_file).filename().string())},
      {"RIS_LANDCOVER_RESAMPLING", "nearest neighbour (GDAL warper)"},
      {"RIS_LANDCOVER_DEFAULT_CELLS", std::to_string(st.default_cells)},
      {"RIS_LANDCOVER_MISSING_CELLS", std::to_string(st.fill_cells + st.unfilled_cells)},
  };
  if (!mapping.library.empty()) {
    st.metadata["RIS_CATEGORY_LIBRARY"] = fs::path(mapping.library).filename().string();
  }
  return st;
}

}  // namespace ris
