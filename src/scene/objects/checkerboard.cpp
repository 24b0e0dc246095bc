// checkerboard: squares cycling through a list of categories, no relief
// (the seed's CHKRBD), to compare the categories' returns side by side and
// across the swath.
//
//   type = "checkerboard"
//   square      side of one square, > 0
//   categories  list of category ids, e.g. [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]
//   x, y        anchor: lower-left corner of square (0, 0) (default 0, 0:
//               the grid's south-west corner)
//   length      extent along u (east before rotation), > 0 (default: to the
//               grid's east edge)
//   width       extent along v (north before rotation), > 0 (default: to the
//               grid's north edge)
//   rotation    counter-clockwise about the anchor, degrees (default 0)
//
// Square (i, j) = (floor(u / square), floor(v / square)) gets
//   categories[(i + j) mod n],   n = number of categories,
// so every row and every column of squares runs through all n categories and
// neighbouring squares differ whenever n >= 2 (n = 2 is the classic board).
// The elevation is left as it is.
#include <cmath>
#include <vector>

#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

class Checkerboard final : public SceneObject {
 public:
  Checkerboard(Placement place, double length_m, double width_m, double square_m,
               std::vector<std::uint16_t> categories)
      : place_(place),
        length_m_(length_m),
        width_m_(width_m),
        square_m_(square_m),
        categories_(std::move(categories)) {}
  std::string_view type() const override { return "checkerboard"; }
  Bounds bounds() const override { return place_.bounds_of(0.0, 0.0, length_m_, width_m_); }
  double smallest_feature_m() const override { return square_m_; }
  std::size_t paint(Scene& scene, float) const override {
    const auto n = static_cast<std::int64_t>(categories_.size());
    return paint_cells(scene, bounds(), [&](double x_m, double y_m, float&, std::uint16_t& c) {
      const auto [u, v] = place_.to_object(x_m, y_m);
      if (u < 0.0 || u > length_m_ || v < 0.0 || v > width_m_) return false;
      // The square's index modulo the category count, in doubles: fmod of
      // an integral double is exact, and an index beyond 2^63 (a huge scene
      // of tiny squares) must not reach an integer conversion.
      const double nd = static_cast<double>(n);
      const double k = std::fmod(
          std::fmod(std::floor(u / square_m_), nd) + std::fmod(std::floor(v / square_m_), nd), nd);
      c = categories_[static_cast<std::size_t>(k)];
      return true;
    });
  }

 private:
  Placement place_;
  double length_m_, width_m_, square_m_;
  std::vector<std::uint16_t> categories_;
};

}  // namespace

std::unique_ptr<SceneObject> parse_checkerboard(ConfigTable& t, const GridExtent& grid) {
  using namespace object_params;
  const double square_m = positive_length_m(t, "square");
  std::vector<std::uint16_t> cats = categories(t, "categories");
  const double x = t.has("x") ? coordinate_m(t, "x") : 0.0;
  const double y = t.has("y") ? coordinate_m(t, "y") : 0.0;
  const double length_m = t.has("length") ? positive_length_m(t, "length") : grid.width_m - x;
  const double width_m = t.has("width") ? positive_length_m(t, "width") : grid.height_m - y;
  if (!(length_m > 0.0)) t.fail("x", "the checkerboard starts east of the grid; give a length");
  if (!(width_m > 0.0)) t.fail("y", "the checkerboard starts north of the grid; give a width");
  const Placement place = Placement::at(x, y, rotation_rad(t, "rotation"));
  return std::make_unique<Checkerboard>(place, length_m, width_m, square_m, std::move(cats));
}

}  // namespace ris::detail
