// Kernels of the greytone quantiser (ris/image/greytone.h
// GreytoneMap::quantise_line): powers to greytones through the map's bucket
// table and thresholds (the power's top 16 bits pick a bucket, then at most
// `steps` threshold compares). AVX2 (intrinsics) and clones (AVX2 /
// baseline) beside the scalar loop; integer and compare operations only:
// the same bytes (image/greytone_test.cpp LineKernelEqualsQuantisedWithMask:
// the kernel this CPU runs against the per-pixel rule).
#pragma once

#include <cstddef>
#include <cstdint>

namespace ris::kernels {

// One threshold step a pixel (any ordinary film). avx2: the intrinsics
// kernel (bucket_step: each bucket's greytone and its threshold's low bits);
// else the clones. Masked (NaN, or mask & mask_bits): no_data_greytone.
void quantise_one_step(bool avx2, const float* power_w, const std::uint8_t* mask,
                       std::uint8_t mask_bits, std::size_t n, std::uint8_t* out,
                       std::uint8_t no_data_greytone, const std::uint32_t* bucket_step,
                       const std::uint8_t* bucket, const float* threshold);
void quantise_one_step_scalar(const float* power_w, const std::uint8_t* mask,
                              std::uint8_t mask_bits, std::size_t n, std::uint8_t* out,
                              std::uint8_t no_data_greytone, const std::uint8_t* bucket,
                              const float* threshold);

// Up to `steps` threshold steps a pixel.
void quantise_steps(const float* power_w, const std::uint8_t* mask, std::uint8_t mask_bits,
                    std::size_t n, std::uint8_t* out, std::uint8_t no_data_greytone,
                    const std::uint8_t* bucket, const float* threshold, unsigned steps);

}  // namespace ris::kernels
