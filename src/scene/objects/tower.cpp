// tower: a vertical circular cylinder standing on the base plane (the
// seed's TOWER).
//
//   type = "tower"
//   x, y      centre
//   radius    > 0
//   height    > 0
//   category  category id of the footprint
//
// With d the horizontal distance from the centre:
//   h = height   for d <= radius.
// Volume: pi radius^2 height.
#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

struct Tower {
  static constexpr std::string_view kType = "tower";
  double xc_m, yc_m, radius_m, height_m;

  Bounds bounds() const {
    return {xc_m - radius_m, yc_m - radius_m, xc_m + radius_m, yc_m + radius_m};
  }
  bool height_at(double x_m, double y_m, double& h_m) const {
    const double d2 = (x_m - xc_m) * (x_m - xc_m) + (y_m - yc_m) * (y_m - yc_m);
    if (d2 > radius_m * radius_m) return false;
    h_m = height_m;
    return true;
  }
};

}  // namespace

std::unique_ptr<SceneObject> parse_tower(ConfigTable& t, const GridExtent&) {
  using namespace object_params;
  const double x = coordinate_m(t, "x");
  const double y = coordinate_m(t, "y");
  Tower w{x, y, positive_length_m(t, "radius"), positive_length_m(t, "height")};
  return std::make_unique<SolidObject<Tower>>(w, category(t, "category"));
}

}  // namespace ris::detail
