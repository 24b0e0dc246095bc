// The oblique line run's kernels (kernels/gather/oblique_scatter_kernels.h), moved
// from sim/slar_oblique_lines.cpp unchanged but for their arguments.
#include "kernels/gather/oblique_scatter_kernels.h"

#include <algorithm>

#include "ris/geometry/scene_geometry_maps.h"
#include "ris/kernels/vector_clones.h"

namespace ris::kernels {

namespace {

// round_half_away for the in-range indices of the scatter's inner loop
// (|f| < 2^31): the same integer, through a 32-bit truncation, which GCC
// vectorises (a 64-bit one it does not without AVX-512).
inline int round_half_away_int(double f) {
  const int t = static_cast<int>(f);
  const double d = f - static_cast<double>(t);
  return t + (d >= 0.5 ? 1 : 0) - (d <= -0.5 ? 1 : 0);
}

}  // namespace

// The inner loop has no test (scatter_block has checked the run's ends
// exactly), so it runs without branches.
RIS_VECTOR_CLONES void scatter_run(double lbase, double line_dc, double sbase, double sample_dc,
                                   int c_begin, int c_end, const BlockMapView& b,
                                   const std::uint8_t* __restrict valid,
                                   std::uint8_t* __restrict mask, float* __restrict incidence) {
  const std::int32_t* __restrict vm = b.mask;
  const float* __restrict vi = b.incidence_deg;
  const int lo = b.lo, hi = b.hi, line0 = b.line0, width = b.width;
  for (int c = c_begin; c < c_end; ++c) {
    // The expressions of CellSampleFrame::line_f / sample_f, rounded as
    // nearest_index rounds.
    const int line = round_half_away_int(lbase + c * line_dc);
    const int j0 = round_half_away_int(sbase + c * sample_dc);
    const int j = j0 < lo ? lo : (j0 > hi ? hi : j0);
    const int k = (line - line0) * width + (j - lo);
    // Unconditional loads, so that GCC vectorises with gathers: a cell
    // without data reads entry 0 (a guard column: unseen, NaN incidence)
    // instead of selecting NaN, which GCC would turn into a masked load.
    const int ok = valid[c] != 0 ? 1 : 0;
    mask[c] = static_cast<std::uint8_t>(vm[k] | (ok ? 0 : scene_flag::kNoData));
    incidence[c] = vi[k * ok];
  }
}

// The same cell by cell, with branches (a cell without data: NaN
// incidence as the guard column's).
void scatter_run_scalar(double lbase, double line_dc, double sbase, double sample_dc, int c_begin,
                        int c_end, const BlockMapView& b, const std::uint8_t* valid,
                        std::uint8_t* mask, float* incidence) {
  for (int c = c_begin; c < c_end; ++c) {
    const int line = round_half_away_int(lbase + c * line_dc);
    const int j = std::clamp(round_half_away_int(sbase + c * sample_dc), b.lo, b.hi);
    const int k = (line - b.line0) * b.width + (j - b.lo);
    if (valid[c] != 0) {
      mask[c] = static_cast<std::uint8_t>(b.mask[k]);
      incidence[c] = b.incidence_deg[k];
    } else {
      mask[c] = static_cast<std::uint8_t>(b.mask[k] | scene_flag::kNoData);
      incidence[c] = b.incidence_deg[0];
    }
  }
}

// GCC vectorises the loop (AVX2 clone: twice the lanes of the SSE2 default).
RIS_VECTOR_CLONES void map_values(int n, const std::uint8_t* __restrict flags,
                                  const float* __restrict range,
                                  const float* __restrict local_incidence, double near_m,
                                  double far_m, std::int32_t* __restrict mask,
                                  float* __restrict incidence_deg) {
  for (int k = 0; k < n; ++k) {
    const SampleMapValue v =
        scene_map_sample(flags[k], range[k], local_incidence[k], near_m, far_m);
    mask[k] = v.mask;
    incidence_deg[k] = v.local_incidence_deg;
  }
}

void map_values_scalar(int n, const std::uint8_t* flags, const float* range,
                       const float* local_incidence, double near_m, double far_m,
                       std::int32_t* mask, float* incidence_deg) {
  for (int k = 0; k < n; ++k) {
    const SampleMapValue v =
        scene_map_sample(flags[k], range[k], local_incidence[k], near_m, far_m);
    mask[k] = v.mask;
    incidence_deg[k] = v.local_incidence_deg;
  }
}

}  // namespace ris::kernels
