#include "kernels/image/slar_element.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

#include "kernels/simd/vec8.h"
#include "ris/kernels/vector_clones.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris::detail {

SlarElementContext element_context(const SlarImagingParams& p, const TwoWayGainTable& gain2,
                                   const Sigma0Lut& lut, int bins) {
  SlarElementContext ctx;
  // P_t lambda^2 / (4 pi)^3: the radar equation's constant part.
  ctx.k_radar = p.transmit_power_w * p.wavelength_m * p.wavelength_m / std::pow(4.0 * kPi, 3.0);
  ctx.near_m = p.range.near_m;
  ctx.inv_dr = 1.0 / p.range.bin_m;
  ctx.bins = bins;
  ctx.gain2 = &gain2;
  ctx.lut = &lut;
  const auto pairs = [](const auto* t, std::size_t size, auto& out) {
    out.assign(2 * size, 0);
    for (std::size_t k = 0; k < size; ++k) {
      out[2 * k] = t[k];
      out[2 * k + 1] = k + 1 < size ? t[k + 1] - t[k] : 0;
    }
  };
  // The gain's pairs from the table rounded to float (value and difference
  // both in single precision, as the power).
  const std::vector<float> gain2_f(gain2.data(), gain2.data() + TwoWayGainTable::kSteps + 1);
  pairs(gain2_f.data(), gain2_f.size(), ctx.gain2_pairs);
  pairs(lut.data(), lut.size(), ctx.sigma0_pairs);
  ctx.g2_uniform = static_cast<float>(gain2.at(0.0));
  ctx.power_scale = ctx.k_radar * kElementPowerScale;
  return ctx;
}

LineElementScratch::LineElementScratch(int samples, int bins_)
    : bins(bins_),
      first(static_cast<std::size_t>(samples)),
      code(first.size()),
      frac_next(first.size()),
      ratio(first.size()),
      area(first.size()),
      acc(2 * kCopies * stride(), 0.0),
      counts(kCopies * stride(), 0),
      touch(counts.size(), 0) {
  general.resize(first.size());
}

void LineElementScratch::reserve_channels(int n) {
  channels = n;
  const auto k = static_cast<std::size_t>(n);
  channel_acc.assign(k * kCopies * stride(), 0.0);
  channel_ratio.assign(k * kChunk, 0.0f);
  channel_general_ratio.assign(k * first.size(), 0.0f);
  formed_area.assign(static_cast<std::size_t>(bins), 0.0);
}

