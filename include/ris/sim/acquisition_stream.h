// An acquisition run (ris/sim/acquisition_simulation.h) streamed: the radar
// grid's window in blocks of azimuth lines, each block's lines through the
// line engine with the acquisition's source (src/sim/sources/acquisition_lines.h),
// and every product written block by block into tiled GeoTIFFs in a staged
// output folder (ris/io/atomic_file.h: a failure leaves nothing behind).
// The products are the in-memory run's files, byte for byte
// (simulate_acquisition + render_slar + write_acquisition_products; tested),
// and the window has no 50 M-pixel cap.
//
// Memory: per block of B lines, B x bins range profiles and radar-grid
// layers, the DEM's postings under the block's lines (read as a window of
// the file, and the land cover on them), the azimuth integrator's running
// sums, one profile's scratch per thread and one strip of tiles per output
// file. The DEM is never held whole: its height range, vertical datum and
// land-cover categories come from a pass over it in bands of rows. The
// land cover (a ris scene) is held whole. The block length comes from
// SlarStreamOptions (block_lines, or the memory budget).
//
// Passes: 1 lines in blocks (terrain profiles, image formation, the
// radar-grid layers local_incidence and layover_shadow_mask; azimuth
// integration, fading and the slant products as lines become ready); 1b
// the median mean power read back (automatic greytone reference); 2 the
// greytones in slant and ground range (src/sim/stream/slant_stream_passes.h, as a
// scene's streamed run).
//
// Under MPI (`mpirun -np N ris simulate --acquisition P --dem D --stream`)
// every rank reads the inputs and sets the run up itself, and reads the DEM
// windows of the blocks it computes; the blocks of
// passes 1 and 2 are computed on any rank (src/sim/engine/block_schedule.h) and
// consumed by rank 0 in line order, which writes every file: the products
// are the single process's bytes.
//
// Example:
//   ris::SlarStreamOptions s;  s.block_lines = 256;
//   ris::EllipsoidalDemFile dem("winnipeg_dem.tif");
//   ris::AcquisitionStreamSummary r =
//       ris::simulate_acquisition_streamed(acq, dem, radar, *sigma0, {}, info, "out", s);
#pragma once

#include <filesystem>

#include "ris/io/ellipsoidal_dem.h"
#include "ris/sim/acquisition_simulation.h"
#include "ris/sim/run_info.h"
#include "ris/sim/slar_stream.h"

namespace ris {

struct AcquisitionStreamSummary {
  // The run's frame and inputs (no radar-grid layers or image arrays: they
  // are on disk); acquisition.sim: layout, counts, image size, ground grid.
  AcquisitionSimulation acquisition;
  int block_lines = 0;
  int blocks = 0;
  // Wall and CPU time of each pass (name, seconds), as SlarStreamSummary.
  std::vector<std::pair<std::string, double>> stage_seconds;
  std::vector<double> stage_cpu_seconds;
  std::vector<std::pair<std::string, double>> cpu_parts;  // pass 1 on rank 0
};

// Throws InputError as simulate_acquisition does (without its window cap),
// and for point targets in `stream` (not placed on an acquisition's grid).
AcquisitionStreamSummary simulate_acquisition_streamed(
    const Acquisition& acq, const EllipsoidalDemFile& dem, const RadarParams& radar,
    const Sigma0Source& sigma0, const AcquisitionSimOptions& options, const SlarRunInfo& info,
    const std::filesystem::path& out_dir, const SlarStreamOptions& stream = {});

}  // namespace ris
