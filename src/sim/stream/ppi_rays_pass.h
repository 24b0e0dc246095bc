// Internal: pass 1 of a streamed PPI as a block pass (sim/engine/block_pass.h):
// blocks of rays computed on any rank (ppi_ray_blocks.h), and on rank 0, in
// ray order, their point targets' results kept and their rays through the
// azimuth integrator (its running sums summed in ray order, as in one
// process: docs/scale.md); the rays it has ready get their switch
// corrections, and those of the sector (the padding rays dropped) are
// counted for the median and written with NaN for no data and fading
// (keyed by seed, bin and sector ray, as render_ppi).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "ris/image/slar_azimuth_integrator.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/sim/ppi_simulation.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/util/progress.h"
#include "ris/util/rank_select.h"
#include "sim/stream/ppi_ray_blocks.h"

namespace ris::detail {

// The B-scope products pass 1 writes (rank 0).
struct PpiRaySinks {
  std::unique_ptr<GeoTiffBlockWriter<float>> mean, speckled;
  std::unique_ptr<GeoTiffBlockWriter<std::uint8_t>> mask;
};

// Rank 0's results of the point targets: per candidate, lit or not and its
// power (filled as blocks are consumed).
struct RayTargetResults {
  std::vector<std::uint8_t> lit;
  std::vector<double> power_w;
};

class PpiRaysPass {
 public:
  using Block = RayBlock;

  // sinks, targets: rank 0's (null on the other ranks); looks: N per bin;
  // power: the median's first pass, counted here; cells: the scene's, for
  // the progress bar.
  PpiRaysPass(PpiRayBlocks& blocks, const PpiSimulation& sim, const RadiometrySetup& rs,
              PpiRaySinks* sinks, RayTargetResults* targets, const std::vector<double>& looks,
              std::uint64_t seed, FloatRankSelect& power, ProgressBar& bar, std::int64_t cells,
              std::vector<RayBlock>& spare);

  int blocks() const { return blocks_.blocks(); }
  Block compute(int b) { return blocks_.compute(b); }
  void pack(const Block& k, std::vector<char>& out) const { pack_ray_block(k, out); }
  Block unpack(const char* p, std::size_t n) const { return unpack_ray_block(p, n); }
  void consume(int b, Block& k);

  // Rank 0, after the last block: every ray emitted (checked), the writers
  // closed.
  void close();
  const RayCounts& counts() const { return counts_; }
  int consumed() const { return consumed_; }

 private:
  void emit_ready();

  PpiRayBlocks& blocks_;
  const PpiSimulation& sim_;
  const RadiometrySetup& rs_;
  PpiRaySinks* sinks_;
  RayTargetResults* targets_;
  const std::vector<double>& looks_;
  const std::uint64_t seed_;
  FloatRankSelect& power_;
  ProgressBar& bar_;
  const std::int64_t cells_;
  std::vector<RayBlock>& spare_;
  std::optional<SlarAzimuthIntegrator> az_;  // rank 0's
  RayCounts counts_;
  int consumed_ = 0;
  std::vector<float> mean_, speckled_;  // reused across blocks
  std::vector<std::uint8_t> mask_;
};

}  // namespace ris::detail
