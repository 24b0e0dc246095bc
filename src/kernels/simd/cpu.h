// Which instruction sets this CPU runs, asked once, for the callers that
// choose between a kernel's AVX-512 version and its portable one
// (kernels/simd/avx512.h). No intrinsics here: logic files include this.
#pragma once

namespace ris {

// Whether this CPU runs RIS_AVX512_KERNEL functions (AVX-512 F, VL, BW and
// DQ; checked once). False where the kernels are not built (other
// compilers or architectures).
inline bool cpu_has_avx512() {
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
  static const bool yes = __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512vl") &&
                          __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq");
  return yes;
#else
  return false;
#endif
}

// Whether this CPU runs the AVX2 clones (RIS_VECTOR_CLONES) and AVX2
// kernels; for tests that say which code they compared.
inline bool cpu_has_avx2() {
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
#else
  return false;
#endif
}

}  // namespace ris
