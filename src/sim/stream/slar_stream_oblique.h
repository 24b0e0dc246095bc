// Internal: the streamed run (ris/sim/slar_stream.h) of a track off the grid
// axes, its two parts beside the grid-axis stream's passes:
//
//  - pass 1, a block of lines (ObliqueBlockLines): each line's samples within
//    the scene (slar_line_span) sampled bilinearly from windows of the scene
//    file: the block's lines cut into segments of samples, each segment's
//    cells (the bounding box of its samples' corner cells, grown by the one
//    cell each side the slopes read) read and turned into texels
//    (sim/engine/texel_window.h), so a block reads only the rows and columns its
//    lines cross, never the whole scene; then the line engine with the
//    in-memory oblique run's stages (sim/sources/slar_oblique_lines.h), with the
//    point targets on the block's lines (LineKeep::targets, from
//    sim/stream/slar_stream_targets.h), as the in-memory run passes its own. Out:
//    the block's profile rows and counts, and each sample's scene-map value
//    (lines x samples; unseen outside a line's span), which the stream spills
//    to temporary rasters in its staging folder.
//  - pass 1m, the scene maps (ObliqueSceneMaps): per block of scene rows,
//    per column tile, each cell's value from the sample nearest its centre
//    (cell_sample), read back from the spilled values in the tile's window of
//    lines and samples; the cells outside the swath as the in-memory run
//    marks them (slar_oblique_lines.cpp fill_outside_swath, scatter_block).
//
// Both give the in-memory oblique run's bytes: the same spans, sampler
// arithmetic, stages and per-cell rule (tests: SlarStream.Oblique*).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/scene/scene_stream.h"
#include "sim/sources/slar_oblique_lines.h"

namespace ris::detail {

// One block of lines' per-sample scene-map values: lines x samples, row k
// for line l0 + k.
struct ObliqueMapValues {
  std::vector<std::uint8_t> mask;
  std::vector<float> incidence_deg;
};

class ObliqueBlockLines {
 public:
  ObliqueBlockLines(const Scene& grid, const SlarGeometry& g, const Sigma0Lut& lut,
                    const SlarImagingParams& p, const std::string& radar_file, int bins);

  // Lines [l0, l1): their terrain read from `in` window by window, then
  // through the line engine into prof (allocated for the lines) and counts;
  // their samples' scene-map values into `maps` (resized). keep (optional):
  // the point targets on the block's lines (LineKeep::targets), found lit or
  // hidden and added to their lines as the in-memory oblique run does.
  void run(const SceneStreamReader& in, int l0, int l1, SlarLineProfiles& prof,
           SlarLineCounts& counts, ObliqueMapValues& maps, const LineKeep* keep = nullptr);

 private:
  void sample_block(const SceneStreamReader& in, int l0, int l1);
  void sample_segment(const SceneStreamReader& in, int k0, int k1, int a, int b);

  const Scene& grid_;
  const SlarGeometry& g_;
  const ObliqueStages stages_;
  const double near_m_, far_m_;
  std::vector<float> u_all_;  // every sample's u, as LineScratch holds it
  std::vector<SlarLineSpan> spans_;
  // The block's sampled terrain, lines x samples (sample j of line l0 + k
  // at k samples + j).
  std::vector<float> height_, dz_dx_, dz_dy_;
  std::vector<std::uint16_t> category_;
  std::vector<std::uint8_t> flags_;
  Scene window_;  // a segment's cells, its buffers reused
};

// The spills of pass 1 (a mask byte and an incidence a sample, lines x
// samples, uncompressed in the staging folder): pass 1m's input, removed
// after it.
inline constexpr const char* kSpillMaskFile = ".oblique_mask.tmp.tif";
inline constexpr const char* kSpillIncidenceFile = ".oblique_incidence.tmp.tif";

// Reads lines [line0, line0 + lines) x samples [j0, j0 + n) of the spilled
// values: mask into `mask`, incidence into `incidence_deg` (row-major).
using SpilledValuesReader = std::function<void(int line0, int lines, int j0, int n,
                                               std::uint8_t* mask, float* incidence_deg)>;

class ObliqueSceneMaps {
 public:
  ObliqueSceneMaps(const Scene& grid, const SlarGeometry& g, double near_m, double far_m);

  // Scene rows [r0, r0 + rows) (their validity in `valid`, rows x cols): the
  // maps of every cell into mask and incidence_deg (rows x cols).
  void rows(int r0, int rows, const std::uint8_t* valid, const SpilledValuesReader& read,
            std::uint8_t* mask, float* incidence_deg);

 private:
  void tile(int r0, int rows, int c0, int c1, const std::uint8_t* valid,
            const SpilledValuesReader& read, std::uint8_t* mask, float* incidence_deg);

  const Scene& grid_;
  const CellSampleFrame frame_;
  const SampleMapValue unseen_;
  std::vector<std::pair<int, int>> swath_;  // the band's rows' swath_cells
  std::vector<std::uint8_t> read_mask_;
  std::vector<std::int32_t> view_mask_;
  std::vector<float> view_incidence_;
};

}  // namespace ris::detail
