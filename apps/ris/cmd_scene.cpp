// `ris scene`: build, describe and preview scenes.
//
//   ris scene build [SCENE.toml] -o scene.tif   TOML description -> GeoTIFF scene
//   ris scene info [FILE]                       size, cell size, CRS, elevation, categories
//   ris scene preview [FILE] -o preview.png     shaded relief + category colours + legend
//   ris scene objects                           the object types of scene descriptions
//
// FILE is a scene description (.toml) or any raster GDAL reads (a ris scene
// GeoTIFF or an elevation model). Without FILE the standard scene is used.
#include <fmt/format.h>
#include <ogr_srs_api.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "command_registry.h"
#include "ris/image/scene_preview.h"
#include "ris/io/safe_paths.h"
#include "ris/scene/scene_builder.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/scene/scene_stats.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace {

using ris::LoadedScene;

LoadedScene load_scene(const std::string& path, const std::string& categories) {
  return ris::load_scene_source(
      path, categories.empty() ? std::nullopt : std::optional<std::string>(categories));
}

std::string crs_name(const std::string& wkt) {
  if (wkt.empty()) return "none (local frame)";
  OGRSpatialReferenceH srs = OSRNewSpatialReference(wkt.c_str());
  std::string name = "unnamed";
  if (srs != nullptr) {
    const char* n = OSRGetName(srs);
    if (n != nullptr) name = n;
    const char* auth = OSRGetAuthorityName(srs, nullptr);
    const char* code = OSRGetAuthorityCode(srs, nullptr);
    if (auth != nullptr && code != nullptr) name += fmt::format(" ({}:{})", auth, code);
    OSRDestroySpatialReference(srs);
  }
  return name;
}

// The description's buildings and reflectors (ris/scene/cultural_object.h),
// ray traced by ris simulate (docs/objects.md); the first 20 one a line.
void print_cultural_objects(const std::vector<ris::CulturalObject>& objects) {
  if (objects.empty()) return;
  int buildings = 0;
  for (const ris::CulturalObject& o : objects) buildings += o.kind == ris::CulturalKind::building;
  fmt::print("objects (ray traced): {} buildings, {} reflectors\n", buildings,
             objects.size() - static_cast<std::size_t>(buildings));
  for (std::size_t i = 0; i < objects.size() && i < 20; ++i) {
    const ris::CulturalObject& o = objects[i];
    if (o.kind == ris::CulturalKind::building) {
      fmt::print("  {}: {} vertices, {:g} m high on {:g} m, walls {}, roof {}\n", o.label,
                 o.footprint_m.size(), o.height_m, o.base_m, o.wall_material, o.roof_material);
    } else {
      fmt::print(
          "  {}: size {:g} m at ({:g}, {:g}) m, {:g} m up, azimuth {:g} deg, tilt {:g} "
          "deg, {}\n",
          o.label, o.size_m, o.x_m, o.y_m, o.height_above_terrain_m, ris::rad_to_deg(o.azimuth_rad),
          ris::rad_to_deg(o.tilt_rad), o.material);
    }
  }
  if (objects.size() > 20) fmt::print("  ... and {} more\n", objects.size() - 20);
}

void print_info(const std::string& path, const std::string& categories) {
  const LoadedScene loaded = load_scene(path, categories);
  const ris::Scene& s = loaded.scene;
  const std::string title = loaded.name.empty() ? "" : " (" + loaded.name + ")";
  const ris::SceneStats st = ris::scene_stats(s);
  const double ft = ris::kFeetToMetres;
  fmt::print("scene: {}{}\n", path, title);
  fmt::print("size: {} columns x {} rows ({} cells)\n", s.cols, s.rows, s.size());
  fmt::print("cell size: {:g} x {:g} m ({:g} x {:g} ft)\n", s.dx_m, s.dy_m, s.dx_m / ft,
             s.dy_m / ft);
  fmt::print("extent: {:g} x {:g} m ({:g} x {:g} ft)\n", s.cols * s.dx_m, s.rows * s.dy_m,
             s.cols * s.dx_m / ft, s.rows * s.dy_m / ft);
  fmt::print("north-west corner: x = {:g} m, y = {:g} m\n", s.origin_x_m, s.origin_y_m);
  fmt::print("CRS: {}\n", crs_name(s.crs_wkt));
  fmt::print("elevation: {:g} .. {:g} m ({:g} .. {:g} ft), mean {:.4g} m\n", st.min_elevation_m,
             st.max_elevation_m, st.min_elevation_m / ft, st.max_elevation_m / ft,
             st.mean_elevation_m);
  fmt::print("no-data cells: {}\n", st.nodata_cells);
  fmt::print("categories: {} (id: cells, share of valid cells)\n", st.category_counts.size());
  for (const auto& [id, n] : st.category_counts) {
    const auto name = loaded.category_names.find(id);
    fmt::print("  {:>5}: {:>9}  {:6.2f}%  {}\n", id, n,
               100.0 * static_cast<double>(n) / static_cast<double>(st.valid_cells),
               name != loaded.category_names.end() ? name->second : "");
  }
  print_cultural_objects(loaded.cultural_objects);
}

