// Parsers of the object types, one per file in this folder (private to
// src/scene); the table that names them is in src/scene/scene_object.cpp.
#pragma once

#include <memory>

#include "ris/io/config_table.h"
#include "ris/scene/scene_object.h"

namespace ris::detail {

std::unique_ptr<SceneObject> parse_patch(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_box(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_wedge(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_pyramid(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_hemisphere(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_cylinder(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_tower(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_checkerboard(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_building(ConfigTable& t, const GridExtent& grid);
std::unique_ptr<SceneObject> parse_reflector(ConfigTable& t, const GridExtent& grid);

}  // namespace ris::detail
