// The fused line engine's kernels along a grid axis
// (kernels/sim/line_block_kernels.h), moved from sim/slar_line_blocks.cpp
// unchanged but for their arguments (plain pointers instead of the engine's
// structs), beside their scalar twins.
#include "kernels/sim/line_block_kernels.h"

#include <cmath>
#include <limits>

#include "kernels/simd/vec8.h"
#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/kernels/vector_clones.h"
#include "ris/util/units.h"

namespace ris::kernels {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// slope_difference (ris/geometry/surface_gradient.h) on eight cells at a
// time: the same operations in double precision (the division too), so the
// same floats; lo_ok and hi_ok are lane masks. The neighbours are chosen in
// single precision (a float select, then the exact widening) and the
// double-precision selects are bitwise: GCC compiles `?:` on eight doubles
// into a branch per lane.
__attribute__((always_inline)) inline vec8::F8 slope_difference8(vec8::I8 lo_ok, vec8::F8 z_lo,
                                                                 vec8::I8 hi_ok, vec8::F8 z_hi,
                                                                 vec8::F8 z_c, double step_m) {
  using vec8::D8;
  using L8 = std::int64_t __attribute__((vector_size(64)));
  const auto select = [](L8 m, D8 x, D8 y) { return D8((m & L8(x)) | (~m & L8(y))); };
  const D8 a = __builtin_convertvector(hi_ok ? z_hi : z_c, D8);
  const D8 b = __builtin_convertvector(lo_ok ? z_lo : z_c, D8);
  const D8 num = select(__builtin_convertvector(lo_ok | hi_ok, L8), a - b, D8{});
  const D8 den =
      select(__builtin_convertvector(lo_ok & hi_ok, L8), D8{} + 2.0 * step_m, D8{} + step_m);
  return __builtin_convertvector(num / den, vec8::F8);
}

}  // namespace

