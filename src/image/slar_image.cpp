#include "ris/image/slar_image.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kernels/image/slar_element.h"
#include "ris/image/slar_azimuth_integrator.h"
#include "ris/image/swath_miss.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

TwoWayGainTable::TwoWayGainTable(const std::function<double(double)>& relative_gain,
                                 double peak_gain, const std::string& radar_file) {
  table_.resize(kSteps + 1);
  uniform_ = !relative_gain;
  for (int i = 0; i <= kSteps; ++i) {
    const double beta = i * kStepRad;
    const double g = (relative_gain ? relative_gain(beta) : 1.0) * peak_gain;
    if (!std::isfinite(g) || g < 0.0) {
      throw InputError(radar_file, "elevation_pattern",
                       fmt::format("gain {} at look angle {:.2f} deg; expected finite and >= 0", g,
                                   rad_to_deg(beta)));
    }
    table_[static_cast<std::size_t>(i)] = g * g;
  }
}

void SlarLineAccumulator::apply_range_window(double window_bins) {
  const int bins = static_cast<int>(acc.size());
  cum[0] = cum_area[0] = 0.0;
  for (std::size_t b = 0; b < acc.size(); ++b) {
    cum[b + 1] = cum[b] + acc[b];
    cum_area[b + 1] = cum_area[b] + acc_area[b];
  }
  const auto integral = [bins](const std::vector<double>& c, double x) {
    const double y = std::clamp(x, 0.0, double(bins));
    const int i = std::min(static_cast<int>(y), bins - 1);
    const std::size_t ii = static_cast<std::size_t>(i);
    return c[ii] + (y - i) * (c[ii + 1] - c[ii]);
  };
  const double half_w = 0.5 * window_bins;
  for (int b = 0; b < bins; ++b) {
    const double lo = b + 0.5 - half_w, hi = b + 0.5 + half_w;
    acc[static_cast<std::size_t>(b)] = integral(cum, hi) - integral(cum, lo);
    acc_area[static_cast<std::size_t>(b)] = integral(cum_area, hi) - integral(cum_area, lo);
  }
}

void SlarLineProfiles::allocate(int lines_, int bins_, int first_line) {
  line0 = first_line;
  lines = lines_;
  bins = bins_;
  const std::size_t n = static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins);
  // power_w and area_m2 are written line by line in full by image formation,
  // so they are not filled here; touch and the counts are accumulated into
  // (|=, +=), so they start at zero, filled by the threads a line at a time
  // (a serial fill of ~5 B per pixel was a serial step of every run).
  power_w.resize(n);
  area_m2.resize(n);
  touch.resize(n);
  mapped_count.resize(n);
  visible_count.resize(n);
  const auto row_bins = static_cast<std::size_t>(bins);
#pragma omp parallel for schedule(static)
  for (int l = 0; l < lines; ++l) {
    const std::size_t at = static_cast<std::size_t>(l) * row_bins;
    std::fill_n(touch.data() + at, row_bins, std::uint8_t{0});
    std::fill_n(mapped_count.data() + at, row_bins, std::uint16_t{0});
    std::fill_n(visible_count.data() + at, row_bins, std::uint16_t{0});
  }
  samples_in_swath = 0;
}

namespace {

void check_inputs(const SlarGeometry& g, const Sigma0Lut& lut, const SlarImagingParams& p,
                  const std::string& radar_file) {
  RIS_CHECK(p.range.count > 0 && p.range.bin_m > 0.0);
  RIS_CHECK(p.azimuth_beamwidth_rad > 0.0);
  // Every category that can be seen must have sigma0 (checked once, not per
  // sample: the LUT lookup itself is unchecked).
  std::vector<std::uint8_t> checked(65536, 0);
  for (std::size_t i = 0; i < g.flags.size(); ++i) {
    if (!sample_visible(g.flags[i])) continue;
    const std::uint16_t c = g.category[i];
    if (checked[c]) continue;
    checked[c] = 1;
    if (!lut.has(c)) {
      throw InputError(radar_file, "category",
                       fmt::format("no backscatter for category {} (the scene uses it)", c));
    }
  }
}

}  // namespace

