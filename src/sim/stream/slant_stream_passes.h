// Internal: what every streamed SLAR / SAR run does with its slant-range
// image, whatever its lines come from (a scene file: ris/sim/slar_stream.h;
// an acquisition's radar grid: ris/sim/acquisition_stream.h). Pass 1's
// blocks of lines as they travel from the rank that computed them to rank 0
// (src/sim/engine/block_schedule.h), the image lines the azimuth integrator makes
// ready, finished and counted for the median; pass 1b (the exact median
// mean power, read back from mean_power_slant.tif) and pass 2 (the
// greytones in slant and ground range, read back from the speckled power).
// Sharing them keeps both runs' products the in-memory run's bytes.
#pragma once

#include <gdal.h>
#include <time.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ris/image/greytone.h"
#include "ris/image/slar_azimuth_integrator.h"
#include "ris/image/slar_image.h"
#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "ris/sim/run_info.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/error.h"
#include "ris/util/process_group.h"
#include "ris/util/progress.h"
#include "ris/util/rank_select.h"
#include "sim/engine/block_schedule.h"
#include "sim/stream/sar_coherent_stream.h"
#include "sim/stream/slar_stream_targets.h"

namespace ris::detail {

// Rows [row0, row0 + rows) x all columns of band 1 of an open raster.
template <typename T>
void read_rows(GDALDatasetH ds, int row0, int rows, T* out, GDALDataType type,
               const std::string& path) {
  const int cols = GDALGetRasterXSize(ds);
  if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, 0, row0, cols, rows, out, cols, rows, type, 0,
                   0) != CE_None) {
    throw InputError(path, "", "cannot read back: " + last_gdal_error());
  }
}

// A window of band 1: rows [row0, row0 + rows) x columns [col0, col0 + cols).
template <typename T>
void read_window(GDALDatasetH ds, int row0, int rows, int col0, int cols, T* out, GDALDataType type,
                 const std::string& path) {
  if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Read, col0, row0, cols, rows, out, cols, rows, type,
                   0, 0) != CE_None) {
    throw InputError(path, "", "cannot read back: " + last_gdal_error());
  }
}

// Exact median of the values counted in pass 1 and refined in pass 2: the
// upper median (nth_element at n / 2) or, with both_middles, the mean of the
// two middle values for an even count (median_valid_power_w).
std::vector<std::uint64_t> median_ranks(std::uint64_t n, bool both_middles);
double median_value(const FloatRankSelect& sel, std::uint64_t n, bool both_middles);

// A pixel counted by the auto greytone reference (ris/image/greytone.h).
inline bool valid_power(float p, std::uint8_t mask) {
  return std::isfinite(p) && p > 0.0f && !(mask & pixel_flag::kNoData);
}

// CPU time of this process (every thread), seconds.
inline double process_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// A pass's CPU time on this process (every thread): computing blocks (how
// many it computed), and consuming them (rank 0: integrating, writing).
struct PassCpu {
  int computed = 0;
  double compute = 0.0, consume = 0.0;
};

// (value, text) as rank 0 has them, on every rank (the median, and the
// staging folder the other ranks read the slant products from).
std::pair<double, std::string> share_from_rank0(ProcessGroup& group, double value,
                                                const std::string& text);

// Azimuth lines per block of a run of `lines` lines taking `per_line_bytes`
// of block buffers a line: `requested` when given (> 0), else what the
// budget holds (16 lines at least). Over several ranks without a request,
// at least 4 blocks a rank, so the queue has blocks to balance (the bytes
// do not depend on the block length).
int stream_block_lines(int lines, std::int64_t per_line_bytes, int requested,
                       std::int64_t budget_bytes, int ranks);