// The cells of row r of the window (all columns) into the scratch in sample
// order (column c is sample c, or cols - 1 - c with `reverse`, where u grows
// towards the west: written in place, no reversal afterwards): height, slope
// (slope_difference, as surface_gradient), category and the flags (kNoData,
// and kUnseen from s.unseen); NaN height and slope where a cell has no data.
// Rows outside the scene read `none` (no data). The interior columns eight
// at a time in vector types (kernels/simd/vec8.h; GCC does not vectorise the scalar
// loop: its double-precision selects on byte flags), the edges and the
// remainder by the scalar `one`, the same operations. With an AVX-512
// clone (this file is compiled with -ffp-contract=off): the eight doubles
// in one register (~2% of the fused benchmark, as map_row's).
RIS_WIDE_VECTOR_CLONES void gather_row(const CellRow& row, double dx_m, double dy_m, bool reverse,
                                       const LineTerrainOut& out) {
  const int cols = row.cols;
  const float* __restrict z = row.z;
  const std::uint8_t* __restrict v = row.valid;
  const std::uint16_t* __restrict cat = row.category;
  // North (+y) is towards row r - 1: the "hi" neighbour of dz/dy.
  const float* __restrict zu = row.z_north;
  const std::uint8_t* __restrict vu = row.valid_north;
  const float* __restrict zd = row.z_south;
  const std::uint8_t* __restrict vd = row.valid_south;
  float* __restrict h = out.height_m;
  float* __restrict gx = out.dz_dx;
  float* __restrict gy = out.dz_dy;
  std::uint16_t* __restrict cg = out.category;
  std::uint8_t* __restrict fl = out.flags;
  const std::uint8_t* __restrict unseen = out.unseen;
  const auto one = [&](int c, bool left_ok, bool right_ok, float zl, float zr) {
    const bool ok = v[c] != 0;
    const float zc = z[c];
    const float sx = slope_difference(left_ok, zl, right_ok, zr, zc, dx_m);
    const float sy = slope_difference(vd[c] != 0, zd[c], vu[c] != 0, zu[c], zc, dy_m);
    const int j = reverse ? cols - 1 - c : c;
    h[j] = ok ? zc : kNaN;
    gx[j] = ok ? sx : kNaN;
    gy[j] = ok ? sy : kNaN;
    const std::uint16_t k = cat[c];  // loaded unconditionally: no control flow
    cg[j] = ok ? k : std::uint16_t{0};
    fl[j] = static_cast<std::uint8_t>((ok ? 0 : sample_flag::kNoData) | unseen[j]);
  };
  if (cols == 1) {
    one(0, false, false, 0.0f, 0.0f);
    return;
  }
  one(0, false, v[1] != 0, 0.0f, z[1]);
  using namespace vec8;
  // Whether eight bytes are all non-zero (the classic zero-byte test).
  const auto all_nonzero = [](const std::uint8_t* p) {
    const auto x = load<std::uint64_t>(p);
    return ((x - 0x0101010101010101u) & ~x & 0x8080808080808080u) == 0;
  };
  const auto valid8 = [](const std::uint8_t* p) { return widen_u8(load<U8x8>(p)) != 0; };
  const I8 reversed = {7, 6, 5, 4, 3, 2, 1, 0};
  const F8 nan = splat(kNaN);
  int c = 1;
  for (; c + kLanes <= cols - 1; c += kLanes) {
    const auto cc = static_cast<std::size_t>(c);
    const F8 zc = load<F8>(z + cc);
    F8 hh, sxx, syy;
    I8 k, nodata;
    if (all_nonzero(v + cc - 1) && all_nonzero(v + cc + 1) && all_nonzero(vd + cc) &&
        all_nonzero(vu + cc)) {
      // The eight cells and their neighbours all have data (most blocks):
      // slope_difference's central difference without its selects.
      const auto central = [](F8 z_lo, F8 z_hi, double step_m) {
        return __builtin_convertvector(
            (__builtin_convertvector(z_hi, D8) - __builtin_convertvector(z_lo, D8)) /
                (D8{} + 2.0 * step_m),
            F8);
      };
      hh = zc;
      sxx = central(load<F8>(z + cc - 1), load<F8>(z + cc + 1), dx_m);
      syy = central(load<F8>(zd + cc), load<F8>(zu + cc), dy_m);
      k = __builtin_convertvector(load<U16x8>(cat + cc), I8);
      nodata = I8{};
    } else {
      const I8 ok = valid8(v + cc);
      const F8 sx = slope_difference8(valid8(v + cc - 1), load<F8>(z + cc - 1), valid8(v + cc + 1),
                                      load<F8>(z + cc + 1), zc, dx_m);
      const F8 sy = slope_difference8(valid8(vd + cc), load<F8>(zd + cc), valid8(vu + cc),
                                      load<F8>(zu + cc), zc, dy_m);
      hh = ok ? zc : nan;
      sxx = ok ? sx : nan;
      syy = ok ? sy : nan;
      k = ok ? __builtin_convertvector(load<U16x8>(cat + cc), I8) : I8{};
      nodata = ~ok & sample_flag::kNoData;
    }
    if (reverse) {
      hh = vec8::shuffle(hh, reversed);
      sxx = vec8::shuffle(sxx, reversed);
      syy = vec8::shuffle(syy, reversed);
      k = vec8::shuffle(k, reversed);
      nodata = vec8::shuffle(nodata, reversed);
    }
    const std::size_t j = reverse ? static_cast<std::size_t>(cols - kLanes - c) : cc;
    store(h + j, hh);
    store(gx + j, sxx);
    store(gy + j, syy);
    store(cg + j, __builtin_convertvector(k, U16x8));
    store(fl + j, narrow_u8(nodata) | load<U8x8>(unseen + j));
  }
  for (; c < cols - 1; ++c) one(c, v[c - 1] != 0, v[c + 1] != 0, z[c - 1], z[c + 1]);
  one(cols - 1, v[cols - 2] != 0, false, z[cols - 2], 0.0f);
}