SlarImage form_slar_image(const SlarGeometry& g, const Sigma0Lut& lut, const SlarImagingParams& p,
                          const std::string& radar_file) {
  check_inputs(g, lut, p, radar_file);
  SlarImage img;
  img.lines = g.lines;
  img.bins = p.range.count;
  img.range = p.range;
  img.line_spacing_m = g.line_spacing_m;

  const TwoWayGainTable gain2(p.elevation_gain, p.peak_gain, radar_file);
  const detail::SlarElementContext ctx = detail::element_context(p, gain2, lut, img.bins);
  const int bins = img.bins;

  // Per-line range profiles before azimuth integration and per-line touch bits.
  SlarLineProfiles prof;
  prof.allocate(img.lines, bins);
  std::int64_t in_swath = 0;

  // Point returns by line (indices into p.point_returns, sorted by line).
  std::vector<std::size_t> target_order(p.point_returns.size());
  for (std::size_t t = 0; t < target_order.size(); ++t) target_order[t] = t;
  std::stable_sort(target_order.begin(), target_order.end(), [&](std::size_t a, std::size_t b) {
    return p.point_returns[a].line < p.point_returns[b].line;
  });
  const bool range_window = p.range_window_bins > 0.0;
  if (p.keep_element_power) img.element_power_w.assign(g.flags.size(), 0.0f);
  img.point_power_w.assign(p.point_returns.size(), 0.0);

#pragma omp parallel reduction(+ : in_swath)
  {
    // Per-thread scratch, allocated once.
    SlarLineAccumulator scratch(bins);
    detail::LineElementScratch elements(g.samples, bins);
#pragma omp for schedule(dynamic, 8)
    for (int line = 0; line < g.lines; ++line) {
      const std::size_t row = prof.index(line, 0);
      const std::size_t i = g.index(line, 0);
      const detail::LineElements e{g.samples,
                                   g.flags.data() + i,
                                   g.slant_range_m.data() + i,
                                   g.range_near_end_m.data() + i,
                                   g.range_far_end_m.data() + i,
                                   g.incidence_rad.data() + i,
                                   g.local_incidence_rad.data() + i,
                                   g.area_m2.data() + i,
                                   g.category.data() + i};
      const detail::LineProfileRow out{prof.touch.data() + row, prof.mapped_count.data() + row,
                                       prof.visible_count.data() + row, scratch.acc.data(),
                                       scratch.acc_area.data()};
      // The coherent SAR needs each visible element's power (ris/sim/sar_coherent.h).
      in_swath +=
          detail::form_line_profile(ctx, e, elements, out,
                                    p.keep_element_power ? img.element_power_w.data() + i : nullptr)
              .in_swath;
      // Point scatterers on this line: their power in the bin of their range.
      const auto first =
          std::lower_bound(target_order.begin(), target_order.end(), line,
                           [&](std::size_t t, int l) { return p.point_returns[t].line < l; });
      for (auto it = first; it != target_order.end() && p.point_returns[*it].line == line; ++it) {
        const PointReturn& pr = p.point_returns[*it];
        const double r2 = pr.slant_range_m * pr.slant_range_m;
        const double power = ctx.k_radar * gain2.at(pr.look_rad) * pr.rcs_m2 / (r2 * r2);
        img.point_power_w[*it] = power;  // each target is on one line: one thread writes it
        const double pos = (pr.slant_range_m - ctx.near_m) * ctx.inv_dr;
        if (!(pos >= 0.0 && pos < bins)) continue;
        scratch.acc[static_cast<std::size_t>(pos)] += power;
      }
      if (range_window) scratch.apply_range_window(p.range_window_bins);
      for (int b = 0; b < bins; ++b) {
        const std::size_t bb = static_cast<std::size_t>(b);
        prof.power_w[row + bb] = static_cast<float>(scratch.acc[bb]);
        prof.area_m2[row + bb] = static_cast<float>(scratch.acc_area[bb]);
      }
    }
  }
  img.samples_in_swath = in_swath;
  if (in_swath == 0) {
    // Where the scene is, for the message.
    float r_min = std::numeric_limits<float>::infinity(), r_max = -r_min;
    for (std::size_t i = 0; i < g.flags.size(); ++i) {
      if (g.flags[i] & (sample_flag::kNoData | sample_flag::kUnseen)) continue;
      r_min = std::min(r_min, g.slant_range_m[i]);
      r_max = std::max(r_max, g.slant_range_m[i]);
    }
    throw_swath_misses_scene(radar_file, p.range, r_min, r_max, "track");
  }

  prof.samples_in_swath = in_swath;
  img.mapped_count = std::move(prof.mapped_count);
  img.visible_count = std::move(prof.visible_count);
  integrate_slar_azimuth(prof, p, g.line_spacing_m, img);
  return img;
}

void integrate_slar_azimuth(const SlarLineProfiles& prof, const SlarImagingParams& p,
                            double line_spacing_m, SlarImage& img) {
  RIS_CHECK(prof.line0 == 0);
  const std::size_t n_pix =
      static_cast<std::size_t>(prof.lines) * static_cast<std::size_t>(prof.bins);
  // emit() writes every pixel: no fill first (UninitVector).
  img.mean_power_w.resize(n_pix);
  img.area_m2.resize(n_pix);
  img.mask.resize(n_pix);
  if (n_pix == 0) return;
  // The streamed step (ris/image/slar_azimuth_integrator.h), fed a block of
  // lines at a time so its running sums stay small. Each thread takes its
  // own range of bins through the whole image (a pixel needs only its bin's
  // column): one parallel region, where one integrator split each block's
  // push and emit over the threads (two barriers per block, each a wait for
  // the slower thread; the same bytes either way).
  const int bins = prof.bins;
#pragma omp parallel
  {
    // Ranges in multiples of four bins (emit's vector blocks).
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    const int quads = (bins + 3) / 4;
    const int b0 = std::min(bins, 4 * static_cast<int>(std::int64_t(quads) * t / nt));
    const int b1 = std::min(bins, 4 * static_cast<int>(std::int64_t(quads) * (t + 1) / nt));
    if (b1 > b0) {
      SlarAzimuthIntegrator az(p, line_spacing_m, prof.lines, bins, b0, b1);
      constexpr int kBlock = 256;
      while (az.lines_emitted() < prof.lines) {
        az.push(prof, std::min(kBlock, prof.lines - az.lines_pushed()));
        const std::size_t at = img.index(az.lines_emitted(), b0);
        az.emit(az.lines_ready(), img.mean_power_w.data() + at, img.area_m2.data() + at,
                img.mask.data() + at, static_cast<std::size_t>(bins));
      }
    }
  }
}

}  // namespace ris
