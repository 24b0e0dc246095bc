// Command-line options shared by the commands that run a simulation
// (simulate, serve): --scene, --radar and --backscatter, with the standard
// scene and radar as defaults.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "command_registry.h"

namespace ris::app {

inline void add_run_input_options(CLI::App* cmd, std::string& scene_path, std::string& radar_path,
                                  std::string& backscatter_path, const std::string& scene_help) {
  scene_path = default_scene_path();
  radar_path = default_radar_path();
  cmd->add_option("--scene", scene_path, scene_help)->capture_default_str();
  cmd->add_option("--radar", radar_path, "Radar description (TOML)")->capture_default_str();
  cmd->add_option("--backscatter", backscatter_path,
                  "Backscatter library (.toml) or table (.csv); default: the standard library");
}

}  // namespace ris::app