// The scene-grid maps of a row of cells that is one line: sample j is cell
// j, or cols - 1 - j (`reverse`) where u grows towards the west. Eight
// samples at a time in vector types (kernels/simd/vec8.h), the same operations as
// scene_map_cell (which takes the remainder), so the same bytes; a scalar
// loop over cells was a fifth of the fused stage (a double division per
// cell for the degrees, and branches).
RIS_WIDE_VECTOR_CLONES void map_row(int n, bool reverse, double near_m, double far_m,
                                    const std::uint8_t* __restrict flags,
                                    const float* __restrict range,
                                    const float* __restrict local_incidence,
                                    const std::uint8_t* __restrict valid,
                                    std::uint8_t* __restrict mask, float* __restrict deg) {
  using namespace vec8;
  // double(R) >= near_m <=> R >= near_f, the smallest float whose double is
  // >= near_m (likewise far_m): the comparisons in single precision.
  const auto float_at_or_above = [](double x) {
    float f = static_cast<float>(x);
    if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
  };
  const F8 near_f = splat(float_at_or_above(near_m)), far_f = splat(float_at_or_above(far_m));
  const F8 nan = splat(kNaN);
  const I8 reversed = {7, 6, 5, 4, 3, 2, 1, 0};
  const int full = n / kLanes * kLanes;
  for (int j = 0; j < full; j += kLanes) {
    const auto jj = static_cast<std::size_t>(j);
    const I8 sf = widen_u8(load<U8x8>(flags + jj));
    const F8 r = load<F8>(range + jj);
    const I8 has_data = (sf & (sample_flag::kNoData | sample_flag::kUnseen)) == 0;
    I8 f = ((sf & sample_flag::kNoData) != 0) & scene_flag::kNoData;
    f |= ((sf & sample_flag::kShadow) != 0) & scene_flag::kShadow;
    f |= ((sf & sample_flag::kLayover) != 0) & scene_flag::kLayover;
    f |= ((sf & sample_flag::kBackFacing) != 0) & scene_flag::kBackFacing;
    const I8 in_swath = (r >= near_f) & (r < far_f);
    f |= (((sf & sample_flag::kUnseen) != 0) | (has_data & ~in_swath)) & scene_flag::kOutsideSwath;
    // rad_to_deg in double, as scene_map_sample.
    const D8 rad = __builtin_convertvector(load<F8>(local_incidence + jj), D8);
    const F8 d = __builtin_convertvector(rad * 180.0 / kPi, F8);
    const std::size_t c = reverse ? static_cast<std::size_t>(n - kLanes - j) : jj;
    I8 ok = widen_u8(load<U8x8>(valid + c)) != 0;
    if (reverse) ok = vec8::shuffle(ok, reversed);
    f |= ~ok & scene_flag::kNoData;
    F8 out = (has_data & ok) ? d : nan;
    if (reverse) {
      f = vec8::shuffle(f, reversed);
      out = vec8::shuffle(out, reversed);
    }
    store(mask + c, narrow_u8(f));
    store(deg + c, out);
  }
  for (int j = full; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    const auto c = static_cast<std::size_t>(reverse ? n - 1 - j : j);
    scene_map_cell(valid[c] != 0, flags[jj], range[jj], local_incidence[jj], near_m, far_m, mask[c],
                   deg[c]);
  }
}