namespace {

constexpr std::int32_t kSkip = sample_flag::kNoData | sample_flag::kUnseen;
constexpr std::int32_t kHidden =
    kSkip | sample_flag::kShadow | sample_flag::kBackFacing;  // not sample_visible

// LineElementScratch::code: the touch bits of the first bin (bits 0-7) and
// of the next one (8-15); whether the centre is in a bin and the element
// visible (the visible count); whether the centre is in the next bin (for an
// element the scatter pass adds; else in the first); whether it is left to
// spread().
constexpr int kCodeNextShift = 8;
constexpr std::int32_t kCodeSeen = 1 << 16;
constexpr int kCodeCentreShift = 17;
constexpr std::int32_t kCodeGeneral = 1 << 24;
// One visible centre in LineElementScratch::counts (both halves).
constexpr std::uint64_t kSeenOne = (std::uint64_t{1} << 32) | 1;

// Pass 1 works on eight elements at a time in GCC vector types
// (kernels/simd/vec8.h): GCC 12 does not vectorise this loop by itself (its
// conditions mix byte flags and float comparisons).
using vec8::F8;
using vec8::I8;
using vec8::kLanes;
using vec8::load;
using vec8::splat;
using vec8::store;
using vec8::U16x8;
using vec8::U8x8;
using vec8::vmax;
using vec8::vmin;

// The fraction of a half element, uniform over the bin-coordinate interval
// between x0 and x1 (either order), at or beyond the bin edge t; a
// zero-length half is wholly on the side of its point (as spread()).
inline F8 beyond(F8 x0, F8 x1, F8 t) {
  const F8 zero = splat(0.0f), one = splat(1.0f);
  const F8 lo = vmin(x0, x1), hi = vmax(x0, x1), w = hi - lo;
  const F8 q = (hi - t) / (w > zero ? w : one);
  const F8 f = vmin(vmax(q, zero), one);
  const F8 point = lo >= t ? one : zero;
  return w > zero ? f : point;
}

// Pass 1's table lookups on eight elements, the same operations as
// Sigma0Lut::interpolate (so the same values) with the tables as (value,
// difference) pairs of floats (SlarElementContext): one 8-byte load per
// element where GCC's vectorised scalar loop emulated two gathers. Element l
// reads entry curve[l] + i of its table (curve: null for offset 0; the
// sigma0 curves of the lanes' categories).
template <int kSteps>
__attribute__((always_inline)) inline F8 pair_block(const float* __restrict pairs,
                                                    const std::int32_t* curve, F8 x,
                                                    float inv_step) {
  F8 pos = x * inv_step;
  pos = pos < 0.0f ? splat(0.0f) : pos;
  pos = pos > static_cast<float>(kSteps) ? splat(static_cast<float>(kSteps)) : pos;
  I8 i = __builtin_convertvector(pos, I8);
  i = i < kSteps - 1 ? i : splat(kSteps - 1);
  const F8 f = pos - __builtin_convertvector(i, F8);
  // The entries' indices through memory: GCC would move each lane to a
  // general register (vmovd / vpextrd, two micro-ops each on this CPU);
  // eight scalar loads from a stored vector are cheaper. The empty asm
  // stops GCC from forwarding the stored lanes through registers.
  alignas(32) std::int32_t ii[kLanes];
  store(ii, i);
  asm("" : "+m"(ii));
  // A pair of floats is 8 bytes: loaded as one double each.
  using D4 = double __attribute__((vector_size(32)));
  D4 a, b;
  for (int l = 0; l < 4; ++l) {
    const std::int32_t ka = curve ? curve[l] + ii[l] : ii[l];
    const std::int32_t kb = curve ? curve[l + 4] + ii[l + 4] : ii[l + 4];
    a[l] = load<double>(pairs + 2 * static_cast<std::ptrdiff_t>(ka));
    b[l] = load<double>(pairs + 2 * static_cast<std::ptrdiff_t>(kb));
  }
  const F8 fa = F8(a), fb = F8(b);
  const F8 t = vec8::shuffle(fa, fb, I8{0, 2, 4, 6, 8, 10, 12, 14});
  const F8 d = vec8::shuffle(fa, fb, I8{1, 3, 5, 7, 9, 11, 13, 15});
  return t + f * d;
}

constexpr float kGainInvStep = static_cast<float>(TwoWayGainTable::kInvStepRad);

// Pass 1's inputs and outputs, at element j (one block of kLanes elements).
struct BinsPassIo {
  const std::uint8_t* flags;
  const float *range, *near_end, *far_end, *incidence, *local_incidence, *area;
  const std::uint16_t* category;
  std::int32_t *first, *code;
  float *frac_next, *ratio_out, *area_out;
};

// Pass 1's tables for the power (SlarElementContext); no lookups when
// nothing is tabulated (then nothing is visible).
struct PowerTables {
  bool tabulated, uniform;
  float g2_uniform;
  const float *gain2_pairs, *sigma0_pairs;
  const std::int32_t* curve_offset;
  std::int32_t any_category;
};

// Pass 1, branch-free: each element's bins. An element whose slant span lies
// in [0, bins) within two bins b0, b0 + 1 ("fast": almost all) gets b0, the
// fraction of its power in b0 + 1 (half of it spread from the near end to
// the centre, half from the centre to the far end, as spread() would) and
// its touch bits and whether its centre is in b0 + 1 (the counts; the
// scatter pass adds them at b0 or b0 + 1, pass 3 those of the others); any
// other element that touches the swath is marked for spread(). Also the
// element_power_ratio (the table lookups and the float arithmetic, in the
// same pass: no per-element arrays between them) with neutral inputs where
// the element is not visible (range 1, area 0, a tabulated category, angles
// 0: ratio 0), and the area (0 where not visible).
// Per-lane tallies of pass 1 (LineElementTally); `valid` masks the padding.
struct BinsTally {
  I8 in_swath{}, nodata{}, shadow{}, back_facing{}, layover{}, general{};
  F8 r_min = splat(std::numeric_limits<float>::infinity());
  F8 r_max = splat(-std::numeric_limits<float>::infinity());
  // The bins the scatter pass adds to: b0 and b0 + 1 of the elements that
  // touch the swath.
  I8 bin_min = splat(std::numeric_limits<std::int32_t>::max()), bin_max = splat(-1);
};

// The bins a line's elements add to, [lo, hi] (lo > hi: none): merge_pass
// reads and clears only those (an oblique track's line clipped to the scene
// covers part of the swath).
struct BinRange {
  int lo = std::numeric_limits<int>::max(), hi = -1;
  void add(int b0, int b1) {
    lo = std::min(lo, b0);
    hi = std::max(hi, b1);
  }
};

// The element_power_ratio of eight elements (pass 1's power half, and a
// further channel's whole pass 1: ratio_pass), with neutral inputs where
// an element is not visible (range 1, area 0, a tabulated category, angles
// 0: ratio 0); area is 0 there already. 0 when nothing is tabulated.
__attribute__((always_inline)) inline F8 power_ratio_block(const PowerTables& pt, I8 vis, F8 area,
                                                           F8 r, const BinsPassIo& io,
                                                           std::size_t j) {
  const F8 zero = splat(0.0f);
  if (!pt.tabulated) return zero;
  const I8 cat = __builtin_convertvector(load<U16x8>(io.category + j), I8);
  const I8 c = vis ? cat : splat(pt.any_category);
  // Each lane's sigma0 curve (the category's offset), through memory as
  // the table entries in pair_block.
  alignas(32) std::int32_t cc[kLanes], curve[kLanes];
  store(cc, c);
  asm("" : "+m"(cc));
  for (int l = 0; l < kLanes; ++l) curve[l] = pt.curve_offset[cc[l]];
  const F8 sigma0 = pair_block<Sigma0Lut::kSteps>(
      pt.sigma0_pairs, curve, vis ? load<F8>(io.local_incidence + j) : zero, Sigma0Lut::kInvStep);
  const F8 g2 = pt.uniform ? splat(pt.g2_uniform)
                           : pair_block<TwoWayGainTable::kSteps>(
                                 pt.gain2_pairs, nullptr, vis ? load<F8>(io.incidence + j) : zero,
                                 kGainInvStep);
  return element_power_ratio(g2, sigma0, area, vis ? r : splat(1.0f));
}

__attribute__((always_inline)) inline void bins_block(const BinsPassIo& io, std::size_t j,
                                                      float near_m, float inv_dr, int bins,
                                                      const PowerTables& pt, I8 valid,
                                                      BinsTally& t) {
  const F8 nb = splat(static_cast<float>(bins)), zero = splat(0.0f);
  const I8 f = vec8::widen_u8(load<U8x8>(io.flags + j));
  const I8 has = (f & kSkip) == 0;
  const I8 vis = (f & kHidden) == 0;
  const I8 lay = (f & sample_flag::kLayover) != 0;
  const F8 r = load<F8>(io.range + j);
  const F8 pos = (r - near_m) * inv_dr;
  const F8 xa = (load<F8>(io.near_end + j) - near_m) * inv_dr;
  const F8 xb = (load<F8>(io.far_end + j) - near_m) * inv_dr;
  const I8 in_swath = has & (pos >= zero) & (pos < nb);
  // The tallies (a mask is -1 where true).
  t.in_swath -= in_swath & valid;
  t.nodata -= ((f & sample_flag::kNoData) != 0) & valid;
  t.shadow -= ((f & sample_flag::kShadow) != 0) & valid;
  t.back_facing -= ((f & sample_flag::kBackFacing) != 0) & valid;
  t.layover -= lay & valid;
  t.r_min = vmin(t.r_min, (has & valid) ? r : t.r_min);
  t.r_max = vmax(t.r_max, (has & valid) ? r : t.r_max);
  const F8 lo = vmin(vmin(xa, xb), pos), hi = vmax(vmax(xa, xb), pos);
  const I8 touch = has & (hi >= zero) & (lo < nb);
  // first_bin and last_bin (truncation of values clamped to [0, bins - 1]).
  const I8 b0 = __builtin_convertvector(touch ? vmax(lo, zero) : zero, I8);
  const I8 b1 = __builtin_convertvector(touch ? vmin(hi, nb - 1.0f) : zero, I8);
  const I8 fast = touch & (lo >= zero) & (hi < nb) & ((b1 - b0) <= 1);
  t.general -= touch & ~fast;  // padding lanes have no data: never touch
  t.bin_min = touch & (b0 < t.bin_min) ? b0 : t.bin_min;
  t.bin_max = touch & (b0 + 1 > t.bin_max) ? b0 + 1 : t.bin_max;
  const I8 bits =
      slar_touch::kData | (vis & slar_touch::kVisible) | (vis & lay & slar_touch::kLayover);
  // The centre's bin (in the swath where fast): b0 or b0 + 1.
  const I8 centre_next = __builtin_convertvector(pos, I8) > b0;
  store(io.code + j, (fast & bits) | (fast & (b1 > b0) & (bits << kCodeNextShift)) |
                         (in_swath & vis & kCodeSeen) |
                         (fast & centre_next & (1 << kCodeCentreShift)) |
                         (touch & ~fast & kCodeGeneral));
  store(io.first + j, fast ? b0 : splat(bins));
  const F8 edge = __builtin_convertvector(b0 + 1, F8);
  const F8 frac = 0.5f * (beyond(xa, pos, edge) + beyond(pos, xb, edge));
  store(io.frac_next + j, fast ? frac : zero);
  const F8 area = vis ? load<F8>(io.area + j) : zero;
  store(io.area_out + j, area);
  store(io.ratio_out + j, power_ratio_block(pt, vis, area, r, io, j));
}

// Pass 1 over the line; the last partial block through a padded copy (its
// padding: no-data elements).
// Its x86-64-v4 clone: the block's state fits AVX-512VL's 32 registers
// (AVX2's 16 spilled a fifth of it to the stack).
RIS_V4_VECTOR_CLONES void bins_pass(int n, float near_m, float inv_dr, int bins,
                                    const PowerTables& pt, const BinsPassIo& io,
                                    LineElementTally& tally, BinRange& range) {
  BinsTally t;
  const std::size_t full = static_cast<std::size_t>(n / kLanes) * kLanes;
  for (std::size_t j = 0; j < full; j += kLanes) {
    bins_block(io, j, near_m, inv_dr, bins, pt, splat(-1), t);
  }
  const std::size_t rest = static_cast<std::size_t>(n) - full;
  if (rest > 0) {
    std::uint8_t flags[kLanes];
    float in[6][kLanes] = {};
    std::uint16_t category[kLanes] = {};
    std::int32_t out_i[2][kLanes];
    float out_f[3][kLanes];
    std::fill(flags, flags + kLanes, sample_flag::kNoData);
    std::copy_n(io.flags + full, rest, flags);
    const float* const src[6] = {io.range,     io.near_end,        io.far_end,
                                 io.incidence, io.local_incidence, io.area};
    for (int k = 0; k < 6; ++k) std::copy_n(src[k] + full, rest, in[k]);
    std::copy_n(io.category + full, rest, category);
    const BinsPassIo pad{flags,    in[0],    in[1],    in[2],    in[3],    in[4],   in[5],
                         category, out_i[0], out_i[1], out_f[0], out_f[1], out_f[2]};
    I8 valid{};
    for (std::size_t l = 0; l < rest; ++l) valid[l] = -1;
    bins_block(pad, 0, near_m, inv_dr, bins, pt, valid, t);
    std::int32_t* const dst_i[2] = {io.first, io.code};
    float* const dst_f[3] = {io.frac_next, io.ratio_out, io.area_out};
    for (int k = 0; k < 2; ++k) std::copy_n(out_i[k], rest, dst_i[k] + full);
    for (int k = 0; k < 3; ++k) std::copy_n(out_f[k], rest, dst_f[k] + full);
  }
  for (int l = 0; l < kLanes; ++l) {
    tally.in_swath += t.in_swath[l];
    tally.nodata += t.nodata[l];
    tally.shadow += t.shadow[l];
    tally.back_facing += t.back_facing[l];
    tally.layover += t.layover[l];
    tally.general += t.general[l];
    tally.r_min_m = std::min(tally.r_min_m, t.r_min[l]);
    tally.r_max_m = std::max(tally.r_max_m, t.r_max[l]);
    range.add(t.bin_min[l], t.bin_max[l]);
  }
}

// A further channel's pass 1 on eight elements: their power ratio only (the
// bins, fractions and areas are the geometry's, io.area_out holding the
// areas pass 1 stored: 0 where not visible, as bins_block reads them).
__attribute__((always_inline)) inline void ratio_block(const BinsPassIo& io, std::size_t j,
                                                       const PowerTables& pt) {
  const I8 f = vec8::widen_u8(load<U8x8>(io.flags + j));
  const I8 vis = (f & kHidden) == 0;
  store(io.ratio_out + j,
        power_ratio_block(pt, vis, load<F8>(io.area_out + j), load<F8>(io.range + j), io, j));
}

// A further channel's pass 1 over the line (its last partial block through
// a padded copy, as bins_pass).
RIS_V4_VECTOR_CLONES void ratio_pass(int n, const PowerTables& pt, const BinsPassIo& io) {
  const std::size_t full = static_cast<std::size_t>(n / kLanes) * kLanes;
  for (std::size_t j = 0; j < full; j += kLanes) ratio_block(io, j, pt);
  const std::size_t rest = static_cast<std::size_t>(n) - full;
  if (rest == 0) return;
  std::uint8_t flags[kLanes];
  float in[4][kLanes] = {}, ratio[kLanes];
  std::uint16_t category[kLanes] = {};
  std::fill(flags, flags + kLanes, sample_flag::kNoData);
  std::copy_n(io.flags + full, rest, flags);
  const float* const src[4] = {io.range, io.incidence, io.local_incidence, io.area_out};
  for (int k = 0; k < 4; ++k) std::copy_n(src[k] + full, rest, in[k]);
  std::copy_n(io.category + full, rest, category);
  const BinsPassIo pad{flags,    in[0],   nullptr, nullptr, in[1], in[2], nullptr,
                       category, nullptr, nullptr, nullptr, ratio, in[3]};
  ratio_block(pad, 0, pt);
  std::copy_n(ratio, rest, io.ratio_out + full);
}

// An element's power P_i = ratio k_radar 2^-40 from its
// element_power_ratio (SlarElementContext::power_scale; 0 where not
// visible: its ratio is 0).
inline double element_power(double power_scale, float ratio) {
  return double(ratio) * power_scale;
}

// Pass 2: the fast elements [j0, j0 + n) into the four copies, element j
// into copy (first_index + j) % 4
// (consecutive elements usually share a bin: in one copy each add would wait
// for the previous one's store). Elements without a bin add to the spare
// bin `bins`. Each element's (power, area) split between b0 and b0 + 1 in
// double here, as it is added (a pass of its own that stored the two
// pairs cost more than the scatter's extra arithmetic: this loop waits on
// its read-modify-writes).
void scatter_pass(int j0, int n, int first_index, double power_scale, LineElementScratch& s) {
  using D2 = double __attribute__((vector_size(16)));
  const std::size_t stride = s.stride();
  const std::int32_t* __restrict first = s.first.data();
  const std::int32_t* __restrict code = s.code.data();
  const float* __restrict ratio = s.ratio.data();
  const float* __restrict area = s.area.data();
  const float* __restrict frac_next = s.frac_next.data();
  double* __restrict acc = s.acc.data();
  std::uint8_t* __restrict touch = s.touch.data();
  std::uint64_t* __restrict counts = s.counts.data();
  const auto add = [](double* a, D2 x) { vec8::store(a, vec8::load<D2>(a) + x); };
  const auto one = [&](int j, std::size_t q) {
    const std::size_t jj = static_cast<std::size_t>(j);
    const std::size_t b = q * stride + static_cast<std::size_t>(first[jj]);
    // P_i and the (power, area) pair split by the fraction in b0 + 1; the
    // pairs added as two scalar arrays would be, in one instruction each.
    const D2 pa = {element_power(power_scale, ratio[jj]), double(area[jj])};
    const D2 h = pa * double(frac_next[jj]);
    const D2 l = pa - h;
    add(acc + 2 * b, l);
    add(acc + 2 * b + 2, h);
    const std::int32_t c = code[jj];
    // The two bins' touch bits as one 16-bit OR (little-endian: the first
    // bin's in the low byte, as code holds them).
    static_assert(std::endian::native == std::endian::little);
    std::uint16_t t2;
    std::memcpy(&t2, touch + b, 2);
    t2 = static_cast<std::uint16_t>(t2 | (c & 0xffff));
    std::memcpy(touch + b, &t2, 2);
    const std::size_t k = b + static_cast<std::size_t>((c >> kCodeCentreShift) & 1);
    counts[k] += (c & kCodeSeen) ? kSeenOne : 1;
  };
  const auto copy = [first_index](int j) {
    return static_cast<std::size_t>((first_index + j) & 3);
  };
  const std::size_t q0 = copy(j0), q1 = copy(j0 + 1), q2 = copy(j0 + 2), q3 = copy(j0 + 3);
  const int j1 = j0 + n;
  int j = j0;
  for (; j + 4 <= j1; j += 4) {
    one(j, q0);
    one(j + 1, q1);
    one(j + 2, q2);
    one(j + 3, q3);
  }
  for (; j < j1; ++j) one(j, copy(j));
}

// Pass 4: the copies summed into the line's outputs, and zeroed for the next
// line; one loop per type, so that each vectorises. Only the bins in
// [lo, hi) were added to: the others are 0 in every copy (their power and
// area outputs 0, touch bits and counts unchanged).
RIS_VECTOR_CLONES void merge_pass(int bins, int lo, int hi, std::size_t stride,
                                  double* __restrict acc, std::uint64_t* __restrict counts,
                                  std::uint8_t* __restrict touch, double* __restrict out_power,
                                  double* __restrict out_area, std::uint8_t* __restrict out_touch,
                                  std::uint16_t* __restrict out_mapped,
                                  std::uint16_t* __restrict out_visible) {
  const std::size_t s1 = stride, s2 = 2 * stride, s3 = 3 * stride;
  const auto b0 = static_cast<std::size_t>(lo), b1 = static_cast<std::size_t>(hi);
  std::fill(out_power, out_power + b0, 0.0);
  std::fill(out_area, out_area + b0, 0.0);
  std::fill(out_power + b1, out_power + bins, 0.0);
  std::fill(out_area + b1, out_area + bins, 0.0);
  for (std::size_t b = b0; b < b1; ++b) {
    const std::size_t k = 2 * b;
    out_power[b] = (acc[k] + acc[k + 2 * s1]) + (acc[k + 2 * s2] + acc[k + 2 * s3]);
    out_area[b] = (acc[k + 1] + acc[k + 1 + 2 * s1]) + (acc[k + 1 + 2 * s2] + acc[k + 1 + 2 * s3]);
  }
  for (std::size_t b = b0; b < b1; ++b) {
    out_touch[b] |=
        static_cast<std::uint8_t>(touch[b] | touch[b + s1] | touch[b + s2] | touch[b + s3]);
  }
  constexpr std::uint32_t kMax = 65535;  // the counts saturate
  for (std::size_t b = b0; b < b1; ++b) {
    const std::uint64_t c = (counts[b] + counts[b + s1]) + (counts[b + s2] + counts[b + s3]);
    const std::uint32_t m = out_mapped[b] + static_cast<std::uint32_t>(c & 0xffffffffu);
    const std::uint32_t v = out_visible[b] + static_cast<std::uint32_t>(c >> 32);
    out_mapped[b] = static_cast<std::uint16_t>(std::min(m, kMax));
    out_visible[b] = static_cast<std::uint16_t>(std::min(v, kMax));
  }
  for (std::size_t q = 0; q < LineElementScratch::kCopies; ++q) {
    std::fill(acc + 2 * (q * stride + b0), acc + 2 * (q * stride + b1), 0.0);
    std::fill(touch + q * stride + b0, touch + q * stride + b1, std::uint8_t{0});
    std::fill(counts + q * stride + b0, counts + q * stride + b1, std::uint64_t{0});
  }
}

// An element's bin coordinates in double precision (pass 3's): its centre
// and ends, and the interval they span.
struct ElementSpan {
  double pos, xa, xb, lo, hi;
};
inline ElementSpan element_span(const SlarElementContext& c, const LineElements& e, std::size_t j) {
  ElementSpan x{};
  x.pos = (double(e.slant_range_m[j]) - c.near_m) * c.inv_dr;
  x.xa = (double(e.near_end_m[j]) - c.near_m) * c.inv_dr;
  x.xb = (double(e.far_end_m[j]) - c.near_m) * c.inv_dr;
  x.lo = std::min(std::min(x.xa, x.xb), x.pos);
  x.hi = std::max(std::max(x.xa, x.xb), x.pos);
  return x;
}

// Pass 3's power: a visible element's power and area, half each from its
// near end to its centre and from its centre to its far end, into copy 0
// by spread() (its ratio in s.ratio).
inline void spread_element(const ElementSpan& x, const SlarElementContext& c, const LineElements& e,
                           LineElementScratch& s, std::size_t j) {
  const double half_power = 0.5 * element_power(c.power_scale, s.ratio[j]);
  const double half_area = 0.5 * double(e.area_m2[j]);
  spread(s.acc.data(), s.acc.data() + 1, x.xa, x.pos, half_power, half_area, c.bins, 2);
  spread(s.acc.data(), s.acc.data() + 1, x.pos, x.xb, half_power, half_area, c.bins, 2);
}

}  // namespace

