// reflector: a canonical radar reflector as an exact mesh (issue 32;
// docs/objects.md "Objects in a scene"), traced by the objects layer and
// not painted into the grid.
//
//   type = "reflector"
//   shape     "trihedral" (square plates), "triangular_trihedral",
//             "dihedral", "plate", "sphere", "cylinder"
//   x, y      position of the reflector's origin (a corner's apex, a
//             dihedral's fold, a plate's or sphere's centre)
//   size      > 0: a trihedral's edge, a dihedral's and a plate's height,
//             a sphere's and a cylinder's radius
//   width     > 0 (default size): a dihedral's plate width, a plate's width,
//             a cylinder's length
//   height    of the origin above the terrain (default 0)
//   azimuth   the boresight's direction, counter-clockwise from +x (east),
//             as scene rotations (default 0: facing east)
//   tilt      boresight raised above the horizontal (default 0)
//   roll      rotation about the boresight (default 0)
//   material  a name in the material library (default "pec")
#include <fmt/format.h>

#include "scene/objects/object_types.h"

namespace ris::detail {
namespace {

class Reflector final : public SceneObject {
 public:
  explicit Reflector(CulturalObject c) : c_(std::move(c)) {}
  std::string_view type() const override { return "reflector"; }
  Bounds bounds() const override {
    const double r = std::max(c_.size_m, c_.width_m);
    return {c_.x_m - r, c_.y_m - r, c_.x_m + r, c_.y_m + r};
  }
  // Not painted: a reflector is traced only. Counts as one cell when its
  // origin is on the grid, so the builder warns of one that is not.
  std::size_t paint(Scene& scene, float) const override {
    const double w = scene.cols * scene.dx_m;
    const double h = scene.rows * scene.dy_m;
    return c_.x_m >= 0.0 && c_.x_m <= w && c_.y_m >= 0.0 && c_.y_m <= h ? 1 : 0;
  }
  // The smallest detail is not a cell's business: it is traced exactly.
  double smallest_feature_m() const override { return INFINITY; }
  std::optional<CulturalObject> cultural(float) const override { return c_; }

 private:
  CulturalObject c_;
};

}  // namespace

std::unique_ptr<SceneObject> parse_reflector(ConfigTable& t, const GridExtent&) {
  using namespace object_params;
  CulturalObject c;
  c.kind = CulturalKind::reflector;
  c.source = t.file();
  c.shape = t.get_enum<ReflectorShape>(
      "shape", {{"trihedral", ReflectorShape::trihedral},
                {"triangular_trihedral", ReflectorShape::triangular_trihedral},
                {"dihedral", ReflectorShape::dihedral},
                {"plate", ReflectorShape::plate},
                {"sphere", ReflectorShape::sphere},
                {"cylinder", ReflectorShape::cylinder}});
  c.x_m = coordinate_m(t, "x");
  c.y_m = coordinate_m(t, "y");
  c.size_m = positive_length_m(t, "size");
  c.width_m = t.has("width") ? positive_length_m(t, "width") : c.size_m;
  c.height_above_terrain_m = t.has("height") ? non_negative_length_m(t, "height") : 0.0;
  c.azimuth_rad = rotation_rad(t, "azimuth");
  c.tilt_rad = rotation_rad(t, "tilt");
  c.roll_rad = rotation_rad(t, "roll");
  c.material = t.get_string_or("material", "pec");
  return std::make_unique<Reflector>(std::move(c));
}

}  // namespace ris::detail