namespace {

// The 8 x 8 transpose of eight 8-lane rows of 32-bit lanes, in place
// (three rounds of two-input shuffles, as unpack / shuffle / permute).
template <class V>
[[gnu::always_inline]] inline void transpose8(V (&a)[8]) {
  using vec8::I8;
  V t[8], u[8];
  for (int i = 0; i < 8; i += 2) {
    t[i] = vec8::shuffle(a[i], a[i + 1], I8{0, 8, 1, 9, 4, 12, 5, 13});
    t[i + 1] = vec8::shuffle(a[i], a[i + 1], I8{2, 10, 3, 11, 6, 14, 7, 15});
  }
  for (int i = 0; i < 8; i += 4) {
    u[i] = vec8::shuffle(t[i], t[i + 2], I8{0, 1, 8, 9, 4, 5, 12, 13});
    u[i + 1] = vec8::shuffle(t[i], t[i + 2], I8{2, 3, 10, 11, 6, 7, 14, 15});
    u[i + 2] = vec8::shuffle(t[i + 1], t[i + 3], I8{0, 1, 8, 9, 4, 5, 12, 13});
    u[i + 3] = vec8::shuffle(t[i + 1], t[i + 3], I8{2, 3, 10, 11, 6, 7, 14, 15});
  }
  for (int i = 0; i < 4; ++i) {
    a[i] = vec8::shuffle(u[i], u[i + 4], I8{0, 1, 2, 3, 8, 9, 10, 11});
    a[i + 4] = vec8::shuffle(u[i], u[i + 4], I8{4, 5, 6, 7, 12, 13, 14, 15});
  }
}

}  // namespace

// ColumnTile's transposes, eight rows by eight columns at a time through
// registers (transpose8; rows taken last to first, so that each column
// comes out in the tile's reversed row order), in functions of their own
// for the AVX2 / AVX-512 clones (the baseline's 16-byte registers would
// split every shuffle). Scene cell (r, c) of the block's rows [0, rows8)
// and columns [0, cols8) is src + r * stride + c; its tile entry is
// (tile_rows - 1 - c) * len + len - 1 - r.
RIS_WIDE_VECTOR_CLONES void transpose_into_tile(
    int rows8, int cols8, int tile_rows, std::size_t len, std::size_t stride,
    const float* __restrict z, const std::uint16_t* __restrict cat,
    const std::uint8_t* __restrict v, float* __restrict tz, std::uint16_t* __restrict tcat,
    std::uint8_t* __restrict tv) {
  using namespace vec8;
  for (int r = 0; r < rows8; r += kLanes) {
    const std::size_t k0 = len - kLanes - static_cast<std::size_t>(r);  // row r + 7's entry
    for (int c = 0; c < cols8; c += kLanes) {
      F8 zz[kLanes];
      I8 kk[kLanes], vv[kLanes];
      for (int i = 0; i < kLanes; ++i) {
        const std::size_t from =
            static_cast<std::size_t>(r + kLanes - 1 - i) * stride + static_cast<std::size_t>(c);
        zz[i] = load<F8>(z + from);
        kk[i] = __builtin_convertvector(load<U16x8>(cat + from), I8);
        vv[i] = widen_u8(load<U8x8>(v + from));
      }
      transpose8(zz);
      transpose8(kk);
      transpose8(vv);
      for (int j = 0; j < kLanes; ++j) {
        const std::size_t to = static_cast<std::size_t>(tile_rows - 1 - c - j) * len + k0;
        store(tz + to, zz[j]);
        store(tcat + to, __builtin_convertvector(kk[j], U16x8));
        store(tv + to, narrow_u8(vv[j]));
      }
    }
  }
}

// The inverse for the scene maps: tile entry (tile_rows - 1 - c) * len +
// len - 1 - r into dst + r * stride + c.
RIS_WIDE_VECTOR_CLONES void transpose_from_tile(int rows8, int cols8, int tile_rows,
                                                std::size_t len, std::size_t stride,
                                                const std::uint8_t* __restrict tmask,
                                                const float* __restrict tdeg,
                                                std::uint8_t* __restrict mask,
                                                float* __restrict deg) {
  using namespace vec8;
  for (int r = 0; r < rows8; r += kLanes) {
    const std::size_t k0 = len - kLanes - static_cast<std::size_t>(r);
    for (int c = 0; c < cols8; c += kLanes) {
      F8 dd[kLanes];
      I8 mm[kLanes];
      for (int i = 0; i < kLanes; ++i) {
        const std::size_t from = static_cast<std::size_t>(tile_rows - 1 - c - i) * len + k0;
        dd[i] = load<F8>(tdeg + from);
        mm[i] = widen_u8(load<U8x8>(tmask + from));
      }
      transpose8(dd);
      transpose8(mm);
      // Row j: entry k0 + j of the eight columns, scene row r + 7 - j.
      for (int j = 0; j < kLanes; ++j) {
        const std::size_t to =
            static_cast<std::size_t>(r + kLanes - 1 - j) * stride + static_cast<std::size_t>(c);
        store(deg + to, dd[j]);
        store(mask + to, narrow_u8(mm[j]));
      }
    }
  }
}

