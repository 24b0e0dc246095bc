#include "ris/scene/scene.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cmath>

#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris {

Scene Scene::flat(int rows, int cols, double cell_m, float elevation_m, std::uint16_t category) {
  Scene s;
  s.rows = rows;
  s.cols = cols;
  s.dx_m = cell_m;
  s.dy_m = cell_m;
  s.origin_x_m = 0.0;
  s.origin_y_m = rows * cell_m;
  s.elevation_m.assign(s.size(), elevation_m);
  s.category.assign(s.size(), category);
  s.valid.assign(s.size(), 1);
  return s;
}

void Scene::validate(const std::string& source) const {
  if (rows <= 0 || cols <= 0) {
    throw InputError(source, "", fmt::format("empty raster ({} columns x {} rows)", cols, rows));
  }
  if (!(dx_m > 0.0) || !(dy_m > 0.0) || !std::isfinite(dx_m) || !std::isfinite(dy_m)) {
    throw InputError(source, "",
                     fmt::format("cell size must be positive, got {} x {} m", dx_m, dy_m));
  }
  RIS_CHECK(elevation_m.size() == size());
  RIS_CHECK(category.size() == size());
  RIS_CHECK(valid.size() == size());
}

void check_scene_fits_in_memory(std::int64_t rows, std::int64_t cols, const std::string& source,
                                const std::string& key) {
  if (rows <= 0 || cols <= 0) {
    throw InputError(
        source, key,
        fmt::format("grid size must be positive, got {} columns x {} rows", cols, rows));
  }
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  const double physical = (pages > 0 && page_size > 0) ? double(pages) * double(page_size) : 8e9;
  const double limit = physical / 2.0;
  const double estimate = double(rows) * double(cols) * double(Scene::bytes_per_cell());
  if (estimate > limit && resource_limits_disabled()) {
    spdlog::warn(
        "{}: '{}': a {} x {} grid needs about {:.1f} GiB, above half of physical memory "
        "({:.1f} GiB); going on (RIS_NO_RESOURCE_LIMITS)",
        source, key, cols, rows, estimate / 1073741824.0, limit / 1073741824.0);
    return;
  }
  if (estimate > limit) {
    throw InputError(
        source, key,
        fmt::format("a {} x {} grid needs about {:.1f} GiB for the scene alone; "
                    "refusing (limit {:.1f} GiB, half of physical memory; RIS_NO_RESOURCE_LIMITS=1 "
                    "tries anyway)",
                    cols, rows, estimate / 1073741824.0, limit / 1073741824.0));
  }
}

}  // namespace ris
