#include "ris/serve/view_link.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ris/image/geocode.h"
#include "ris/util/error.h"

namespace ris {
namespace {

struct Box {
  double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
  void add(double x, double y, double w) {
    x0 = std::min(x0, x);
    y0 = std::min(y0, y);
    x1 = std::max(x1, x + w);
    y1 = std::max(y1, y + w);
  }
  bool empty() const { return !(x1 > x0 && y1 > y0); }
};

// Sample positions covering [lo, hi) of a grid of n cells: at most `count`,
// the first and last cells included.
std::vector<int> samples(double lo, double hi, int n, int count) {
  const int a = std::clamp(static_cast<int>(std::floor(lo)), 0, n - 1);
  const int b = std::clamp(static_cast<int>(std::ceil(hi)) - 1, 0, n - 1);
  std::vector<int> out;
  const int step = std::max(1, (b - a + count - 2) / (count - 1));
  for (int v = a; v < b; v += step) out.push_back(v);
  out.push_back(b);
  return out;
}

nlohmann::json answer(const std::string& view, const Box& b) {
  return {{"view", view}, {"x0", b.x0}, {"y0", b.y0}, {"x1", b.x1}, {"y1", b.y1}};
}

}  // namespace

nlohmann::json linked_region(const RunResult& run, const std::string& from, double x0, double y0,
                             double x1, double y1) {
  if (from != "scene" && from != "slant") {
    throw InputError(
        "request", "from",
        "expected \"scene\" or \"slant\" (the views linked by zoom), got \"" + from + "\"");
  }
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1) ||
      !(x1 > x0) || !(y1 > y0)) {
    throw InputError("request", "x0, y0, x1, y1",
                     "expected a region with x0 < x1 and y0 < y1, all finite");
  }
  const SlarRun* slar = run.in_memory() ? slar_image_run(run) : nullptr;
  if (slar == nullptr) {
    throw InputError("request", "from", "linked zoom needs a SLAR or SAR run's slant image");
  }
  const Scene& scene = *run.scene;
  const SlarImage& image = slar->sim.image;
  const Track& track = slar->sim.track;
  Box box;
  if (from == "scene") {
    for (const int r : samples(y0, y1, scene.rows, 65)) {
      for (const int c : samples(x0, x1, scene.cols, 65)) {
        const std::size_t i = scene.index(r, c);
        int line = 0, bin = 0;
        if (!scene.valid[i] ||
            !geocode_pixel(scene, track, image, r, c, scene.elevation_m[i], line, bin)) {
          continue;
        }
        box.add(bin, line, 1.0);
      }
    }
  } else {
    const int step = std::max(1, (std::max(scene.rows, scene.cols) + 255) / 256);
    for (int r = 0; r < scene.rows; r += step) {
      for (int c = 0; c < scene.cols; c += step) {
        const std::size_t i = scene.index(r, c);
        int line = 0, bin = 0;
        if (!scene.valid[i] ||
            !geocode_pixel(scene, track, image, r, c, scene.elevation_m[i], line, bin)) {
          continue;
        }
        if (bin + 1 > x0 && bin < x1 && line + 1 > y0 && line < y1) box.add(c, r, step);
      }
    }
  }
  if (box.empty()) {
    throw InputError("request", "x0, y0, x1, y1",
                     fmt::format("the region of the {} view images nothing in the {} view", from,
                                 from == "scene" ? "slant" : "scene"));
  }
  return answer(from == "scene" ? "slant" : "scene", box);
}

}  // namespace ris
