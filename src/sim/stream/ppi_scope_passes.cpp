#include "sim/stream/ppi_scope_passes.h"

#include <gdal.h>

#include <algorithm>
#include <filesystem>

#include "ris/image/ppi_scope.h"
#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "ris/util/error.h"
#include "sim/stream/slant_stream_passes.h"

namespace ris::detail {

namespace {

constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
constexpr int kScopeStripRows = 256;

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

}  // namespace

double ppi_median_mean_power(const PpiReadback& p, FloatRankSelect& power) {
  const std::uint64_t n_power = power.total();
  RIS_CHECK(n_power > 0);
  std::vector<float> mean;
  std::vector<std::uint8_t> mask;
  power.select(median_ranks(n_power, true));
  GdalDataset mean_ds = open_raster(p.dir.path("mean_power_bscope.tif").string());
  GdalDataset mask_ds = open_raster(p.dir.path("mask_bscope.tif").string());
  const int step = p.readback_rays;
  for (int k0 = 0; k0 < p.scan_rays; k0 += step) {
    const int n = std::min(step, p.scan_rays - k0);
    const std::size_t np = sz(n) * sz(p.bins);
    mean.resize(np);
    mask.resize(np);
    read_window(handle(mean_ds), k0, n, 0, p.bins, mean.data(), GDT_Float32,
                "mean_power_bscope.tif");
    read_window(handle(mask_ds), k0, n, 0, p.bins, mask.data(), GDT_Byte, "mask_bscope.tif");
    for (std::size_t i = 0; i < np; ++i)
      if (valid_power(mean[i], mask[i])) power.refine(mean[i]);
  }
  const double median = median_value(power, n_power, true);
  return median;
}

void ppi_bscope_picture(const PpiReadback& p, const GreytoneMap& map) {
  const std::filesystem::path tmp = p.dir.path(".bscope.png.tmp.tif");
  {
    GeoTiffBlockWriter<std::uint8_t> out(tmp, p.bins, p.scan_rays, {""}, nullptr);
    GdalDataset sp_ds = open_raster(p.dir.path("speckled_power_bscope.tif").string());
    GdalDataset mask_ds = open_raster(p.dir.path("mask_bscope.tif").string());
    const int step = p.readback_rays;
    std::vector<float> speckled;
    std::vector<std::uint8_t> mask, no_data, grey;
    for (int k0 = 0; k0 < p.scan_rays; k0 += step) {
      const int n = std::min(step, p.scan_rays - k0);
      const std::size_t np = sz(n) * sz(p.bins);
      speckled.resize(np);
      mask.resize(np);
      read_window(handle(sp_ds), k0, n, 0, p.bins, speckled.data(), GDT_Float32,
                  "speckled_power_bscope.tif");
      read_window(handle(mask_ds), k0, n, 0, p.bins, mask.data(), GDT_Byte, "mask_bscope.tif");
      no_data.resize(np);
      for (std::size_t i = 0; i < np; ++i) no_data[i] = (mask[i] & pixel_flag::kNoData) ? 1 : 0;
      grey.resize(np);
      greytones(speckled, grey, map, no_data);
      out.write(grey.data(), n);
    }
    out.close();
  }
  write_png_gray_from_raster(p.dir.path("bscope.png"), tmp,
                             png_compression_level(p.info.compression));
  std::filesystem::remove(tmp);
}

void ppi_scope_picture(const PpiReadback& p, const GreytoneMap& map, const PpiRasterSpecs& specs) {
  const PpiScopeGrid& sg = p.sim.scope_grid;
  const int size = sg.size;
  const Georef* ref = specs.scope_georeferenced ? &specs.georef : nullptr;
  const std::filesystem::path tmp = p.dir.path(".ppi_scope.png.tmp.tif");
  {
    auto power_out = ppi_product_writer<float>(p.dir, p.info, "ppi_scope_power.tif", size, size,
                                               specs.scope, "speckled_power_w", ref);
    auto mask_out = ppi_product_writer<std::uint8_t>(p.dir, p.info, "ppi_scope_mask.tif", size,
                                                     size, specs.scope, "mask", ref);
    GeoTiffBlockWriter<std::uint8_t> grey_out(tmp, size, size, {""}, nullptr);
    GdalDataset sp_ds = open_raster(p.dir.path("speckled_power_bscope.tif").string());
    GdalDataset mask_ds = open_raster(p.dir.path("mask_bscope.tif").string());
    const int rays = p.scan_rays;
    std::vector<std::int64_t> src;
    std::vector<int> lo(sz(rays)), hi(sz(rays));
    std::vector<std::size_t> offset(sz(rays));
    std::vector<float> power, ray_power;
    std::vector<std::uint8_t> mask, no_data, grey, ray_mask;
    const double rings = p.sim.radar.ppi.ring_spacing_m;
    for (int r0 = 0; r0 < size; r0 += kScopeStripRows) {
      const int n = std::min(kScopeStripRows, size - r0);
      const std::size_t np = sz(n) * sz(size);
      src.resize(np);
      std::fill(lo.begin(), lo.end(), p.bins);
      std::fill(hi.begin(), hi.end(), -1);
#pragma omp parallel for schedule(static)
      for (int r = 0; r < n; ++r)
        for (int c = 0; c < size; ++c)
          src[sz(r) * sz(size) + sz(c)] = ppi_scope_source(sg, r0 + r, c);
      for (std::size_t i = 0; i < np; ++i) {
        if (src[i] < 0) continue;
        const auto ray = sz(src[i] / p.bins);
        const int bin = static_cast<int>(src[i] % p.bins);
        lo[ray] = std::min(lo[ray], bin);
        hi[ray] = std::max(hi[ray], bin);
      }
      std::size_t total = 0;
      for (int k = 0; k < rays; ++k) {
        offset[sz(k)] = total;
        if (hi[sz(k)] >= lo[sz(k)]) total += sz(hi[sz(k)] - lo[sz(k)] + 1);
      }
      ray_power.resize(total);
      ray_mask.resize(total);
      for (int k = 0; k < rays; ++k) {
        if (hi[sz(k)] < lo[sz(k)]) continue;
        const int w = hi[sz(k)] - lo[sz(k)] + 1;
        read_window(handle(sp_ds), k, 1, lo[sz(k)], w, ray_power.data() + offset[sz(k)],
                    GDT_Float32, "speckled_power_bscope.tif");
        read_window(handle(mask_ds), k, 1, lo[sz(k)], w, ray_mask.data() + offset[sz(k)], GDT_Byte,
                    "mask_bscope.tif");
      }
      power.assign(np, kNaNf);
      mask.assign(np, pixel_flag::kNoData);
      for (std::size_t i = 0; i < np; ++i) {
        if (src[i] < 0) continue;
        const auto ray = sz(src[i] / p.bins);
        const std::size_t at = offset[ray] + sz(src[i] % p.bins - lo[ray]);
        power[i] = ray_power[at];
        mask[i] = ray_mask[at];
      }
      no_data.resize(np);
      for (std::size_t i = 0; i < np; ++i) no_data[i] = (mask[i] & pixel_flag::kNoData) ? 1 : 0;
      grey.resize(np);
      greytones(power, grey, map, no_data);
      if (rings > 0.0) {
        for (int r = 0; r < n; ++r)
          for (int c = 0; c < size; ++c)
            if (on_range_ring(sg, r0 + r, c, rings)) grey[sz(r) * sz(size) + sz(c)] = 255;
      }
      power_out->write(power.data(), n);
      mask_out->write(mask.data(), n);
      grey_out.write(grey.data(), n);
    }
    power_out->close();
    mask_out->close();
    grey_out.close();
  }
  write_png_gray_from_raster(p.dir.path("ppi_scope.png"), tmp,
                             png_compression_level(p.info.compression));
  std::filesystem::remove(tmp);
}

}  // namespace ris::detail
