// A SLAR simulation of a scene larger than memory: the scene is streamed
// from its raster file in blocks of azimuth lines (ris/io/scene_stream.h),
// each block runs through the fused per-line engine (ris/sim/
// slar_line_blocks.h), and every product is written block by block into
// tiled, compressed GeoTIFFs (ris/io/geotiff_block_writer.h) in a staged
// output folder (ris/io/atomic_file.h: a failure leaves nothing behind). The
// products are the same files, byte for byte, as an in-memory run's
// (simulate_slar + render_slar + write_slar_products; tested).
//
// Memory is bounded by the block, not the scene: a block of B lines holds
// (B + 2) x (cells across) scene cells (elevation, category, validity, mask,
// local incidence: 12 bytes a cell), B x bins range profiles, the azimuth
// running sums of B + 2 M lines (M: half the longest footprint, in lines)
// and one strip of 256 tiles per output file; GDAL's block cache is capped
// at 256 MiB (unless GDAL_CACHEMAX is set). The coherent SAR reads a halo of
// H lines each side of a block (H: the azimuth response's half-length + 2;
// src/sim/stream/sar_coherent_stream.h) and keeps each of those lines' element
// power and slant range (8 bytes a cell, a sample off the axes) and
// range-compressed lines.
//
// Passes (each reads the scene, or an image-sized product, once):
//   0  scene statistics: cells with data, categories used (for the sigma0
//      table), elevation range and highest cell (terrain below the sensor),
//      and the first pass of the exact median elevation (the ground-range
//      reference height; ris/util/rank_select.h);
//   1  lines in blocks: geometry, image formation and scene-grid maps;
//      azimuth integration as lines become ready (ris/image/
//      slar_azimuth_integrator.h); mean power, fading (keyed by seed, bin,
//      line), masks, shadow map and the scene-grid maps written; the median
//      elevation's second pass;
//   1m (a track off the grid axes, or along one with lines not one per
//      cell row or column) the scene-grid maps, scene rows top
//      down, from the samples' map values pass 1 spilled to temporary
//      rasters (pass 1 then samples each block's lines from windows of the
//      scene along them: src/sim/stream/slar_stream_oblique.h); the median
//      elevation's second pass;
//   1b the mean power read back for the exact median (auto greytone
//      reference), when the radar asks for it;
//   2b the geocoded products, scene rows top down, reading back the
//      speckled power;
//   2  greytones (slant and ground range, into PNGs through tiled
//      temporaries).
//
// Under MPI (`mpirun -np N ris simulate --stream`; ris/util/process_group.h,
// docs/scale.md) every rank reads its own windows of the scene: pass 0 is
// split by rows and reduced exactly, the blocks of passes 1, 2b and 2 are
// computed on any rank (src/sim/engine/block_schedule.h) and consumed by rank 0 in
// order (azimuth integration, fading, every write), and pass 1b and the
// PNGs run on rank 0: the products are the single process's bytes.
//
// It runs SLAR and SAR tracks at any heading (along a grid axis with one
// azimuth line per cell row or column, fused_slar_applies; off the axes
// with any line spacing, src/sim/stream/slar_stream_oblique.h; along an axis at
// another spacing, the line engine's per-sample map values spilled for the
// oblique run's pass 1m), with point targets
// (src/sim/stream/slar_stream_targets.h) and the coherent SAR
// (src/sim/stream/sar_coherent_stream.h) at any heading and line spacing (PPI
// streams through ris/sim/ppi_stream.h).
//
// Example:
//   ris::SlarStreamOptions o;  o.block_lines = 512;
//   ris::SlarStreamSummary s = ris::simulate_slar_streamed("big.tif", radar, *sigma0, info, "out",
//   o);
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/fault_plan.h"
#include "ris/sim/point_target.h"
#include "ris/sim/point_target_irf.h"
#include "ris/sim/slar_products.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

struct SlarStreamOptions {
  // Azimuth lines per block; 0: from memory_budget_bytes.
  int block_lines = 0;
  // What the block buffers may take (bytes), when block_lines is 0.
  std::int64_t memory_budget_bytes = std::int64_t(512) << 20;
  // Ground-range reference height; default: the median elevation.
  std::optional<double> reference_height_m;
  // No progress bar (it shows only on a terminal anyway).
  bool quiet = false;
  // Point scatterers added to the scene (ris/sim/point_target.h), as
  // SlarOptions::targets; targets_file names them in metadata.json.
  std::vector<PointTarget> targets;
  std::string targets_file;
  // Failures injected for the tests of the failure paths (none by default).
  FaultPlan faults;
};

struct SlarStreamSummary {
  Scene grid;          // the scene's grid (no arrays)
  SlarSimulation sim;  // layout, counts, image size, ground grid (no pixel arrays)
  int block_lines = 0;
  int blocks = 0;
  // Wall time of each pass (name, seconds), for the user and benchmarks.
  std::vector<std::pair<std::string, double>> stage_seconds;
  // CPU time (user + system, every thread of this process) of each pass,
  // in the same order; and parts of passes 1 and 2b on rank 0 (what rank 0
  // computed, and what it alone does: integrating and writing), for the
  // cost model of docs/scale.md.
  std::vector<double> stage_cpu_seconds;
  std::vector<std::pair<std::string, double>> cpu_parts;
  // With point targets: their measurements, as measure_point_targets gives
  // them (sim.point_returns and sim.hidden_targets are set too).
  std::vector<PointTargetIrf> irfs;
};

// Runs the simulation and writes every product of write_slar_products into
// out_dir. info: as for write_slar_products (info.backscatter_path names the
// sigma0 source in messages). Throws InputError for bad input (an unreadable
// or non-north-up scene, a DEM that needs importing, a track or mode the
// stream does not run, and everything simulate_slar refuses).
SlarStreamSummary simulate_slar_streamed(const std::filesystem::path& scene_path,
                                         const RadarParams& radar, const Sigma0Source& sigma0,
                                         const SlarRunInfo& info,
                                         const std::filesystem::path& out_dir,
                                         const SlarStreamOptions& options = {});

// Whether an in-memory run of a rows x cols scene would not fit: about 28
// bytes a cell (measured) beyond half of physical memory, the limit of
// check_scene_fits_in_memory. `ris simulate` streams then.
bool scene_needs_streaming(std::int64_t rows, std::int64_t cols);

// The memory of an in-memory run of a rows x cols scene (28 bytes a cell,
// checked arithmetic; InputError naming file and key on overflow).
std::int64_t in_memory_run_bytes(std::int64_t rows, std::int64_t cols, const std::string& file,
                                 const std::string& key);

// The temporary files a streamed SLAR or SAR run writes into its
// staging folder beside the products and removes before it ends: for a
// track off the grid axes, or along one with lines not one per cell row or
// column, the samples' scene-map values (azimuth lines x samples x 5 bytes,
// pass 1m's input); 0 along an axis at one line per cell and other modes.
// grid: the scene's grid (SceneStreamReader::grid). Throws InputError
// naming the radar file for a track that cannot be placed (resolve_track).
std::int64_t streamed_temporary_bytes(const Scene& grid, const RadarParams& radar);

}  // namespace ris
