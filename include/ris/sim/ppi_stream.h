// A PPI simulation of a scene read from its raster file a window at a time
// (issue 19): the rays in blocks, each block's terrain sampled from windows
// of the scene (ris/scene/scene_stream.h) that cover a sector of its rays
// over a range segment, and every product written block by block into tiled
// GeoTIFFs (ris/io/geotiff_block_writer.h) in a staged output folder (a
// failure leaves nothing behind). The products are the same files, byte for
// byte, as an in-memory run's (simulate_ppi + render_ppi +
// write_ppi_products; tested for both shipped PPI radars, several block
// sizes and 1 and 2 threads).
//
// Exactness: a ray's samples are placed in the whole scene's grid
// coordinates (ppi_ray_line), so each takes the same four cells and
// weights (bilinear_cells with the scene's size) as in memory; the window
// holds every cell a sample's interpolation touches plus one cell around
// them, so each cell's slope (its four neighbours, the scene's edge rule)
// is the in-memory one. The per-ray geometry, image formation and azimuth
// integration are the in-memory code (ppi_ray_geometry, form_line_profile,
// SlarAzimuthIntegrator).
//
// Memory is bounded by the block and the window, not the scene: a block of
// B rays holds B x samples x 46 bytes (sampled terrain and geometry), B x
// bins profiles and the azimuth running sums of B + 2 M rays (M: half the
// beamwidth in rays, plus 2); a window holds at most window_cells cells (23
// bytes each: elevation, category, validity, texel), a range segment of a
// group of rays (one ray's segment at least); the scope is converted a strip
// of 256 rows at a time from the B-scope read back. The samples per ray (the
// far range over half a cell) and the B-scope (rays x bins) depend on the
// radar and the cell size, not on the scene's extent.
//
// Passes: 0 scene statistics (cells with data, categories, lowest and
// highest elevation); 1 rays in blocks: terrain from windows, geometry,
// profiles, azimuth integration, the B-scope's mean power, fading and mask
// written, the median mean power's first pass; 1b the mean power read back
// for the exact median (auto greytone reference; ris/util/rank_select.h);
// 2 the B-scope's greytones (bscope.png); 2b the scope, a strip of rows at a
// time (ppi_scope_power.tif, ppi_scope_mask.tif, ppi_scope.png).
//
// Point targets (PpiStreamOptions::targets) are checked on the scene and
// placed on the padded rays once (their base height read from the four
// cells around each), each block's rays find theirs lit or hidden as the
// in-memory engine does, and rank 0 folds the blocks' results in ray order
// (src/sim/targets/ppi_ray_targets.h): the same returns, hidden names and
// metadata.json as simulate_ppi.
//
// Example:
//   ris::PpiStreamOptions o;  o.block_rays = 64;
//   ris::PpiStreamSummary s = ris::simulate_ppi_streamed("big.tif", radar, *sigma0, info, "out",
//   o);
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/fault_plan.h"
#include "ris/sim/point_target.h"
#include "ris/sim/ppi_simulation.h"
#include "ris/sim/run_info.h"

namespace ris {

struct PpiStreamOptions {
  // Rays (with the padding rays) per block; 0: from memory_budget_bytes.
  int block_rays = 0;
  // Scene cells a window may hold; 0: from memory_budget_bytes.
  std::int64_t window_cells = 0;
  // Samples of a range segment (the terrain of a ray is read in segments
  // this long); 0: 2048.
  int segment_samples = 0;
  // What the block buffers and windows may take (bytes).
  std::int64_t memory_budget_bytes = std::int64_t(512) << 20;
  // No progress bar (it shows only on a terminal anyway).
  bool quiet = false;
  // Point targets (ris/sim/point_target.h); InputError for one off the
  // scene or on a no-data cell, as simulate_ppi.
  std::vector<PointTarget> targets;
  // Failures injected for the tests of the failure paths (none by default).
  FaultPlan faults;
};

struct PpiStreamSummary {
  Scene grid;         // the scene's grid (no arrays)
  PpiSimulation sim;  // layout, counts, B-scope size, scope grid (no pixel arrays)
  int block_rays = 0;
  int blocks = 0;
  std::int64_t windows = 0;           // scene windows read by pass 1
  std::int64_t max_window_cells = 0;  // the largest of them
  // Wall time of each pass (name, seconds).
  std::vector<std::pair<std::string, double>> stage_seconds;
};

// Runs the simulation and writes every product of write_ppi_products into
// out_dir (sim.point_returns and sim.hidden_targets set on rank 0). Throws
// InputError for bad input (an unreadable or non-north-up scene, a DEM that
// needs importing, and everything simulate_ppi refuses).
PpiStreamSummary simulate_ppi_streamed(const std::filesystem::path& scene_path,
                                       const RadarParams& radar, const Sigma0Source& sigma0,
                                       const SlarRunInfo& info,
                                       const std::filesystem::path& out_dir,
                                       const PpiStreamOptions& options = {});

}  // namespace ris
