// Cultural objects of a scene description (issue 32, docs/objects.md
// "Objects in a scene"): buildings and canonical reflectors, kept as 3-D
// descriptions beside the grid. A building is also painted into the grid
// (its footprint takes its category and its roof height, by the composition
// rule of ris/scene/scene_object.h), so the line engine sees its diffuse
// return, its layover and the shadow it casts; its walls, roof and the
// multiple bounces between them and the ground are traced by the objects
// layer (ris/objects/object_scene.h). A reflector is not painted: it is
// traced only.
//
// Coordinates are the scene's world coordinates (the grid's CRS; a
// description's local frame moved by its origin), metres.
//
// Example:
//   ris::LoadedScene s = ris::load_scene_source("data/scenes/town.toml");
//   for (const ris::CulturalObject& o : s.cultural_objects) std::puts(o.label.c_str());
#pragma once

#include <array>
#include <string>
#include <vector>

namespace ris {

enum class CulturalKind { building, reflector };

// The canonical reflectors (ris/objects/mesh.h builds each as an exact mesh).
enum class ReflectorShape { plate, dihedral, trihedral, triangular_trihedral, sphere, cylinder };

struct CulturalObject {
  CulturalKind kind = CulturalKind::building;
  std::string label;   // "object[3] (building)", for messages
  std::string source;  // the scene file

  // Building: a simple polygon (counter-clockwise, not closed: the last
  // vertex joins the first), a flat roof at base_m + height_m.
  std::vector<std::array<double, 2>> footprint_m;
  double base_m = 0.0;  // elevation of the walls' foot (the grid's base plane)
  double height_m = 0.0;
  std::string wall_material = "concrete";
  std::string roof_material = "concrete";
  std::string ground_material = "concrete";  // the ground the walls stand on

  // Reflector: shape, size (edge, side, radius), width (a dihedral's plate
  // width, a plate's height, a cylinder's length; 0 = size), position of
  // its origin (ris/objects/mesh.h) above the terrain, and its boresight's
  // azimuth (counter-clockwise from +x, as scene rotations), tilt (raised)
  // and roll (about the boresight).
  ReflectorShape shape = ReflectorShape::trihedral;
  double size_m = 0.0;
  double width_m = 0.0;
  double x_m = 0.0, y_m = 0.0;
  double height_above_terrain_m = 0.0;
  double azimuth_rad = 0.0, tilt_rad = 0.0, roll_rad = 0.0;
  std::string material = "pec";
};

// Whether (x, y) lies in a building's footprint (even-odd rule, the
// boundary inside), as the building paints its cells.
bool point_in_footprint(const std::vector<std::array<double, 2>>& footprint_m, double x_m,
                        double y_m);

// The objects moved from a description's local frame (south-west corner at
// (0, 0)) to world coordinates, the south-west corner at (x0_m, y0_m).
void move_to_world(std::vector<CulturalObject>& objects, double x0_m, double y0_m);

}  // namespace ris
