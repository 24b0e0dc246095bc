// cylinder: half of a circular cylinder lying on its side, its axis on the
// base plane (the seed's CYL).
//
//   type = "cylinder"
//   x, y      anchor: one end of the centre line (the axis)
//   radius    > 0 (also the height of the crest)
//   length    along the axis, > 0
//   rotation  direction of the axis, counter-clockwise from east about the
//             anchor, degrees (default 0: the axis runs east)
//   category  category id of the footprint
//
// With (u, v) in the cylinder's frame (u along the axis, v across it):
//   h(u, v) = sqrt(radius^2 - v^2)   for 0 <= u <= length and |v| <= radius.
// Volume: pi radius^2 length / 2.
#include <cmath>

#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

struct Cylinder {
  static constexpr std::string_view kType = "cylinder";
  Placement place;
  double radius_m, length_m;

  Bounds bounds() const { return place.bounds_of(0.0, -radius_m, length_m, radius_m); }
  bool height_at(double x_m, double y_m, double& h_m) const {
    const auto [u, v] = place.to_object(x_m, y_m);
    if (u < 0.0 || u > length_m || std::abs(v) > radius_m) return false;
    h_m = std::sqrt(radius_m * radius_m - v * v);
    return true;
  }
};

}  // namespace

std::unique_ptr<SceneObject> parse_cylinder(ConfigTable& t, const GridExtent&) {
  using namespace object_params;
  const double x = coordinate_m(t, "x");
  const double y = coordinate_m(t, "y");
  Cylinder c{Placement::at(x, y, rotation_rad(t, "rotation")), positive_length_m(t, "radius"),
             positive_length_m(t, "length")};
  return std::make_unique<SolidObject<Cylinder>>(c, category(t, "category"));
}

}  // namespace ris::detail