// A block of lines as computed by any rank and consumed, in line order, by
// rank 0: its profile rows, counts and its map values (a scene run's own
// cells' scene-grid maps in the writers' layout; an acquisition's
// radar-grid layers, lines x bins).
struct StreamLineBlock {
  int l0 = 0, l1 = 0;
  SlarLineProfiles prof;
  SlarLineCounts counts;
  std::vector<std::uint8_t> scene_mask;
  std::vector<float> incidence;
  BlockTargets targets;    // its point targets, lit or not
  CoherentBlock coherent;  // the coherent SAR's intensity
};
void pack_line_block(const StreamLineBlock& k, std::vector<char>& out);
// Block b's lines [l0, l1) of `lines` in blocks of block_lines, its counts
// cleared, in a consumed block's buffers when `spare` has one. Throws at
// b == fail_block (FaultPlan::line_block, ris/sim/fault_plan.h: a failure
// injected for the tests).
StreamLineBlock start_line_block(int b, int block_lines, int lines, int fail_block,
                                 std::vector<StreamLineBlock>& spare);
StreamLineBlock unpack_line_block(const char* p, std::size_t n);

// The n image lines the integrator has ready (n = az.lines_ready() > 0):
// their mean power, area and mask (into `mask`), the switch corrections
// and noise applied (finish_slar_image).
SlarImage emit_finished_lines(SlarAzimuthIntegrator& az, int n, SlarSimulation& sim,
                              const SwitchedRadarTerms& terms, std::vector<std::uint8_t>& mask);

// The finished lines' mean power as written: the valid pixels counted for
// the median (pass 1 of power), NaN for no data.
void count_and_blank_no_data(const SlarImage& block, const std::vector<std::uint8_t>& mask,
                             FloatRankSelect& power, std::vector<float>& mean);

// What metadata.json says of the pictures (make_greytone_image's map, N
// per bin and the fading seed), as render_slar's SlarPictures.
SlarPictures picture_metadata(const GreytoneMap& map, std::uint64_t seed,
                              const std::vector<double>& looks);

// What passes 1b and 2 read and write. dir and the writes: rank 0's (null
// elsewhere). extra_metadata: added to the pictures' GeoTIFFs (an
// acquisition's grid).
struct SlantImagePasses {
  ProcessGroup& group;
  const BlockOrder& order;
  const SlarSimulation& sim;  // image layout, ground grid
  const SlarRunInfo& info;
  int block_lines = 0;
  StagedDirectory* dir = nullptr;
  ProgressBar* bar = nullptr;
  RasterMetadata extra_metadata;
  const Georef* slant_georef = nullptr;  // the slant-range GCPs (slant_range.tif)
  // The progress bar's units pass 2 stands for, spread over its lines.
  std::int64_t bar_units = 0;
};

// Each pass's wall and CPU time (into a stream's summary) and the progress
// bar's stage name.
class StageClock {
 public:
  StageClock(std::vector<std::pair<std::string, double>>& seconds, std::vector<double>& cpu)
      : seconds_(seconds), cpu_(cpu) {}
  void start(const std::string& name, ProgressBar& bar);
  void done();

 private:
  std::vector<std::pair<std::string, double>>& seconds_;
  std::vector<double>& cpu_;
  std::chrono::steady_clock::time_point mark_;
  double cpu_mark_ = 0.0;
};

// Pass 1b on rank 0: the median of the `power` counted in pass 1, refined
// over mean_power_slant.tif read back, timed as a stage of its own; NaN
// (no pass) unless the reference is automatic and some pixel counted.
double median_mean_power_pass(const SlantImagePasses& p, FloatRankSelect& power, bool automatic,
                              StageClock& clock);

// Pass 2: the greytones (map) of the speckled power in slant_dir, computed
// in blocks on every rank, written by rank 0: a tiled GeoTIFF when too
// large for a PNG (picture_file), else through a tiled temporary in the
// staging folder (removed before it is committed), then to PNG.
void pictures_pass(const SlantImagePasses& p, const GreytoneMap& map, const std::string& slant_dir);

}  // namespace ris::detail
