// hemisphere: the upper half of a sphere resting on the base plane (the
// seed's HEMISP).
//
//   type = "hemisphere"
//   x, y      centre
//   radius    > 0
//   category  category id of the footprint
//
// With d the horizontal distance from the centre:
//   h = sqrt(radius^2 - d^2)   for d <= radius.
// Volume: 2/3 pi radius^3.
#include <cmath>

#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

struct Hemisphere {
  static constexpr std::string_view kType = "hemisphere";
  double xc_m, yc_m, radius_m;

  Bounds bounds() const {
    return {xc_m - radius_m, yc_m - radius_m, xc_m + radius_m, yc_m + radius_m};
  }
  bool height_at(double x_m, double y_m, double& h_m) const {
    const double d2 = (x_m - xc_m) * (x_m - xc_m) + (y_m - yc_m) * (y_m - yc_m);
    const double r2 = radius_m * radius_m;
    if (d2 > r2) return false;
    h_m = std::sqrt(r2 - d2);
    return true;
  }
};

}  // namespace

std::unique_ptr<SceneObject> parse_hemisphere(ConfigTable& t, const GridExtent&) {
  using namespace object_params;
  const double x = coordinate_m(t, "x");
  const double y = coordinate_m(t, "y");
  Hemisphere h{x, y, positive_length_m(t, "radius")};
  return std::make_unique<SolidObject<Hemisphere>>(h, category(t, "category"));
}

}  // namespace ris::detail
