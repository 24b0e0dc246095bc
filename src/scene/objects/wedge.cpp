// wedge: a ridge with a sloping front face, a flat top and a sloping back
// face (the seed's WEDGE), extruded along its length.
//
//   type = "wedge"
//   x, y         anchor: the lower-left corner (south-west before rotation),
//                where the front face starts
//   length       extent along the ridge (u axis, east before rotation), > 0
//   height       height of the flat top, > 0
//   front_slope  angle of the front face, 0 < slope < 90 degrees
//   top_width    width of the flat top, >= 0 (0 gives a sharp ridge)
//   back_slope   angle of the back face, 0 < slope < 90 degrees
//   rotation     counter-clockwise about the anchor, degrees (default 0)
//   category     category id of the footprint
//
// The profile runs along v (north before rotation). With
//   v1 = height / tan(front_slope), v2 = v1 + top_width,
//   v3 = v2 + height / tan(back_slope):
//   h = v tan(front_slope)                 for 0 <= v <= v1   (front face)
//   h = height                             for v1 <= v <= v2  (flat top)
//   h = height - (v - v2) tan(back_slope)  for v2 <= v <= v3  (back face)
// for 0 <= u <= length. With rotation 0 the front face looks south; with
// rotation -90 (anchor at the north-west corner) it looks west.
// Volume: length * height * (v1 / 2 + top_width + (v3 - v2) / 2).
#include <cmath>

#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

struct Wedge {
  static constexpr std::string_view kType = "wedge";
  Placement place;
  double length_m, height_m, tan_front, tan_back, v1_m, v2_m, v3_m;

  Bounds bounds() const { return place.bounds_of(0.0, 0.0, length_m, v3_m); }
  bool height_at(double x_m, double y_m, double& h_m) const {
    const auto [u, v] = place.to_object(x_m, y_m);
    if (u < 0.0 || u > length_m || v < 0.0 || v > v3_m) return false;
    if (v < v1_m) {
      h_m = v * tan_front;
    } else if (v <= v2_m) {
      h_m = height_m;
    } else {
      h_m = height_m - (v - v2_m) * tan_back;
    }
    return true;
  }
};

}  // namespace

std::unique_ptr<SceneObject> parse_wedge(ConfigTable& t, const GridExtent&) {
  using namespace object_params;
  const double x = coordinate_m(t, "x");
  const double y = coordinate_m(t, "y");
  Wedge w{};
  w.place = Placement::at(x, y, rotation_rad(t, "rotation"));
  w.length_m = positive_length_m(t, "length");
  w.height_m = positive_length_m(t, "height");
  w.tan_front = std::tan(slope_rad(t, "front_slope"));
  const double top_m = non_negative_length_m(t, "top_width");
  w.tan_back = std::tan(slope_rad(t, "back_slope"));
  w.v1_m = w.height_m / w.tan_front;
  w.v2_m = w.v1_m + top_m;
  w.v3_m = w.v2_m + w.height_m / w.tan_back;
  return std::make_unique<SolidObject<Wedge>>(w, category(t, "category"));
}

}  // namespace ris::detail
