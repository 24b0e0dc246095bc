// Internal to kernels/: eight-lane GCC vector types and helpers, for hot loops that GCC
// 12 does not vectorise by itself (conditions that mix byte flags with float
// or double comparisons). One F8 is one AVX2 register in a RIS_VECTOR_CLONES
// function's AVX2 clone and two SSE2 registers in its default clone; the
// lane operations round as the scalar ones (no FMA), so both clones give the
// same bytes. Comparisons give -1 / 0 lane masks (I8); `m ? a : b` selects.
//
// Example:
//   const ris::vec8::F8 r = ris::vec8::load<ris::vec8::F8>(range + j);
//   ris::vec8::store(out + j, r < ris::vec8::splat(1.0f) ? r : ris::vec8::splat(1.0f));
#pragma once

#include <cstdint>
#include <cstring>

// The helpers take and return vectors by value; GCC's note that this
// changes the ABI without AVX (-Wpsabi) is moot for inlined internal
// helpers and is switched off for the kernels folder only (CMakeLists.txt).

namespace ris::vec8 {

inline constexpr int kLanes = 8;
using F8 = float __attribute__((vector_size(32)));
using D8 = double __attribute__((vector_size(64)));
using I8 = std::int32_t __attribute__((vector_size(32)));
using U16x8 = std::uint16_t __attribute__((vector_size(16)));
using U8x8 = std::uint8_t __attribute__((vector_size(8)));

template <class V, class T>
inline V load(const T* p) {
  V v;
  std::memcpy(&v, p, sizeof v);
  return v;
}
template <class V, class T>
inline void store(T* p, V v) {
  std::memcpy(p, &v, sizeof v);
}
inline F8 splat(float x) {
  return F8{} + x;
}
inline I8 splat(std::int32_t x) {
  return I8{} + x;
}
// Bytes to and from 32-bit lanes through 16-bit lanes: the same values as
// one __builtin_convertvector, but GCC 12 compiles the direct conversion
// into a scalar extract / insert per lane and this into a few vector
// instructions (vpmovzxbw, vpmovzxwd; vpackusdw, vpackuswb).
inline I8 widen_u8(U8x8 b) {
  return __builtin_convertvector(__builtin_convertvector(b, U16x8), I8);
}
inline U8x8 narrow_u8(I8 x) {
  return __builtin_convertvector(__builtin_convertvector(x, U16x8), U8x8);
}
// GCC's __builtin_shuffle (lanes picked by a mask vector, indices taken
// modulo the lane count, or twice it with two sources). Clang has no such
// builtin for a mask that is not a constant list, so under clang (the
// libFuzzer build, `make fuzz`) the same selection is a loop over lanes:
// same values, slower code, in a build where only correctness counts.
#if defined(__clang__)
template <class V, class M>
inline V shuffle(V a, M m) {
  constexpr int n = static_cast<int>(sizeof(V) / sizeof(a[0]));
  V r;
  for (int i = 0; i < n; ++i) r[i] = a[static_cast<int>(m[i]) & (n - 1)];
  return r;
}
template <class V, class M>
inline V shuffle(V a, V b, M m) {
  constexpr int n = static_cast<int>(sizeof(V) / sizeof(a[0]));
  V r;
  for (int i = 0; i < n; ++i) {
    const int k = static_cast<int>(m[i]) & (2 * n - 1);
    r[i] = k < n ? a[k] : b[k - n];
  }
  return r;
}
#else
template <class V, class M>
inline V shuffle(V a, M m) {
  return __builtin_shuffle(a, m);
}
template <class V, class M>
inline V shuffle(V a, V b, M m) {
  return __builtin_shuffle(a, b, m);
}
#endif
inline F8 vmin(F8 a, F8 b) {
  return b < a ? b : a;
}
inline F8 vmax(F8 a, F8 b) {
  return a < b ? b : a;
}

}  // namespace ris::vec8
