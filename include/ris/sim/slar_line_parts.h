// The data the line engine's parts exchange (ris/sim/slar_line_blocks.h,
// sim/engine/slar_line_engine.h): a source's window of scene cells, a sink's window
// of scene-grid maps, and the per-sample counts the stages add up. Plain
// structs, below both the engine and its stages.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ris/scene/scene.h"

namespace ris {

// A rectangle of scene cells held in memory: global rows [row0, row0 + rows),
// columns [col0, col0 + cols), row-major with `cols` per row.
struct SceneWindow {
  int row0 = 0, col0 = 0, rows = 0, cols = 0;
  const float* elevation_m = nullptr;
  const std::uint16_t* category = nullptr;
  const std::uint8_t* valid = nullptr;

  static SceneWindow whole(const Scene& s) {
    return {0, 0, s.rows, s.cols, s.elevation_m.data(), s.category.data(), s.valid.data()};
  }
  bool holds(int r, int c) const {
    return r >= row0 && r < row0 + rows && c >= col0 && c < col0 + cols;
  }
  std::size_t index(int r, int c) const {
    return static_cast<std::size_t>(r - row0) * static_cast<std::size_t>(cols) +
           static_cast<std::size_t>(c - col0);
  }
};

// Scene-grid outputs for a rectangle of cells (same layout as SceneWindow).
struct SceneMapsWindow {
  int row0 = 0, col0 = 0, rows = 0, cols = 0;
  std::uint8_t* mask = nullptr;
  float* local_incidence_deg = nullptr;
  std::size_t index(int r, int c) const {
    return static_cast<std::size_t>(r - row0) * static_cast<std::size_t>(cols) +
           static_cast<std::size_t>(c - col0);
  }
};

// Each sample's scene-map value (scene_map_sample) of a block of lines,
// row k for line line0 + k, samples wide: what a streamed run of lines not
// one per cell row or column spills, its maps then taken per cell as
// scene_geometry_maps takes them from the kept geometry.
struct SampleMapRows {
  int line0 = 0;
  std::uint8_t* mask = nullptr;
  float* local_incidence_deg = nullptr;
};

// Per-sample counts of SlarGeometry, plus the slant-range extent of the
// samples with data (for the "swath misses the scene" message).
struct SlarLineCounts {
  std::int64_t nodata = 0, shadow = 0, back_facing = 0, layover = 0;
  float r_min_m = 0.0f, r_max_m = 0.0f;  // +inf / -inf when none
  SlarLineCounts();
  void add(const SlarLineCounts& o);
};

}  // namespace ris