// ---- Scalar twins: the same operations one cell at a time ----------------

void gather_row_scalar(const CellRow& row, double dx_m, double dy_m, bool reverse,
                       const LineTerrainOut& out) {
  const int cols = row.cols;
  for (int c = 0; c < cols; ++c) {
    const bool left = c > 0, right = c + 1 < cols;
    const bool ok = row.valid[c] != 0;
    const float zc = row.z[c];
    const float sx =
        slope_difference(left && row.valid[c - 1] != 0, left ? row.z[c - 1] : 0.0f,
                         right && row.valid[c + 1] != 0, right ? row.z[c + 1] : 0.0f, zc, dx_m);
    const float sy = slope_difference(row.valid_south[c] != 0, row.z_south[c],
                                      row.valid_north[c] != 0, row.z_north[c], zc, dy_m);
    const int j = reverse ? cols - 1 - c : c;
    out.height_m[j] = ok ? zc : kNaN;
    out.dz_dx[j] = ok ? sx : kNaN;
    out.dz_dy[j] = ok ? sy : kNaN;
    out.category[j] = ok ? row.category[c] : std::uint16_t{0};
    out.flags[j] = static_cast<std::uint8_t>((ok ? 0 : sample_flag::kNoData) | out.unseen[j]);
  }
}

void map_row_scalar(int n, bool reverse, double near_m, double far_m, const std::uint8_t* flags,
                    const float* range, const float* local_incidence, const std::uint8_t* valid,
                    std::uint8_t* mask, float* deg) {
  for (int j = 0; j < n; ++j) {
    const auto jj = static_cast<std::size_t>(j);
    const auto c = static_cast<std::size_t>(reverse ? n - 1 - j : j);
    scene_map_cell(valid[c] != 0, flags[jj], range[jj], local_incidence[jj], near_m, far_m, mask[c],
                   deg[c]);
  }
}

void transpose_into_tile_scalar(int rows8, int cols8, int tile_rows, std::size_t len,
                                std::size_t stride, const float* z, const std::uint16_t* cat,
                                const std::uint8_t* v, float* tz, std::uint16_t* tcat,
                                std::uint8_t* tv) {
  for (int r = 0; r < rows8; ++r) {
    for (int c = 0; c < cols8; ++c) {
      const std::size_t from = static_cast<std::size_t>(r) * stride + static_cast<std::size_t>(c);
      const std::size_t to =
          static_cast<std::size_t>(tile_rows - 1 - c) * len + len - 1 - static_cast<std::size_t>(r);
      tz[to] = z[from];
      tcat[to] = cat[from];
      tv[to] = v[from];
    }
  }
}

void transpose_from_tile_scalar(int rows8, int cols8, int tile_rows, std::size_t len,
                                std::size_t stride, const std::uint8_t* tmask, const float* tdeg,
                                std::uint8_t* mask, float* deg) {
  for (int r = 0; r < rows8; ++r) {
    for (int c = 0; c < cols8; ++c) {
      const std::size_t from =
          static_cast<std::size_t>(tile_rows - 1 - c) * len + len - 1 - static_cast<std::size_t>(r);
      const std::size_t to = static_cast<std::size_t>(r) * stride + static_cast<std::size_t>(c);
      mask[to] = tmask[from];
      deg[to] = tdeg[from];
    }
  }
}

}  // namespace ris::kernels
