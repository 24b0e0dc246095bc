// box: the seed's "cube", a rectangular block of constant height.
//
//   type = "box"
//   x, y      anchor: the block's lower-left (south-west before rotation) corner
//   length    along the block's u axis (east before rotation), > 0
//   width     along the block's v axis (north before rotation), > 0
//   height    > 0
//   rotation  counter-clockwise about the anchor, degrees (default 0)
//   category  category id of the block's footprint
//
// With (u, v) the point in the block's frame (Placement::to_object):
//   h(u, v) = height   for 0 <= u <= length and 0 <= v <= width.
// Volume: length * width * height.
#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

struct Box {
  static constexpr std::string_view kType = "box";
  Placement place;
  double length_m, width_m, height_m;

  Bounds bounds() const { return place.bounds_of(0.0, 0.0, length_m, width_m); }
  bool height_at(double x_m, double y_m, double& h_m) const {
    const auto [u, v] = place.to_object(x_m, y_m);
    if (u < 0.0 || u > length_m || v < 0.0 || v > width_m) return false;
    h_m = height_m;
    return true;
  }
};

}  // namespace

std::unique_ptr<SceneObject> parse_box(ConfigTable& t, const GridExtent&) {
  using namespace object_params;
  const double x = coordinate_m(t, "x");
  const double y = coordinate_m(t, "y");
  Box b{Placement::at(x, y, rotation_rad(t, "rotation")), positive_length_m(t, "length"),
        positive_length_m(t, "width"), positive_length_m(t, "height")};
  return std::make_unique<SolidObject<Box>>(b, category(t, "category"));
}

}  // namespace ris::detail
