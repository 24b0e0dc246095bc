// Internal: pass 1's consuming half for every streamed run with a
// slant-range image (a scene's: slar_stream.cpp; an acquisition's grid:
// acquisition_stream.cpp). On rank 0, blocks of lines in line order: their
// counts, point targets and coherent intensity kept, their profile rows
// through the azimuth integrator, and the image lines it has ready finished
// (switch corrections, noise), counted for the median, blanked for no data,
// faded (or, for the coherent SAR, its intensity) and written: the
// in-memory run's render_slar + write_slar_products, a block at a time.
// What each run writes besides (scene maps, radar-grid layers) is its own.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "ris/image/slar_azimuth_integrator.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/rank_select.h"
#include "sim/stream/sar_coherent_stream.h"
#include "sim/stream/slant_stream_passes.h"
#include "sim/stream/slar_stream_targets.h"

namespace ris::detail {

// The three slant-range products pass 1 writes, opened by the run (each run
// its own raster specs and georeferencing).
struct SlantImageWriters {
  std::unique_ptr<GeoTiffBlockWriter<float>> mean, speckled;
  std::unique_ptr<GeoTiffBlockWriter<std::uint8_t>> mask;
};

class SlantLineSink {
 public:
  // sim: the run's radar, layout and image (after the set-up); looks: N per
  // range bin (make_greytone_image's); power: the median's first pass,
  // counted here; targets, coherent: the run's, or null.
  SlantLineSink(SlarSimulation& sim, const RadiometrySetup& rs, SlantImageWriters writers,
                std::vector<double> looks, std::uint64_t seed, FloatRankSelect& power,
                StreamTargets* targets, CoherentStream* coherent);

  // Rank 0, blocks in line order: the block's counts, targets and
  // intensity kept, its lines integrated, the lines ready written.
  void take(StreamLineBlock& k);
  // After the last block: every line emitted (checked), the writers closed.
  void close();

  const SlarLineCounts& counts() const { return counts_; }
  std::int64_t samples_in_swath() const { return samples_in_swath_; }

 private:
  void emit_ready();

  SlarSimulation& sim_;
  const RadiometrySetup& rs_;
  SlantImageWriters out_;
  std::vector<double> looks_;
  std::uint64_t seed_;
  FloatRankSelect& power_;
  StreamTargets* targets_;
  CoherentStream* coherent_;
  SlarAzimuthIntegrator az_;
  SlarLineCounts counts_;
  std::int64_t samples_in_swath_ = 0;
  std::vector<float> mean_, speckled_;  // reused across blocks
  std::vector<std::uint8_t> mask_;
};

}  // namespace ris::detail
