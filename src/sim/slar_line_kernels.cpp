#include "sim/slar_line_kernels.h"

#include <algorithm>
#include <cmath>

#include "ris/util/units.h"

namespace ris::detail {

// The constant part of a run's image formation (as form_slar_image).
SlarElementContext element_context(const SlarImagingParams& p, const TwoWayGainTable& gain2,
                                   const Sigma0Lut& lut, int bins) {
  SlarElementContext ctx;
  ctx.k_radar = p.transmit_power_w * p.wavelength_m * p.wavelength_m / std::pow(4.0 * kPi, 3.0);
  ctx.near_m = p.range.near_m;
  ctx.inv_dr = 1.0 / p.range.bin_m;
  ctx.bins = bins;
  ctx.gain2 = &gain2;
  ctx.lut = &lut;
  return ctx;
}

// The look geometry, element ends, cast shadow and layover of a line whose
// terrain is in the scratch (MODEL.md section 2; the code the stage path
// runs: ris/geometry/line_scan.h).
void line_geometry(const SlarGeometry& g, const LineLookFrame& frame, bool need_incidence,
                   LineScratch& s) {
  const int samples = g.samples;
  look_line({samples, s.u.data(), s.height.data(), s.dz_dx.data(), s.dz_dy.data()}, frame,
            {s.range.data(), need_incidence ? s.incidence.data() : nullptr,
             s.local_incidence.data(), s.area.data(), s.dh_du.data(), s.flags.data()});
  const LineSamples ls{samples,         g.first_sample_u_m, g.sample_step_m,   g.altitude_m,
                       s.height.data(), s.range.data(),     s.near_end.data(), s.far_end.data(),
                       s.dh_du.data(),  s.flags.data()};
  line_element_ends(ls);
  mark_shadow_and_layover(ls);
}

// Image formation's per-line step (as form_slar_image): the line's elements
// into its range profile row; counts into `counts`. Returns the number of
// elements whose centre falls in a bin.
std::int64_t accumulate_line(const SlarElementContext& ctx, int samples, LineScratch& s,
                             SlarLineProfiles& prof, int line, SlarLineCounts& counts,
                             double range_window_bins) {
  constexpr std::uint8_t kSkip = sample_flag::kNoData | sample_flag::kUnseen;
  std::int64_t in_swath = 0;
  std::fill(s.acc.acc.begin(), s.acc.acc.end(), 0.0);
  std::fill(s.acc.acc_area.begin(), s.acc.acc_area.end(), 0.0);
  const std::size_t row = prof.index(line, 0);
  for (int j = 0; j < samples; ++j) {
    const std::size_t jj = static_cast<std::size_t>(j);
    const std::uint8_t sf = s.flags[jj];
    counts.nodata += (sf & sample_flag::kNoData) ? 1 : 0;
    counts.shadow += (sf & sample_flag::kShadow) ? 1 : 0;
    counts.back_facing += (sf & sample_flag::kBackFacing) ? 1 : 0;
    counts.layover += (sf & sample_flag::kLayover) ? 1 : 0;
    if (sf & kSkip) continue;
    counts.r_min_m = std::min(counts.r_min_m, s.range[jj]);
    counts.r_max_m = std::max(counts.r_max_m, s.range[jj]);
    in_swath += detail::accumulate_element(
        ctx, sf, s.range[jj], s.near_end[jj], s.far_end[jj], s.incidence[jj], s.local_incidence[jj],
        s.area[jj], s.category[jj], prof.touch.data() + row, prof.mapped_count.data() + row,
        prof.visible_count.data() + row, s.acc.acc.data(), s.acc.acc_area.data());
  }
  if (range_window_bins > 0.0) s.acc.apply_range_window(range_window_bins);
  for (int b = 0; b < prof.bins; ++b) {
    const std::size_t bb = static_cast<std::size_t>(b);
    prof.power_w[row + bb] = static_cast<float>(s.acc.acc[bb]);
    prof.area_m2[row + bb] = static_cast<float>(s.acc.acc_area[bb]);
  }
  return in_swath;
}

}  // namespace ris::detail
