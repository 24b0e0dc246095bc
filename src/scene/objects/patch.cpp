// patch: a rectangle of one category with no relief (the seed's PATCH), for
// reference greytones beside an object.
//
//   type = "patch"
//   x, y      anchor: the lower-left (south-west before rotation) corner
//   length    along u (east before rotation), > 0
//   width     along v (north before rotation), > 0
//   rotation  counter-clockwise about the anchor, degrees (default 0)
//   category  category id painted where 0 <= u <= length, 0 <= v <= width
//
// The elevation is left as it is (a patch over a hill recolours the hill).
#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

class Patch final : public SceneObject {
 public:
  Patch(Placement place, double length_m, double width_m, std::uint16_t category)
      : place_(place), length_m_(length_m), width_m_(width_m), category_(category) {}
  std::string_view type() const override { return "patch"; }
  Bounds bounds() const override { return place_.bounds_of(0.0, 0.0, length_m_, width_m_); }
  std::size_t paint(Scene& scene, float) const override {
    return paint_cells(scene, bounds(), [this](double x_m, double y_m, float&, std::uint16_t& c) {
      const auto [u, v] = place_.to_object(x_m, y_m);
      if (u < 0.0 || u > length_m_ || v < 0.0 || v > width_m_) return false;
      c = category_;
      return true;
    });
  }

 private:
  Placement place_;
  double length_m_, width_m_;
  std::uint16_t category_;
};

}  // namespace

std::unique_ptr<SceneObject> parse_patch(ConfigTable& t, const GridExtent&) {
  using namespace object_params;
  const double x = coordinate_m(t, "x");
  const double y = coordinate_m(t, "y");
  const Placement place = Placement::at(x, y, rotation_rad(t, "rotation"));
  const double length_m = positive_length_m(t, "length");
  const double width_m = positive_length_m(t, "width");
  return std::make_unique<Patch>(place, length_m, width_m, category(t, "category"));
}

}  // namespace ris::detail