struct SceneArgs {
  std::string input = ris::app::default_scene_path();
  std::string categories;  // optional category raster for an elevation raster
  std::string output;
};

void add_input(CLI::App* cmd, SceneArgs& args) {
  cmd->add_option("file", args.input,
                  "Scene description (.toml) or raster (ris scene GeoTIFF or any DEM GDAL "
                  "reads); default: the standard scene")
      ->capture_default_str();
  cmd->add_option("--categories", args.categories,
                  "Category raster on the same grid as an elevation raster");
}

void add_scene(CLI::App& app) {
  auto* scene = app.add_subcommand("scene", "Build, describe and preview scenes");
  scene->require_subcommand(1);

  // scene build
  auto* build = scene->add_subcommand("build", "Build a scene description (TOML) into a GeoTIFF");
  auto build_args = std::make_shared<SceneArgs>();
  build
      ->add_option("scene", build_args->input,
                   "Scene description (.toml); default: the standard scene")
      ->capture_default_str();
  build
      ->add_option("-o,--output", build_args->output,
                   "Output scene: a GeoTIFF (.tif: band 1 elevation in metres, band 2 "
                   "category, both Float32) or, with .vrt, a VRT over a Float32 elevation "
                   "and a UInt16 category GeoTIFF (docs/scene-format.md)")
      ->required();
  build->callback([build_args] {
    if (!ris::is_scene_description(build_args->input)) {
      throw ris::InputError(build_args->input, "",
                            "`scene build` takes a scene description (.toml); to turn a DEM "
                            "into a scene use `ris scene import`");
    }
    const ris::SceneDescription d = ris::read_scene_description(build_args->input);
    ris::require_safe_output_file(build_args->output, "--output");
    const ris::Scene s = ris::build_scene(d);
    // The name and labels travel in the file, so previews of it keep them.
    ris::write_scene_geotiff(s, build_args->output,
                             ris::scene_label_metadata(d.name, d.category_names));
    spdlog::info("wrote {} ({} columns x {} rows)", build_args->output, s.cols, s.rows);
  });

  // scene info
  auto* info = scene->add_subcommand("info", "Describe a scene (.toml or raster)");
  auto info_args = std::make_shared<SceneArgs>();
  add_input(info, *info_args);
  info->callback([info_args] { print_info(info_args->input, info_args->categories); });

  // scene preview
  auto* preview = scene->add_subcommand(
      "preview", "Draw a scene: shaded relief in category colours, with a legend (PNG)");
  auto prev_args = std::make_shared<SceneArgs>();
  add_input(preview, *prev_args);
  preview->add_option("-o,--output", prev_args->output, "Output PNG")->required();
  preview->callback([prev_args] {
    const LoadedScene loaded = load_scene(prev_args->input, prev_args->categories);
    ris::ScenePreviewOptions opt;
    opt.title = loaded.name.empty() ? std::filesystem::path(prev_args->input).filename().string()
                                    : loaded.name;
    opt.category_names = loaded.category_names;
    ris::write_scene_preview(loaded.scene, prev_args->output, opt);
    spdlog::info("wrote {}", prev_args->output);
  });

  // scene objects
  auto* objects = scene->add_subcommand(
      "objects", "List the object types a scene description may use (docs/scene-format.md)");
  objects->callback([] {
    for (const ris::ObjectType& t : ris::object_types()) {
      fmt::print("{:<13} {}\n", t.name, t.summary);
    }
  });
}

const ris::app::Registration reg{"scene", add_scene};

}  // namespace
