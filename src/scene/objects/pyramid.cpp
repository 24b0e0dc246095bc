// pyramid: a regular four-sided pyramid on a square base (the seed's
// PRYAMID); the face slope follows from the height and the base.
//
//   type = "pyramid"
//   x, y      anchor: the base's lower-left (south-west before rotation) corner
//   base      side of the square base, > 0
//   height    apex height, > 0
//   rotation  counter-clockwise about the anchor, degrees (default 0)
//   category  category id of the footprint
//
// With (u, v) in the pyramid's frame and a = base / 2:
//   h(u, v) = height * (1 - max(|u - a|, |v - a|) / a)   for 0 <= u, v <= base.
// Each face rises at atan(height / a). Volume: base^2 * height / 3.
#include <algorithm>
#include <cmath>

#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

struct Pyramid {
  static constexpr std::string_view kType = "pyramid";
  Placement place;
  double base_m, height_m;

  Bounds bounds() const { return place.bounds_of(0.0, 0.0, base_m, base_m); }
  bool height_at(double x_m, double y_m, double& h_m) const {
    const auto [u, v] = place.to_object(x_m, y_m);
    if (u < 0.0 || u > base_m || v < 0.0 || v > base_m) return false;
    const double a = 0.5 * base_m;
    h_m = height_m * (1.0 - std::max(std::abs(u - a), std::abs(v - a)) / a);
    return true;
  }
};

}  // namespace

std::unique_ptr<SceneObject> parse_pyramid(ConfigTable& t, const GridExtent&) {
  using namespace object_params;
  const double x = coordinate_m(t, "x");
  const double y = coordinate_m(t, "y");
  Pyramid p{Placement::at(x, y, rotation_rad(t, "rotation")), positive_length_m(t, "base"),
            positive_length_m(t, "height")};
  return std::make_unique<SolidObject<Pyramid>>(p, category(t, "category"));
}

}  // namespace ris::detail
