// Kernels of the fused run for a track off the grid axes
// (sim/slar_oblique_lines.cpp): a block of lines' scene-map values, and
// their scatter into a run of a scene row's cells. Vector clones (AVX2 /
// baseline, GCC-vectorised loops; the scatter uses AVX2 gathers: this
// folder is compiled with -mtune-ctrl=use_gather) with scalar twins that
// give the same bytes (kernels/gather/oblique_scatter_kernels_test.cpp).
#pragma once

#include <cstdint>

namespace ris::kernels {

// A block of lines' scene-map values, dense: row k (line line0 + k) holds
// `width` samples from sample `lo`; any sample index is clamped to [lo, hi]
// (the guard columns).
struct BlockMapView {
  const std::int32_t* mask = nullptr;  // scene_flag bits
  const float* incidence_deg = nullptr;
  int line0 = 0, lo = 0, hi = 0, width = 0;
};

// Cells [c_begin, c_end) of one scene row, every one taking a line of the
// block and a sample (line = round(lbase + c line_dc), sample = round(sbase
// + c sample_dc), half away from zero): mask (with kNoData where valid is
// 0) and local incidence from the block.
void scatter_run(double lbase, double line_dc, double sbase, double sample_dc, int c_begin,
                 int c_end, const BlockMapView& b, const std::uint8_t* valid, std::uint8_t* mask,
                 float* incidence);
void scatter_run_scalar(double lbase, double line_dc, double sbase, double sample_dc, int c_begin,
                        int c_end, const BlockMapView& b, const std::uint8_t* valid,
                        std::uint8_t* mask, float* incidence);

// The scene-map values (scene_map_sample) of n samples.
void map_values(int n, const std::uint8_t* flags, const float* range, const float* local_incidence,
                double near_m, double far_m, std::int32_t* mask, float* incidence_deg);
void map_values_scalar(int n, const std::uint8_t* flags, const float* range,
                       const float* local_incidence, double near_m, double far_m,
                       std::int32_t* mask, float* incidence_deg);

}  // namespace ris::kernels
