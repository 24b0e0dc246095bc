// The one loop every scene object paints with (private to src/scene).
//
// paint_cells visits each cell whose centre lies inside `bounds` (clipped to
// the grid), computes the centre's local-frame coordinates and calls
// `paint(x_m, y_m, elevation, category)`, which returns true when the centre
// is inside the footprint (and then has updated the cell). The functor is a
// template parameter so the per-cell call inlines (DESIGN.md principle 5);
// rows are shared among OpenMP threads and every cell is written by one
// thread only, so the result does not depend on the thread count.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "ris/scene/scene.h"
#include "ris/scene/scene_object.h"

namespace ris::detail {

// The cells paint_cells visits for `b`: rows and columns, inclusive, clipped
// to a grid of rows x cols cells of dx_m x dy_m; empty when the bounds miss
// the grid. Also what the scene builder counts before painting (its work
// estimate, ris/util/resource_guard.h).
struct CellRange {
  int row_begin = 0, row_end = -1, col_begin = 0, col_end = -1;
  std::int64_t cells() const {
    return row_end < row_begin || col_end < col_begin
               ? 0
               : std::int64_t{row_end - row_begin + 1} * (col_end - col_begin + 1);
  }
};

inline CellRange cell_range(int rows, int cols, double dx_m, double dy_m, const Bounds& b) {
  // Cells with centre x in [x_min, x_max]: (c + 0.5) dx in range. One extra
  // cell each side keeps the range conservative against rounding; the
  // functor decides membership exactly.
  const double c0 = std::floor(b.x_min_m / dx_m - 0.5) - 1.0;
  const double c1 = std::ceil(b.x_max_m / dx_m - 0.5) + 1.0;
  const double r0 = std::floor(rows - 0.5 - b.y_max_m / dy_m) - 1.0;
  const double r1 = std::ceil(rows - 0.5 - b.y_min_m / dy_m) + 1.0;
  if (!(c1 >= 0.0 && r1 >= 0.0 && c0 < cols && r0 < rows)) return {};
  return {static_cast<int>(std::max(r0, 0.0)), static_cast<int>(std::min(r1, rows - 1.0)),
          static_cast<int>(std::max(c0, 0.0)), static_cast<int>(std::min(c1, cols - 1.0))};
}

template <typename PaintFn>
std::size_t paint_cells(Scene& scene, const Bounds& b, PaintFn&& paint) {
  const double dx = scene.dx_m;
  const double dy = scene.dy_m;
  const CellRange range = cell_range(scene.rows, scene.cols, dx, dy, b);
  if (range.cells() == 0) return 0;
  const int col_begin = range.col_begin;
  const int col_end = range.col_end;
  const int row_begin = range.row_begin;
  const int row_end = range.row_end;

  std::size_t painted = 0;
#pragma omp parallel for schedule(static) reduction(+ : painted)
  for (int r = row_begin; r <= row_end; ++r) {
    const double y_m = (scene.rows - r - 0.5) * dy;
    float* z = scene.elevation_m.data() + scene.index(r, 0);
    std::uint16_t* cat = scene.category.data() + scene.index(r, 0);
    for (int c = col_begin; c <= col_end; ++c) {
      const double x_m = (c + 0.5) * dx;
      if (paint(x_m, y_m, z[c], cat[c])) ++painted;
    }
  }
  return painted;
}

// The composition rule for a solid of height h_m (above the base plane) at
// one cell: the higher surface wins, the object's category wins.
inline void compose_solid(float& elevation_m, std::uint16_t& category, double base_m, double h_m,
                          std::uint16_t object_category) {
  elevation_m = std::max(elevation_m, static_cast<float>(base_m + h_m));
  category = object_category;
}

// A SceneObject for a solid given by a shape struct with
//   Bounds bounds() const;  bool height_at(double x_m, double y_m, double& h_m) const;
//   static constexpr std::string_view kType;
// and a category.
template <typename Shape>
class SolidObject final : public SceneObject {
 public:
  SolidObject(Shape shape, std::uint16_t category) : shape_(shape), category_(category) {}
  std::string_view type() const override { return Shape::kType; }
  Bounds bounds() const override { return shape_.bounds(); }
  std::size_t paint(Scene& scene, float base_elevation_m) const override {
    const Shape& shape = shape_;
    const std::uint16_t cat = category_;
    const double base_m = base_elevation_m;
    return paint_cells(scene, shape.bounds(),
                       [&](double x_m, double y_m, float& z, std::uint16_t& c) {
                         double h_m = 0.0;
                         if (!shape.height_at(x_m, y_m, h_m)) return false;
                         compose_solid(z, c, base_m, h_m, cat);
                         return true;
                       });
  }
  const Shape& shape() const { return shape_; }

 private:
  Shape shape_;
  std::uint16_t category_;
};

}  // namespace ris::detail
