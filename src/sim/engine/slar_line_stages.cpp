#include "sim/engine/slar_line_stages.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

#include "ris/util/error.h"
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

LinePointTargets::LinePointTargets(std::vector<PointCandidate> candidates)
    : by_line(std::move(candidates)), lit(by_line.size(), 0), power_w(by_line.size(), 0.0) {
  std::stable_sort(
      by_line.begin(), by_line.end(),
      [](const PointCandidate& a, const PointCandidate& b) { return a.ret.line < b.ret.line; });
}

// Image formation's per-line step (as form_slar_image).
std::int64_t accumulate_line(const SlarElementContext& ctx, int samples, LineScratch& s,
                             SlarLineProfiles& prof, int line, SlarLineCounts& counts,
                             double range_window_bins, int first_sample, const LineKeep* keep,
                             const SlarGeometry* g,
                             std::span<const SceneQueryStage* const> queries) {
  const std::size_t row = prof.index(line, 0);
  const LineElements e{
      samples,           s.flags.data(),     s.range.data(),           s.near_end.data(),
      s.far_end.data(),  s.incidence.data(), s.local_incidence.data(), s.area.data(),
      s.category.data(), first_sample};
  const LineProfileRow out{prof.touch.data() + row, prof.mapped_count.data() + row,
                           prof.visible_count.data() + row, s.acc.acc.data(),
                           s.acc.acc_area.data()};
  // The row of line in the kept arrays (from line keep->line0).
  const std::size_t kept_at =
      keep ? g->index(line, first_sample) - g->index(keep->line0, 0) : std::size_t{0};
  float* element_power = keep && keep->element_power_w ? keep->element_power_w + kept_at : nullptr;
  if (keep && keep->slant_range_m)
    std::copy_n(s.range.data(), samples, keep->slant_range_m + kept_at);
  const LineElementTally t = form_line_profile(ctx, e, s.elements, out, element_power);
  counts.nodata += t.nodata;
  counts.shadow += t.shadow;
  counts.back_facing += t.back_facing;
  counts.layover += t.layover;
  counts.r_min_m = std::min(counts.r_min_m, t.r_min_m);
  counts.r_max_m = std::max(counts.r_max_m, t.r_max_m);
  if (!queries.empty()) {
    query_line(queries, LineQuery{line, first_sample, samples, *g, s, ctx}, s.acc.acc.data(),
               s.contributions, s.carried);
  }
  if (range_window_bins > 0.0) s.acc.apply_range_window(range_window_bins);
  for (int b = 0; b < prof.bins; ++b) {
    const std::size_t bb = static_cast<std::size_t>(b);
    prof.power_w[row + bb] = static_cast<float>(s.acc.acc[bb]);
    prof.area_m2[row + bb] = static_cast<float>(s.acc.acc_area[bb]);
  }
  if (keep && keep->geometry) keep_line_geometry(*keep->geometry, line, first_sample, samples, s);
  return t.in_swath;
}

void accumulate_channel_lines(std::span<const ExtraChannel> channels,
                              std::span<const SlarElementContext* const> contexts, int samples,
                              LineScratch& s, const SlarLineProfiles& first, int line,
                              int first_sample, const LineKeep* keep, const SlarGeometry* g) {
  const std::size_t row = first.index(line, 0);
  const LineElements e{
      samples,           s.flags.data(),     s.range.data(),           s.near_end.data(),
      s.far_end.data(),  s.incidence.data(), s.local_incidence.data(), s.area.data(),
      s.category.data(), first_sample};
  // The channels' element powers, where kept: this line's row of each.
  std::array<float*, kMaxKeptChannels> kept{};
  std::span<float* const> kept_rows;
  if (keep && g && std::any_of(channels.begin(), channels.end(), [](const ExtraChannel& c) {
        return c.element_power_w != nullptr;
      })) {
    RIS_CHECK(channels.size() <= kept.size());
    const std::size_t at = g->index(line, first_sample) - g->index(keep->line0, 0);
    for (std::size_t k = 0; k < channels.size(); ++k) {
      kept[k] = channels[k].element_power_w ? channels[k].element_power_w + at : nullptr;
    }
    kept_rows = std::span<float* const>(kept.data(), channels.size());
  }
  scatter_channel_elements(contexts, e, s.elements, kept_rows);
  const std::size_t bins = static_cast<std::size_t>(first.bins);
  for (std::size_t k = 0; k < channels.size(); ++k) {
    const ExtraChannel& c = channels[k];
    SlarLineProfiles& prof = *c.prof;
    RIS_CHECK(prof.bins == first.bins && prof.index(line, 0) == row);
    merge_channel(s.elements, static_cast<int>(k), s.acc.acc.data());
    std::copy(s.elements.formed_area.begin(), s.elements.formed_area.end(), s.acc.acc_area.begin());
    if (c.range_window_bins > 0.0) s.acc.apply_range_window(c.range_window_bins);
    for (std::size_t b = 0; b < bins; ++b) {
      prof.power_w[row + b] = static_cast<float>(s.acc.acc[b]);
      prof.area_m2[row + b] = static_cast<float>(s.acc.acc_area[b]);
    }
    // The touch bits and centre counts follow from the geometry alone.
    const auto copy_row = [&](const auto& from, auto& to) {
      std::copy_n(from.begin() + static_cast<std::ptrdiff_t>(row), bins,
                  to.begin() + static_cast<std::ptrdiff_t>(row));
    };
    copy_row(first.touch, prof.touch);
    copy_row(first.mapped_count, prof.mapped_count);
    copy_row(first.visible_count, prof.visible_count);
  }
}

void keep_line_geometry(SlarGeometry& kept, int line, int first, int n, const LineScratch& s) {
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  const std::size_t row = kept.index(line, 0);
  const auto unseen = [&](std::size_t i0, std::size_t i1) {
    for (auto* v :
         {&kept.height_m, &kept.slant_range_m, &kept.incidence_rad, &kept.local_incidence_rad,
          &kept.area_m2, &kept.range_near_end_m, &kept.range_far_end_m}) {
      std::fill(v->begin() + static_cast<std::ptrdiff_t>(i0),
                v->begin() + static_cast<std::ptrdiff_t>(i1), kNaN);
    }
    std::fill(kept.category.begin() + static_cast<std::ptrdiff_t>(i0),
              kept.category.begin() + static_cast<std::ptrdiff_t>(i1), std::uint16_t{0});
    std::fill(kept.flags.begin() + static_cast<std::ptrdiff_t>(i0),
              kept.flags.begin() + static_cast<std::ptrdiff_t>(i1), sample_flag::kUnseen);
  };
  const std::size_t at = row + static_cast<std::size_t>(first);
  const std::size_t end = at + static_cast<std::size_t>(n);
  unseen(row, at);
  unseen(end, row + static_cast<std::size_t>(kept.samples));
  const auto copy = [&](const auto& from, auto& to) {
    std::copy_n(from.begin(), n, to.begin() + static_cast<std::ptrdiff_t>(at));
  };
  copy(s.height, kept.height_m);
  copy(s.range, kept.slant_range_m);
  copy(s.incidence, kept.incidence_rad);
  copy(s.local_incidence, kept.local_incidence_rad);
  copy(s.area, kept.area_m2);
  copy(s.near_end, kept.range_near_end_m);
  copy(s.far_end, kept.range_far_end_m);
  copy(s.category, kept.category);
  copy(s.flags, kept.flags);
}

}  // namespace ris::detail
