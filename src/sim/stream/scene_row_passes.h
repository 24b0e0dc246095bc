// Internal: the passes of a scene's streamed run over bands of scene rows,
// as block passes (sim/engine/block_pass.h) with RowBand blocks
// (row_band.h): every rank computes bands, rank 0 writes them in row order.
//
//  - SceneMapsPass (pass 1m, a track off the axes or lines not one per
//    cell): each cell's scene-grid maps from the sample nearest its centre,
//    read back from pass 1's spills (slar_stream_oblique.h); the median
//    elevation's second pass over the band's cells.
//  - SceneGeocodedPass (pass 2b): each cell's pixel of the slant-range
//    speckled power (read back from the staging folder every rank sees),
//    its power and greytone.
//
// Each pass opens what it reads back at its first block, so that a rank
// that cannot read rank 0's staging folder (an output folder not on a
// shared file system) fails through the schedule: rank 0 reports it and
// removes its staging folder.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "ris/image/greytone.h"
#include "ris/io/gdal_util.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/scene/scene_stream.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/progress.h"
#include "ris/util/rank_select.h"
#include "sim/stream/row_band.h"
#include "sim/stream/slant_stream_passes.h"
#include "sim/stream/slar_stream_oblique.h"

namespace ris::detail {

// Bands of `band_rows` scene rows, the last one shorter.
class SceneRowBands {
 public:
  SceneRowBands(const SceneStreamReader& in, int band_rows);
  int blocks() const { return (in_.grid().rows + band_rows_ - 1) / band_rows_; }
  // Band b's rows read into z, cat, ok (RowBand r0, rows set).
  RowBand read(int b);
  RowBand unpack(const char* p, std::size_t n) const {
    return unpack_row_band(p, n, in_.grid().cols);
  }
  const float* z() const { return z_.data(); }
  const std::uint8_t* ok() const { return ok_.data(); }

 protected:
  const SceneStreamReader& in_;
  const int band_rows_;
  std::vector<float> z_;
  std::vector<std::uint16_t> cat_;
  std::vector<std::uint8_t> ok_;
};

class SceneMapsPass : public SceneRowBands {
 public:
  using Block = RowBand;
  // spill_dir: rank 0's staging folder; mask_out, incidence_out: rank 0's
  // writers (null elsewhere); fail_block: FaultPlan::maps_block.
  SceneMapsPass(const SceneStreamReader& in, int band_rows, const SlarSimulation& sim,
                std::filesystem::path spill_dir, int fail_block, FloatRankSelect& elevation,
                GeoTiffBlockWriter<std::uint8_t>* mask_out,
                GeoTiffBlockWriter<float>* incidence_out);
  RowBand compute(int b);
  void pack(const RowBand& k, std::vector<char>& out) const { pack_row_band(k, out); }
  void consume(int, RowBand& k);
  // Closes what compute opened (before the spills are removed).
  void release();

 private:
  const std::filesystem::path dir_;
  const int fail_block_;
  FloatRankSelect& elevation_;
  GeoTiffBlockWriter<std::uint8_t>* mask_out_;
  GeoTiffBlockWriter<float>* incidence_out_;
  ObliqueSceneMaps maps_;
  std::optional<GdalDataset> mask_ds_, incidence_ds_;
};

class SceneGeocodedPass : public SceneRowBands {
 public:
  using Block = RowBand;
  // slant_dir: rank 0's staging folder (the slant products); power_out,
  // grey_out: rank 0's writers (null elsewhere); fail_block:
  // FaultPlan::geocoding_block.
  SceneGeocodedPass(const SceneStreamReader& in, int band_rows, const SlarSimulation& sim,
                    const GreytoneMap& map, std::filesystem::path slant_dir, int fail_block,
                    GeoTiffBlockWriter<float>* power_out,
                    GeoTiffBlockWriter<std::uint8_t>* grey_out, ProgressBar& bar);
  RowBand compute(int b);
  void pack(const RowBand& k, std::vector<char>& out) const { pack_row_band(k, out); }
  void consume(int, RowBand& k);
  const PassCpu& cpu() const { return cpu_; }

 private:
  void geocode_rows(int r0, int n, float* out_power, std::uint8_t* out_grey);

  const SlarSimulation& sim_;
  const GreytoneMap map_;
  const std::filesystem::path dir_;
  const int fail_block_;
  GeoTiffBlockWriter<float>* power_out_;
  GeoTiffBlockWriter<std::uint8_t>* grey_out_;
  ProgressBar& bar_;
  PassCpu cpu_;
  std::optional<GdalDataset> sp_ds_, mask_ds_;
  std::vector<std::int32_t> pix_line_, pix_bin_;
  std::vector<float> speckled_;
  std::vector<std::uint8_t> mask_;
};

}  // namespace ris::detail
