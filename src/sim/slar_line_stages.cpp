#include "sim/slar_line_stages.h"

#include <algorithm>
#include <cmath>

#include "ris/util/units.h"

namespace ris::detail {

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

// Image formation's per-line step (as form_slar_image).
std::int64_t accumulate_line(const SlarElementContext& ctx, int samples, LineScratch& s,
                             SlarLineProfiles& prof, int line, SlarLineCounts& counts,
                             double range_window_bins, int first_sample) {
  const std::size_t row = prof.index(line, 0);
  const LineElements e{
      samples,           s.flags.data(),     s.range.data(),           s.near_end.data(),
      s.far_end.data(),  s.incidence.data(), s.local_incidence.data(), s.area.data(),
      s.category.data(), first_sample};
  const LineProfileRow out{prof.touch.data() + row, prof.mapped_count.data() + row,
                           prof.visible_count.data() + row, s.acc.acc.data(),
                           s.acc.acc_area.data()};
  const LineElementTally t = form_line_profile(ctx, e, s.elements, out, nullptr);
  counts.nodata += t.nodata;
  counts.shadow += t.shadow;
  counts.back_facing += t.back_facing;
  counts.layover += t.layover;
  counts.r_min_m = std::min(counts.r_min_m, t.r_min_m);
  counts.r_max_m = std::max(counts.r_max_m, t.r_max_m);
  if (range_window_bins > 0.0) s.acc.apply_range_window(range_window_bins);
  for (int b = 0; b < prof.bins; ++b) {
    const std::size_t bb = static_cast<std::size_t>(b);
    prof.power_w[row + bb] = static_cast<float>(s.acc.acc[bb]);
    prof.area_m2[row + bb] = static_cast<float>(s.acc.acc_area[bb]);
  }
  return t.in_swath;
}

}  // namespace ris::detail
