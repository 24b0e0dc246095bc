// Internal: pass 1 of a scene's streamed run as a block pass
// (sim/engine/block_pass.h): blocks of lines computed on any rank
// (scene_line_blocks.h), and on rank 0, in line order, their scene-grid
// maps (or pass 1m's spills) and the seed's shadow map written and their
// lines made into the slant-range image (slant_line_sink.h).
#pragma once

#include <cstdint>
#include <fstream>
#include <memory>
#include <optional>
#include <vector>

#include "ris/io/geotiff_block_writer.h"
#include "ris/util/progress.h"
#include "sim/stream/scene_line_blocks.h"
#include "sim/stream/scene_product_writers.h"
#include "sim/stream/slant_line_sink.h"

namespace ris::detail {

// Rank 0's files of pass 1: the slant image (sink), the scene-grid maps (or,
// spilled, each sample's map values) and the shadow map's text.
struct SceneLineSinks {
  std::optional<SlantLineSink> image;
  std::unique_ptr<GeoTiffBlockWriter<std::uint8_t>> scene_mask;
  std::unique_ptr<GeoTiffBlockWriter<float>> incidence;
  std::ofstream shadow_text;
};

// Opens pass 1's files (rank 0); the image sink is the caller's to set.
SceneLineSinks open_scene_line_sinks(SceneProductWriters& w, const Scene& grid,
                                     const SlarSimulation& sim, bool spill_maps);

// Pass 1m (scene_row_passes.h: SceneMapsPass) after pass 1 spilled each
// sample's map values: rank 0 closes the spills (sinks) and opens the
// scene-grid maps (writers); every rank computes its share of the cells
// (reading the spills from rank 0's staging folder, as pass 2b reads the
// slant products); rank 0 writes them in row order and removes the spills.
// writers and sinks: rank 0's (null elsewhere).
void scene_maps_pass(ProcessGroup& group, const BlockOrder& order, const SceneStreamReader& in,
                     int band_rows, const SlarSimulation& sim, int fail_block,
                     FloatRankSelect& elevation, SceneProductWriters* writers,
                     SceneLineSinks* sinks);

class SceneLinesPass {
 public:
  using Block = StreamLineBlock;

  // sinks: rank 0's (null on the other ranks); cross_cells: cells a line
  // stands for on the progress bar.
  SceneLinesPass(SceneLineBlocks& blocks, SceneLineSinks* sinks, ProgressBar& bar, int cross_cells,
                 std::vector<StreamLineBlock>& spare)
      : blocks_(blocks), sinks_(sinks), bar_(bar), cross_cells_(cross_cells), spare_(spare) {}

  int blocks() const { return blocks_.blocks(); }
  Block compute(int b);
  void pack(const Block& k, std::vector<char>& out) const { pack_line_block(k, out); }
  Block unpack(const char* p, std::size_t n) const { return unpack_line_block(p, n); }
  void consume(int b, Block& k);

  // This process's CPU time in the two halves (docs/scale.md's cost model).
  const PassCpu& cpu() const { return cpu_; }
  int consumed() const { return consumed_; }

 private:
  void write_shadow_text(const SlarLineProfiles& prof, int l0, int l1);

  SceneLineBlocks& blocks_;
  SceneLineSinks* sinks_;
  ProgressBar& bar_;
  int cross_cells_;
  std::vector<StreamLineBlock>& spare_;
  PassCpu cpu_;
  int consumed_ = 0;
  std::string text_;
};

}  // namespace ris::detail
