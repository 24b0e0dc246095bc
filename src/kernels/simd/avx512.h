// Hand-written AVX-512 kernels beside portable code: RIS_AVX512_KERNEL
// compiles one function for AVX-512 (F, VL, BW and DQ: every AVX-512 CPU but
// the Xeon Phi) in a build without -march, and cpu_has_avx512()
// (kernels/simd/cpu.h) says at run time whether it may be called; otherwise
// the caller runs its portable version (plain code or
// ris/kernels/vector_clones.h's clones). A kernel gives the same bytes as
// the portable version: it does the same floating-point operations lane by
// lane (src/kernels/ is compiled with -ffp-contract=off, as the avx512f
// target enables FMA), and tests compare the two.
//
// Example:
//   #ifdef RIS_HAVE_AVX512_KERNELS
//   RIS_AVX512_KERNEL int scale_avx512(int n, const float* in, float* out);  // returns n done
//   #endif
//   void scale(int n, const float* in, float* out) {
//     int done = 0;
//   #ifdef RIS_HAVE_AVX512_KERNELS
//     if (ris::cpu_has_avx512()) done = scale_avx512(n, in, out);
//   #endif
//     scale_portable(n - done, in + done, out + done);
//   }
#pragma once

#include "kernels/simd/cpu.h"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
#define RIS_HAVE_AVX512_KERNELS 1
#define RIS_AVX512_KERNEL __attribute__((target("avx512f,avx512vl,avx512bw,avx512dq")))
#else
#define RIS_AVX512_KERNEL
#endif
