#include "sim/stream/scene_row_passes.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "ris/image/geocode.h"
#include "ris/image/geocoded_grey.h"
#include "ris/io/raster_io.h"

namespace ris::detail {

namespace {

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

}  // namespace

SceneRowBands::SceneRowBands(const SceneStreamReader& in, int band_rows)
    : in_(in), band_rows_(band_rows) {
  const std::size_t cap = sz(band_rows) * sz(in.grid().cols);
  z_.resize(cap);
  cat_.resize(cap);
  ok_.resize(cap);
}

RowBand SceneRowBands::read(int b) {
  const Scene& g = in_.grid();
  RowBand k;
  k.r0 = b * band_rows_;
  k.rows = std::min(band_rows_, g.rows - k.r0);
  in_.read(k.r0, k.rows, 0, g.cols, z_.data(), cat_.data(), ok_.data());
  return k;
}

// ---- Pass 1m -----------------------------------------------------------

SceneMapsPass::SceneMapsPass(const SceneStreamReader& in, int band_rows, const SlarSimulation& sim,
                             std::filesystem::path spill_dir, int fail_block,
                             FloatRankSelect& elevation, GeoTiffBlockWriter<std::uint8_t>* mask_out,
                             GeoTiffBlockWriter<float>* incidence_out)
    : SceneRowBands(in, band_rows),
      dir_(std::move(spill_dir)),
      fail_block_(fail_block),
      elevation_(elevation),
      mask_out_(mask_out),
      incidence_out_(incidence_out),
      maps_(in.grid(), sim.geometry, sim.image.range.near_m, sim.image.range.far_m()) {}

RowBand SceneMapsPass::compute(int b) {
  if (b == fail_block_) {
    throw std::runtime_error(
        fmt::format("scene maps block {}: a failure injected by RIS_FAIL_MAPS_BLOCK", b));
  }
  if (!mask_ds_) {
    mask_ds_.emplace(open_raster((dir_ / kSpillMaskFile).string()));
    incidence_ds_.emplace(open_raster((dir_ / kSpillIncidenceFile).string()));
  }
  const SpilledValuesReader read_spills = [&](int l0, int nl, int j0, int nj, std::uint8_t* mask,
                                              float* incidence) {
    read_window(handle(*mask_ds_), l0, nl, j0, nj, mask, GDT_Byte, kSpillMaskFile);
    read_window(handle(*incidence_ds_), l0, nl, j0, nj, incidence, GDT_Float32,
                kSpillIncidenceFile);
  };
  RowBand k = read(b);
  const std::size_t nc = sz(k.rows) * sz(in_.grid().cols);
  for (std::size_t i = 0; i < nc; ++i) {
    if (ok_[i] && std::isfinite(z_[i])) elevation_.refine(z_[i]);  // the band's cells
  }
  k.bytes.resize(nc);
  k.values.resize(nc);
  maps_.rows(k.r0, k.rows, ok_.data(), read_spills, k.bytes.data(), k.values.data());
  return k;
}

void SceneMapsPass::consume(int, RowBand& k) {
  mask_out_->write(k.bytes.data(), k.rows);
  incidence_out_->write(k.values.data(), k.rows);
}

void SceneMapsPass::release() {
  mask_ds_.reset();
  incidence_ds_.reset();
}

// ---- Pass 2b -----------------------------------------------------------

SceneGeocodedPass::SceneGeocodedPass(const SceneStreamReader& in, int band_rows,
                                     const SlarSimulation& sim, const GreytoneMap& map,
                                     std::filesystem::path slant_dir, int fail_block,
                                     GeoTiffBlockWriter<float>* power_out,
                                     GeoTiffBlockWriter<std::uint8_t>* grey_out, ProgressBar& bar)
    : SceneRowBands(in, band_rows),
      sim_(sim),
      map_(map),
      dir_(std::move(slant_dir)),
      fail_block_(fail_block),
      power_out_(power_out),
      grey_out_(grey_out),
      bar_(bar),
      pix_line_(z_.size()),
      pix_bin_(z_.size()) {}

RowBand SceneGeocodedPass::compute(int b) {
  const double t0 = process_cpu_seconds();
  if (b == fail_block_) {
    throw std::runtime_error(
        fmt::format("geocoding block {}: a failure injected by RIS_FAIL_GEO_BLOCK", b));
  }
  if (!sp_ds_) {
    sp_ds_.emplace(open_raster((dir_ / "speckled_power_slant.tif").string()));
    mask_ds_.emplace(open_raster((dir_ / "mask_slant.tif").string()));
  }
  RowBand k = read(b);
  const std::size_t nc = sz(k.rows) * sz(in_.grid().cols);
  k.values.assign(nc, std::numeric_limits<float>::quiet_NaN());
  k.bytes.assign(nc, std::uint8_t{0});
  geocode_rows(k.r0, k.rows, k.values.data(), k.bytes.data());
  cpu_.compute += process_cpu_seconds() - t0;
  ++cpu_.computed;
  return k;
}

void SceneGeocodedPass::consume(int, RowBand& k) {
  const double t0 = process_cpu_seconds();
  power_out_->write(k.values.data(), k.rows);
  grey_out_->write(k.bytes.data(), k.rows, 0, geocoded_validity(k.values).data());
  bar_.advance(static_cast<std::int64_t>(k.values.size()));
  cpu_.consume += process_cpu_seconds() - t0;
}

// Scene rows [r0, r0 + n) (read into z_, ok_): each cell's pixel, then the
// window of the image they need read back, its greytones, and each cell's
// power and greytone.
void SceneGeocodedPass::geocode_rows(int r0, int n, float* out_power, std::uint8_t* out_grey) {
  const Scene& grid = in_.grid();
  const SlarImage& img = sim_.image;
  const int cols = grid.cols;
  const std::size_t nc = sz(n) * sz(cols);
  int l_lo = img.lines, l_hi = -1, b_lo = img.bins, b_hi = -1;
  for (int r = r0; r < r0 + n; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = sz(r - r0) * sz(cols) + sz(c);
      int line = -1, bin = -1;
      if (!(ok_[i] && geocode_pixel(grid, sim_.track, img, r, c, z_[i], line, bin))) {
        line = -1;
      } else {
        l_lo = std::min(l_lo, line);
        l_hi = std::max(l_hi, line);
        b_lo = std::min(b_lo, bin);
        b_hi = std::max(b_hi, bin);
      }
      pix_line_[i] = line;
      pix_bin_[i] = bin;
    }
  }
  if (l_hi < 0) return;
  const int wl = l_hi - l_lo + 1, wb = b_hi - b_lo + 1;
  const std::size_t np = sz(wl) * sz(wb);
  speckled_.resize(np);
  mask_.resize(np);
  read_window(handle(*sp_ds_), l_lo, wl, b_lo, wb, speckled_.data(), GDT_Float32,
              "speckled_power_slant.tif");
  read_window(handle(*mask_ds_), l_lo, wl, b_lo, wb, mask_.data(), GDT_Byte, "mask_slant.tif");
  std::vector<std::uint8_t> no_data(np), grey(np);
  for (std::size_t i = 0; i < np; ++i) no_data[i] = (mask_[i] & pixel_flag::kNoData) ? 1 : 0;
  greytones(speckled_, grey, map_, no_data);
  for (std::size_t i = 0; i < nc; ++i) {
    if (pix_line_[i] < 0) continue;
    const std::size_t p = sz(pix_line_[i] - l_lo) * sz(wb) + sz(pix_bin_[i] - b_lo);
    out_power[i] = speckled_[p];
    out_grey[i] = grey[p];
  }
}

}  // namespace ris::detail
