// RIS_VECTOR_CLONES: compile a hot loop's function twice, for AVX2 and for
// the baseline x86-64 (SSE2), and pick the clone at load time (GCC function
// multiversioning, target_clones). The build stays portable (no -march).
// The AVX2 target does not include FMA, so no multiply-add is contracted and
// the vector operations round exactly as the scalar ones: both clones give
// the same bytes on any CPU. Elsewhere (other compilers, other
// architectures) it expands to nothing.
//
// Example:
//   RIS_VECTOR_CLONES void scale(int n, float k, const float* __restrict in,
//                                float* __restrict out) {
//     for (int i = 0; i < n; ++i) out[i] = k * in[i];
//   }
#pragma once

//
// RIS_WIDE_VECTOR_CLONES adds an AVX-512 clone (twice the lanes of GCC's
// vectorised loops; one instruction for kernels/simd/vec8.h's eight doubles). GCC's
// avx512f target enables FMA, so it is used only in src/kernels/, which
// is compiled with -ffp-contract=off (CMakeLists.txt): every clone's bytes
// stay the same.
//
// RIS_V4_VECTOR_CLONES adds an x86-64-v4 clone instead (AVX-512 F, VL, BW,
// DQ): for loops in GCC's 8-lane vector types (kernels/simd/vec8.h) that run out of
// AVX2's 16 registers, AVX-512VL gives the same 256-bit operations 32
// registers and mask registers for the selects (no spills). Its target
// enables FMA too: the same rule (src/kernels/ only).
//
// Public because ris/util/float_select.h's key template (over a caller's
// predicate, so a template, not a compiled kernel) uses RIS_VECTOR_CLONES,
// whose AVX2 target has no FMA; every other user is in src/kernels/.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#define RIS_WIDE_VECTOR_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#define RIS_V4_VECTOR_CLONES __attribute__((target_clones("arch=x86-64-v4", "avx2", "default")))
#else
#define RIS_VECTOR_CLONES
#define RIS_WIDE_VECTOR_CLONES
#define RIS_V4_VECTOR_CLONES
#endif
