// `ris scene`: build, describe and preview scenes.
//
//   ris scene build [SCENE.toml] -o scene.tif   TOML description -> GeoTIFF scene
//   ris scene info [FILE]                       size, cell size, CRS, elevation, categories
//   ris scene preview [FILE] -o preview.png     shaded relief + category colours + legend
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
#include <string>

#include "command_registry.h"
#include "ris/image/scene_preview.h"
#include "ris/io/scene_io.h"
#include "ris/scene/scene_builder.h"
#include "ris/scene/scene_stats.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace {

bool is_toml(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext == ".toml";
}

// A scene from a description (built) or from a raster (read), with the
// description's name and category labels when there is one.
struct LoadedScene {
  ris::Scene scene;
  std::string name;
  std::map<std::uint16_t, std::string> category_names;
};

LoadedScene load_scene(const std::string& path) {
  LoadedScene out;
  if (is_toml(path)) {
    const ris::SceneDescription d = ris::read_scene_description(path);
    out.scene = ris::build_scene(d);
    out.name = d.name;
    out.category_names = d.category_names;
  } else {
    out.scene = ris::read_scene(path);
  }
  return out;
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

void print_info(const std::string& path) {
  const LoadedScene loaded = load_scene(path);
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
}

void add_scene(CLI::App& app) {
  auto* scene = app.add_subcommand("scene", "Build, describe and preview scenes");
  scene->require_subcommand(1);

  // scene build
  auto* build = scene->add_subcommand("build", "Build a scene description (TOML) into a GeoTIFF");
  auto build_in = std::make_shared<std::string>(ris::app::default_scene_path());
  auto build_out = std::make_shared<std::string>();
  build->add_option("scene", *build_in, "Scene description (.toml); default: the standard scene")
      ->capture_default_str();
  build->add_option("-o,--output", *build_out, "Output GeoTIFF (band 1 elevation, band 2 category)")
      ->required();
  build->callback([build_in, build_out] {
    const ris::Scene s = ris::build_scene_file(*build_in);
    ris::write_scene_geotiff(s, *build_out);
    spdlog::info("wrote {} ({} columns x {} rows)", *build_out, s.cols, s.rows);
  });

  // scene info
  auto* info = scene->add_subcommand("info", "Describe a scene (.toml or raster)");
  auto info_in = std::make_shared<std::string>(ris::app::default_scene_path());
  info->add_option("file", *info_in, "Scene description (.toml) or raster; default: standard scene")
      ->capture_default_str();
  info->callback([info_in] { print_info(*info_in); });

  // scene preview
  auto* preview = scene->add_subcommand(
      "preview", "Draw a scene: shaded relief in category colours, with a legend (PNG)");
  auto prev_in = std::make_shared<std::string>(ris::app::default_scene_path());
  auto prev_out = std::make_shared<std::string>();
  preview
      ->add_option("file", *prev_in, "Scene description (.toml) or raster; default: standard scene")
      ->capture_default_str();
  preview->add_option("-o,--output", *prev_out, "Output PNG")->required();
  preview->callback([prev_in, prev_out] {
    const LoadedScene loaded = load_scene(*prev_in);
    ris::ScenePreviewOptions opt;
    opt.title =
        loaded.name.empty() ? std::filesystem::path(*prev_in).filename().string() : loaded.name;
    opt.category_names = loaded.category_names;
    ris::write_scene_preview(loaded.scene, *prev_out, opt);
    spdlog::info("wrote {}", *prev_out);
  });
}

const ris::app::Registration reg{"scene", add_scene};

}  // namespace