LineElementTally form_line_profile(const SlarElementContext& c, const LineElements& e,
                                   LineElementScratch& s, const LineProfileRow& out,
                                   float* element_power_w) {
  const int n = e.samples;
  const int bins = c.bins;
  RIS_CHECK(s.bins == bins && s.first.size() >= static_cast<std::size_t>(n));
  LineElementTally t;
  const Sigma0Lut& lut = *c.lut;
  // Passes 1-2 a chunk of elements at a time, so that what one pass writes
  // is still in the L1 cache when the next reads it (a whole line's
  // per-element arrays are ~200 KB).
  const PowerTables pt{!lut.empty(),         c.gain2->uniform(),    c.g2_uniform,
                       c.gain2_pairs.data(), c.sigma0_pairs.data(), lut.offsets(),
                       lut.any_category()};
  constexpr int kChunk = LineElementScratch::kChunk;
  BinRange range;
  const float near_f = static_cast<float>(c.near_m), inv_dr_f = static_cast<float>(c.inv_dr);
  for (int j0 = 0; j0 < n; j0 += kChunk) {
    const int m = std::min(kChunk, n - j0);
    const auto o = static_cast<std::size_t>(j0);
    const BinsPassIo io{e.flags + o,
                        e.slant_range_m + o,
                        e.near_end_m + o,
                        e.far_end_m + o,
                        (e.incidence_rad ? e.incidence_rad : e.local_incidence_rad) + o,
                        e.local_incidence_rad + o,
                        e.area_m2 + o,
                        e.category + o,
                        s.first.data() + o,
                        s.code.data() + o,
                        s.frac_next.data() + o,
                        s.ratio.data() + o,
                        s.area.data() + o};
    bins_pass(m, near_f, inv_dr_f, bins, pt, io, t, range);
    scatter_pass(j0, m, e.first_index, c.power_scale, s);
  }

  // Pass 3: the elements spanning more than two bins or the swath's edge,
  // into copy 0 by spread(), in element order, and their centre counts.
  // Their indices gathered branch-free (an index is written at every
  // element and kept where the count advances); most lines have none
  // (bins_pass counts them), and then the loop over the line is skipped.
  const std::int32_t* __restrict code = s.code.data();
  std::int32_t* __restrict general = s.general.data();
  int n_general = 0;
  if (t.general > 0) {
    for (int j = 0; j < n; ++j) {
      general[n_general] = j;
      n_general += (code[j] & kCodeGeneral) ? 1 : 0;
    }
  }
  s.n_general = n_general;
  for (int g = 0; g < n_general; ++g) {
    const std::int32_t j = general[g];
    const std::size_t jj = static_cast<std::size_t>(j);
    // The centre's bin as bins_pass finds it (in single precision).
    const float pos_f = (e.slant_range_m[jj] - near_f) * inv_dr_f;
    if (pos_f >= 0.0f && pos_f < static_cast<float>(bins)) {
      range.add(static_cast<int>(pos_f), static_cast<int>(pos_f));
      s.counts[static_cast<std::size_t>(pos_f)] += (code[j] & kCodeSeen) ? kSeenOne : 1;
    }
    const std::uint8_t f = e.flags[jj];
    const bool vis = sample_visible(f);
    const ElementSpan x = element_span(c, e, jj);
    if (x.hi < 0.0 || x.lo >= bins) continue;  // in single precision only
    const int b0 = first_bin(x.lo), b1 = last_bin(x.hi, bins);
    range.add(b0, b1);
    std::uint8_t bits = slar_touch::kData;
    if (vis) bits |= slar_touch::kVisible;
    if (vis && (f & sample_flag::kLayover)) bits |= slar_touch::kLayover;
    for (int b = b0; b <= b1; ++b) s.touch[static_cast<std::size_t>(b)] |= bits;
    if (vis) spread_element(x, c, e, s, jj);
  }

  const bool any = range.lo <= range.hi;
  const int lo = any ? std::clamp(range.lo, 0, bins) : 0;
  const int hi = any ? std::clamp(range.hi + 1, lo, bins) : 0;
  s.formed = {n, c.near_m, c.inv_dr, lo, hi};
  merge_pass(bins, lo, hi, s.stride(), s.acc.data(), s.counts.data(), s.touch.data(), out.power_w,
             out.area_m2, out.touch, out.mapped_count, out.visible_count);
  if (s.channels > 0) std::copy_n(out.area_m2, bins, s.formed_area.begin());
  if (element_power_w) {
    for (int j = 0; j < n; ++j) {
      element_power_w[j] =
          static_cast<float>(element_power(c.power_scale, s.ratio[static_cast<std::size_t>(j)]));
    }
  }
  return t;
}

void scatter_channel_elements(std::span<const SlarElementContext* const> channels,
                              const LineElements& e, LineElementScratch& s,
                              std::span<float* const> element_power_w) {
  const int n = e.samples;
  const int nc = static_cast<int>(channels.size());
  RIS_CHECK(nc <= s.channels);
  RIS_CHECK(element_power_w.empty() || element_power_w.size() == channels.size());
  const std::size_t stride = s.stride();
  for (const SlarElementContext* c : channels) {
    // The line the scratch holds must be this one, in these range bins.
    RIS_CHECK(s.formed.samples == n && s.bins == c->bins && s.formed.near_m == c->near_m &&
              s.formed.inv_dr == c->inv_dr);
  }
  constexpr int kChunk = LineElementScratch::kChunk;
  float* const ratio = s.channel_ratio.data();
  double* const acc = s.channel_acc.data();
  const std::int32_t* __restrict first = s.first.data();
  const float* __restrict frac_next = s.frac_next.data();
  float* const general_ratio = s.channel_general_ratio.data();
  const std::size_t samples = s.first.size();
  int g_next = 0;
  for (int j0 = 0; j0 < n; j0 += kChunk) {
    const int m = std::min(kChunk, n - j0);
    const auto o = static_cast<std::size_t>(j0);
    // Pass 1: each channel's power ratios for the chunk.
    for (int k = 0; k < nc; ++k) {
      const SlarElementContext& c = *channels[static_cast<std::size_t>(k)];
      const Sigma0Lut& lut = *c.lut;
      const PowerTables pt{!lut.empty(),         c.gain2->uniform(),    c.g2_uniform,
                           c.gain2_pairs.data(), c.sigma0_pairs.data(), lut.offsets(),
                           lut.any_category()};
      const BinsPassIo io{e.flags + o,
                          e.slant_range_m + o,
                          nullptr,
                          nullptr,
                          (e.incidence_rad ? e.incidence_rad : e.local_incidence_rad) + o,
                          e.local_incidence_rad + o,
                          nullptr,
                          e.category + o,
                          nullptr,
                          nullptr,
                          nullptr,
                          ratio + static_cast<std::size_t>(k) * kChunk,
                          s.area.data() + o};
      ratio_pass(m, pt, io);
      float* kept =
          element_power_w.empty() ? nullptr : element_power_w[static_cast<std::size_t>(k)];
      if (kept) {
        const float* r = ratio + static_cast<std::size_t>(k) * kChunk;
        for (int j = 0; j < m; ++j) {
          kept[o + static_cast<std::size_t>(j)] =
              static_cast<float>(element_power(c.power_scale, r[j]));
        }
      }
    }
    // Pass 2 for every channel at once: each element's bin and fraction
    // read once; its power into copy (first_index + j) % 4 of each channel
    // as scatter_pass adds it (the same operations, in the same order).
    for (int j = j0; j < j0 + m; ++j) {
      const std::size_t jj = static_cast<std::size_t>(j);
      const std::size_t q = static_cast<std::size_t>((e.first_index + j) & 3);
      const std::size_t b = q * stride + static_cast<std::size_t>(first[jj]);
      const double fr = double(frac_next[jj]);
      for (int k = 0; k < nc; ++k) {
        const std::size_t kk = static_cast<std::size_t>(k);
        const double p = element_power(channels[kk]->power_scale, ratio[kk * kChunk + (jj - o)]);
        const double h = p * fr;
        double* a = acc + kk * LineElementScratch::kCopies * stride + b;
        a[0] += p - h;
        a[1] += h;
      }
    }
    // Pass 3's elements of the chunk (the list the first channel gathered,
    // in element order): their ratios kept for after the last chunk.
    for (; g_next < s.n_general; ++g_next) {
      const std::size_t jj = static_cast<std::size_t>(s.general[static_cast<std::size_t>(g_next)]);
      if (jj >= o + static_cast<std::size_t>(m)) break;
      for (std::size_t k = 0; k < static_cast<std::size_t>(nc); ++k) {
        general_ratio[k * samples + static_cast<std::size_t>(g_next)] =
            ratio[k * kChunk + (jj - o)];
      }
    }
  }
  // Pass 3 into copy 0 of each channel, after pass 2 as form_line_profile
  // adds them (the same sums in the same order).
  for (int g = 0; g < s.n_general; ++g) {
    const std::size_t jj = static_cast<std::size_t>(s.general[static_cast<std::size_t>(g)]);
    if (!sample_visible(e.flags[jj])) continue;
    for (std::size_t k = 0; k < static_cast<std::size_t>(nc); ++k) {
      const SlarElementContext& c = *channels[k];
      const ElementSpan x = element_span(c, e, jj);
      if (x.hi < 0.0 || x.lo >= c.bins) continue;
      const double half =
          0.5 *
          element_power(c.power_scale, general_ratio[k * samples + static_cast<std::size_t>(g)]);
      double* a = acc + k * LineElementScratch::kCopies * stride;
      spread_fractions(x.xa, x.pos, c.bins, [&](int bin, double f) { a[bin] += half * f; });
      spread_fractions(x.pos, x.xb, c.bins, [&](int bin, double f) { a[bin] += half * f; });
    }
  }
}

RIS_VECTOR_CLONES void merge_channel(LineElementScratch& s, int channel,
                                     double* __restrict power_w) {
  RIS_CHECK(channel < s.channels);
  const std::size_t stride = s.stride();
  double* __restrict acc = s.channel_acc.data() +
                           static_cast<std::size_t>(channel) * LineElementScratch::kCopies * stride;
  const auto b0 = static_cast<std::size_t>(s.formed.lo), b1 = static_cast<std::size_t>(s.formed.hi);
  const auto bins = static_cast<std::size_t>(s.bins);
  std::fill(power_w, power_w + b0, 0.0);
  std::fill(power_w + b1, power_w + bins, 0.0);
  for (std::size_t b = b0; b < b1; ++b) {
    power_w[b] = (acc[b] + acc[b + stride]) + (acc[b + 2 * stride] + acc[b + 3 * stride]);
  }
  for (std::size_t q = 0; q < LineElementScratch::kCopies; ++q) {
    std::fill(acc + q * stride + b0, acc + q * stride + b1, 0.0);
  }
}

}  // namespace ris::detail
