#include "ris/sim/slar_line_blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/util/error.h"
#include "ris/util/thread_ranges.h"
#include "ris/util/units.h"
#include "ris/util/vector_clones.h"
#include "sim/slar_line_kernels.h"
#include "util/vec8.h"

namespace ris {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool nearly(double a, double b) {
  return std::abs(a - b) < 1e-9;
}

// The zero bytes in v[i0, i1): 32-bit counts per block, which vectorise
// (std::count's 64-bit count widened every byte: 1.1 ms for the 2000 x 2000
// scene's no-data cells on one thread, this 0.24 ms).
std::int64_t count_zero_bytes(const std::uint8_t* v, std::size_t i0, std::size_t i1) {
  constexpr std::size_t kBlock = 1 << 16;
  std::int64_t total = 0;
  for (std::size_t b = i0; b < i1; b += kBlock) {
    const std::size_t e = std::min(i1, b + kBlock);
    std::uint32_t count = 0;
    for (std::size_t i = b; i < e; ++i) count += v[i] == 0 ? 1u : 0u;
    total += count;
  }
  return total;
}

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

// The cells of row r of the window (all columns) into the scratch in sample
// order (column c is sample c, or cols - 1 - c with `reverse`, where u grows
// towards the west: written in place, no reversal afterwards): height, slope
// (slope_difference, as surface_gradient), category and the flags (kNoData,
// and kUnseen from s.unseen); NaN height and slope where a cell has no data.
// Rows outside the scene read `none` (no data). The interior columns eight
// at a time in vector types (util/vec8.h; GCC does not vectorise the scalar
// loop: its double-precision selects on byte flags), the edges and the
// remainder by the scalar `one`, the same operations. With an AVX-512
// clone (this file is compiled with -ffp-contract=off): the eight doubles
// in one register (~2% of the fused benchmark, as map_row's).
RIS_WIDE_VECTOR_CLONES void gather_row(const SceneWindow& in, int scene_rows, int r, double dx_m,
                                       double dy_m, const std::uint8_t* none_valid,
                                       const float* none_z, bool reverse, detail::LineScratch& s) {
  const int cols = in.cols;
  const std::size_t base = in.index(r, in.col0);
  const float* __restrict z = in.elevation_m + base;
  const std::uint8_t* __restrict v = in.valid + base;
  const std::uint16_t* __restrict cat = in.category + base;
  // North (+y) is towards row r - 1: the "hi" neighbour of dz/dy.
  const bool up_in = r - 1 >= 0, down_in = r + 1 < scene_rows;
  const float* __restrict zu = up_in ? z - in.cols : none_z;
  const std::uint8_t* __restrict vu = up_in ? v - in.cols : none_valid;
  const float* __restrict zd = down_in ? z + in.cols : none_z;
  const std::uint8_t* __restrict vd = down_in ? v + in.cols : none_valid;
  float* __restrict h = s.height.data();
  float* __restrict gx = s.dz_dx.data();
  float* __restrict gy = s.dz_dy.data();
  std::uint16_t* __restrict cg = s.category.data();
  std::uint8_t* __restrict fl = s.flags.data();
  const std::uint8_t* __restrict unseen = s.unseen.data();
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
      hh = __builtin_shuffle(hh, reversed);
      sxx = __builtin_shuffle(sxx, reversed);
      syy = __builtin_shuffle(syy, reversed);
      k = __builtin_shuffle(k, reversed);
      nodata = __builtin_shuffle(nodata, reversed);
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
// samples at a time in vector types (util/vec8.h), the same operations as
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
    if (reverse) ok = __builtin_shuffle(ok, reversed);
    f |= ~ok & scene_flag::kNoData;
    F8 out = (has_data & ok) ? d : nan;
    if (reverse) {
      f = __builtin_shuffle(f, reversed);
      out = __builtin_shuffle(out, reversed);
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

// The 8 x 8 transpose of eight 8-lane rows of 32-bit lanes, in place
// (three rounds of two-input shuffles, as unpack / shuffle / permute).
template <class V>
[[gnu::always_inline]] inline void transpose8(V (&a)[8]) {
  using vec8::I8;
  V t[8], u[8];
  for (int i = 0; i < 8; i += 2) {
    t[i] = __builtin_shuffle(a[i], a[i + 1], I8{0, 8, 1, 9, 4, 12, 5, 13});
    t[i + 1] = __builtin_shuffle(a[i], a[i + 1], I8{2, 10, 3, 11, 6, 14, 7, 15});
  }
  for (int i = 0; i < 8; i += 4) {
    u[i] = __builtin_shuffle(t[i], t[i + 2], I8{0, 1, 8, 9, 4, 5, 12, 13});
    u[i + 1] = __builtin_shuffle(t[i], t[i + 2], I8{2, 3, 10, 11, 6, 7, 14, 15});
    u[i + 2] = __builtin_shuffle(t[i + 1], t[i + 3], I8{0, 1, 8, 9, 4, 5, 12, 13});
    u[i + 3] = __builtin_shuffle(t[i + 1], t[i + 3], I8{2, 3, 10, 11, 6, 7, 14, 15});
  }
  for (int i = 0; i < 4; ++i) {
    a[i] = __builtin_shuffle(u[i], u[i + 4], I8{0, 1, 2, 3, 8, 9, 10, 11});
    a[i + 4] = __builtin_shuffle(u[i], u[i + 4], I8{4, 5, 6, 7, 12, 13, 14, 15});
  }
}

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

// Lines along columns (a track heading east or west): a block of lines'
// columns, with one column of margin each side, transposed so that each
// column is one contiguous row; gather_row and map_row then run on it as on
// a row of cells, instead of a per-cell loop with strided reads and writes
// (3.5x the row path's time for the fused stage at 2000 x 2000). Tile row t
// holds scene column cols - 1 - t and tile column k scene row rows - 1 - k:
// with both reversed, gather_row's in-row neighbours (k - 1, k + 1) are the
// cell's south and north neighbours (dz/dy's lo and hi in
// surface_gradient's rule) and its rows above and below (t - 1, t + 1) the
// east and west neighbours (dz/dx's hi and lo): the same slope_difference
// calls as the per-cell rule, with the two slopes coming out swapped and
// the steps exchanged.
struct ColumnTile {
  int scene_cols = 0;
  int c_lo = 0, c_hi = -1;  // scene columns held, inclusive
  int len = 0;              // scene rows: the tile's row length
  std::vector<float> z;
  std::vector<std::uint16_t> cat;
  std::vector<std::uint8_t> valid;
  std::vector<std::uint8_t> mask;  // map_row's output, in the tile's layout
  std::vector<float> deg;

  int row_of_column(int c) const { return scene_cols - 1 - c; }
  int t0() const { return row_of_column(c_hi); }
  std::size_t offset(int c) const {
    return static_cast<std::size_t>(row_of_column(c) - t0()) * static_cast<std::size_t>(len);
  }
  SceneWindow window() const {
    return {t0(), 0, c_hi - c_lo + 1, len, z.data(), cat.data(), valid.data()};
  }
  // Columns [lo, hi] of `in` (which holds every scene row), transposed.
  void load_columns(const SceneWindow& in, int scene_columns, int lo, int hi) {
    scene_cols = scene_columns;
    c_lo = lo;
    c_hi = hi;
    len = in.rows;
    const std::size_t n = static_cast<std::size_t>(hi - lo + 1) * static_cast<std::size_t>(len);
    if (z.size() < n) {
      z.resize(n);
      cat.resize(n);
      valid.resize(n);
      mask.resize(n);
      deg.resize(n);
    }
    // Eight rows by eight columns at a time (transpose_into_tile), the
    // edges one cell at a time.
    const auto one = [&](int r, int c) {
      const std::size_t from = in.index(in.row0 + r, c);
      const std::size_t to = offset(c) + static_cast<std::size_t>(len - 1 - r);
      z[to] = in.elevation_m[from];
      cat[to] = in.category[from];
      valid[to] = in.valid[from];
    };
    const int width = hi - lo + 1;
    const int c8 = lo + width / vec8::kLanes * vec8::kLanes;
    const int r8 = len / vec8::kLanes * vec8::kLanes;
    const std::size_t from = in.index(in.row0, lo);
    transpose_into_tile(r8, c8 - lo, width, static_cast<std::size_t>(len),
                        static_cast<std::size_t>(in.cols), in.elevation_m + from,
                        in.category + from, in.valid + from, z.data(), cat.data(), valid.data());
    for (int r = 0; r < r8; ++r)
      for (int c = c8; c <= hi; ++c) one(r, c);
    for (int r = r8; r < len; ++r)
      for (int c = lo; c <= hi; ++c) one(r, c);
  }
  // The map values of the tile's columns [first, first + n) (each a line
  // of the block) back into the scene grid: eight by eight through
  // registers, as load_columns().
  void store_maps(int first, int n, const SceneMapsWindow& maps) const {
    const auto one = [&](int r, int c) {
      const std::size_t from = offset(c) + static_cast<std::size_t>(len - 1 - r);
      const std::size_t to = maps.index(maps.row0 + r, c);
      maps.mask[to] = mask[from];
      maps.local_incidence_deg[to] = deg[from];
    };
    const int end = first + n;
    const int c8 = first + n / vec8::kLanes * vec8::kLanes;
    const int r8 = len / vec8::kLanes * vec8::kLanes;
    // The tile's column `first` is tile row offset(first) / len; the
    // columns after it are the rows before.
    const int tile_rows = static_cast<int>(offset(first) / static_cast<std::size_t>(len)) + 1;
    const std::size_t to = maps.index(maps.row0, first);
    transpose_from_tile(r8, c8 - first, tile_rows, static_cast<std::size_t>(len),
                        static_cast<std::size_t>(maps.cols), mask.data(), deg.data(),
                        maps.mask + to, maps.local_incidence_deg + to);
    for (int r = 0; r < r8; ++r)
      for (int c = c8; c < end; ++c) one(r, c);
    for (int r = r8; r < len; ++r)
      for (int c = first; c < end; ++c) one(r, c);
  }
};

// Lines per block of the column path: the tile (34 columns of 7 bytes a
// cell and the maps' 5: 0.8 MB for 2000 rows) stays in L2, and the two
// margin columns are a small share of its scalar edges. Measured on the
// 2000 x 2000 bench scene at heading 90, fused stage on 1 thread: 8 lines
// 64-68 ms, 16 54 ms, 24 53 ms, 32 52-53 ms (heading 0: 41 ms).
constexpr int kColumnBlockLines = 32;

}  // namespace

SlarLineCounts::SlarLineCounts()
    : r_min_m(std::numeric_limits<float>::infinity()),
      r_max_m(-std::numeric_limits<float>::infinity()) {}

void SlarLineCounts::add(const SlarLineCounts& o) {
  nodata += o.nodata;
  shadow += o.shadow;
  back_facing += o.back_facing;
  layover += o.layover;
  r_min_m = std::min(r_min_m, o.r_min_m);
  r_max_m = std::max(r_max_m, o.r_max_m);
}

bool fused_slar_applies(const Scene& scene, const SlarGeometry& g) {
  if (!g.direct_sampling) return false;
  const bool along_y = nearly(std::abs(g.track.along_y), 1.0);
  const double cell_m = along_y ? scene.dy_m : scene.dx_m;
  const int n = along_y ? scene.rows : scene.cols;
  return g.line_spacing_m == cell_m && g.lines == n;
}

SlarLineEngine::SlarLineEngine(const Scene& scene, const SlarGeometry& layout, const Sigma0Lut& lut,
                               const SlarImagingParams& params, const std::string& radar_file)
    : scene_(scene),
      g_(layout),
      lut_(lut),
      params_(params),
      gain2_(params.elevation_gain, params.peak_gain, radar_file) {
  RIS_CHECK(g_.direct_sampling);
  const Track& t = g_.track;
  const bool along_y = nearly(std::abs(t.along_y), 1.0);
  cross_is_x_ = along_y;
  u_grows_with_index_ = along_y ? t.cross_x > 0.0 : t.cross_y < 0.0;
}

namespace {

// The row (cross_is_x) or column of cells line `line` runs over; -1: none.
int line_cell(const Scene& scene, const SlarGeometry& g, bool cross_is_x, int line) {
  const auto [x, y] = g.track.world_from_along_cross(g.line_s_m(line), 0.0);
  const auto [cf, rf] = scene.grid_from_world(x, y);
  const double f = cross_is_x ? rf : cf;
  const int n = cross_is_x ? scene.rows : scene.cols;
  return (f >= 0.0 && f < n) ? static_cast<int>(std::floor(f)) : -1;
}

// Whether lines [b0, b1) (along columns) each take their own column, the
// columns forming one run [lo, hi]; `scratch` holds them.
bool column_run(const Scene& scene, const SlarGeometry& g, int b0, int b1,
                std::vector<int>& scratch, int& lo, int& hi) {
  scratch.clear();
  for (int line = b0; line < b1; ++line) scratch.push_back(line_cell(scene, g, false, line));
  std::sort(scratch.begin(), scratch.end());
  if (scratch.empty() || scratch.front() < 0) return false;
  lo = scratch.front();
  hi = scratch.back();
  return hi - lo + 1 == b1 - b0 &&
         std::adjacent_find(scratch.begin(), scratch.end()) == scratch.end();
}

}  // namespace

int SlarLineEngine::cell_of_line(int line) const {
  return line_cell(scene_, g_, cross_is_x_, line);
}

void SlarLineEngine::window_for_lines(int line0, int line1, int& row0, int& rows, int& col0,
                                      int& cols) const {
  int lo = std::numeric_limits<int>::max(), hi = -1;
  for (int line : {line0, line1 - 1}) {
    const int c = line_cell(scene_, g_, cross_is_x_, line);
    if (c < 0) continue;
    lo = std::min(lo, c);
    hi = std::max(hi, c);
  }
  const int n = cross_is_x_ ? scene_.rows : scene_.cols;
  if (hi < 0) {
    lo = 0;
    hi = -1;
  } else {
    lo = std::max(0, lo - 1);
    hi = std::min(n - 1, hi + 1);
  }
  if (cross_is_x_) {
    row0 = lo;
    rows = hi - lo + 1;
    col0 = 0;
    cols = scene_.cols;
  } else {
    col0 = lo;
    cols = hi - lo + 1;
    row0 = 0;
    rows = scene_.rows;
  }
}

void SlarLineEngine::run(int line0, int line1, const SceneWindow& in, SlarLineProfiles& prof,
                         const SceneMapsWindow& maps, SlarLineCounts& counts) const {
  const SlarGeometry& g = g_;
  const Scene& scene = scene_;
  const Track& t = g.track;
  const double H = g.altitude_m;
  const int samples = g.samples;
  const int bins = prof.bins;
  const LineLookFrame frame{H, t.cross_x, t.cross_y, g.line_spacing_m * g.sample_step_m};
  const bool need_incidence = !gain2_.uniform();
  const double near_m = params_.range.near_m, far_m = params_.range.far_m();

  const detail::SlarElementContext ctx = detail::element_context(params_, gain2_, lut_, bins);

  const auto ok = [&](int r, int c) {
    return scene.contains(r, c) && in.valid[in.index(r, c)] != 0;
  };
  const auto z = [&](int r, int c) {
    return scene.contains(r, c) ? in.elevation_m[in.index(r, c)] : 0.0f;
  };

  // Lines along columns whose window holds every scene row go by blocks
  // through a transposed tile (ColumnTile); rows and the rest line by line.
  const bool column_tiles =
      !cross_is_x_ && in.row0 == 0 && in.rows == samples && maps.row0 == 0 && maps.rows == samples;
  const int block_lines = column_tiles ? kColumnBlockLines : 16;
  const int blocks = (line1 - line0 + block_lines - 1) / block_lines;

  std::int64_t in_swath = 0;
#pragma omp parallel reduction(+ : in_swath)
  {
    detail::LineScratch s(g, bins);
    SlarLineCounts local;
    ColumnTile tile;
    std::vector<int> columns;
#pragma omp for schedule(dynamic, 1)
    for (int block = 0; block < blocks; ++block) {
      const int b0 = line0 + block * block_lines, b1 = std::min(line1, b0 + block_lines);
      // Tiled when the block's lines take one run of distinct columns [lo,
      // hi] (one line per column, as fused_slar_applies makes them); the
      // tile adds one column of margin each side.
      int lo = 0, hi = -1;
      const bool tiled = column_tiles && column_run(scene, g, b0, b1, columns, lo, hi);
      if (tiled)
        tile.load_columns(in, scene.cols, std::max(0, lo - 1), std::min(scene.cols - 1, hi + 1));
      for (int line = b0; line < b1; ++line) {
        const int lc = line_cell(scene, g, cross_is_x_, line);
        const auto cell_of = [&](int j, int& r, int& c) {
          if (cross_is_x_) {
            r = lc;
            c = u_grows_with_index_ ? j : scene.cols - 1 - j;
          } else {
            c = lc;
            r = u_grows_with_index_ ? j : scene.rows - 1 - j;
          }
        };

        // The terrain under each sample (as slar_geometry.cpp fill_line with
        // its DirectSampler, the slope computed in place as surface_gradient).
        if (cross_is_x_ && lc >= 0 && in.col0 == 0 && in.cols == samples) {
          // A row of cells, contiguous in memory.
          gather_row(in, scene.rows, lc, scene.dx_m, scene.dy_m, s.none_valid.data(),
                     s.none_z.data(), !u_grows_with_index_, s);
        } else if (tiled && lc >= 0) {
          // A column, as a row of the transposed tile: the steps exchanged,
          // the slopes swapped back (ColumnTile).
          gather_row(tile.window(), scene.cols, tile.row_of_column(lc), scene.dy_m, scene.dx_m,
                     s.none_valid.data(), s.none_z.data(), u_grows_with_index_, s);
          std::swap(s.dz_dx, s.dz_dy);
        } else
          for (int j = 0; j < samples; ++j) {
            const std::size_t jj = static_cast<std::size_t>(j);
            std::uint8_t f = 0;
            int r = 0, c = 0;
            bool valid = false;
            if (lc < 0) {
              f |= sample_flag::kUnseen;
            } else {
              cell_of(j, r, c);
              valid = in.valid[in.index(r, c)] != 0;
              if (!valid) f |= sample_flag::kNoData;
            }
            if (!(g.sample_u_m(j) > 0.0)) f |= sample_flag::kUnseen;
            s.flags[jj] = f;
            if (lc < 0 || !valid) {
              s.height[jj] = s.dz_dx[jj] = s.dz_dy[jj] = kNaN;
              s.category[jj] = 0;
              continue;
            }
            const std::size_t i = in.index(r, c);
            const float zc = in.elevation_m[i];
            s.height[jj] = zc;
            s.dz_dx[jj] = slope_difference(ok(r, c - 1), z(r, c - 1), ok(r, c + 1), z(r, c + 1), zc,
                                           scene.dx_m);
            // North (+y) is towards row r - 1.
            s.dz_dy[jj] = slope_difference(ok(r + 1, c), z(r + 1, c), ok(r - 1, c), z(r - 1, c), zc,
                                           scene.dy_m);
            s.category[jj] = in.category[i];
          }

        detail::line_geometry(g, frame, need_incidence, s);
        in_swath +=
            detail::accumulate_line(ctx, samples, s, prof, line, local, params_.range_window_bins);

        // The scene-grid maps (scene_geometry_maps: each cell is its own
        // sample here).
        if (cross_is_x_ && lc >= 0 && in.col0 == 0 && in.cols == samples && maps.col0 == 0 &&
            maps.cols == samples) {
          map_row(samples, !u_grows_with_index_, near_m, far_m, s.flags.data(), s.range.data(),
                  s.local_incidence.data(), in.valid + in.index(lc, 0),
                  maps.mask + maps.index(lc, 0), maps.local_incidence_deg + maps.index(lc, 0));
        } else if (tiled && lc >= 0) {
          const std::size_t at = tile.offset(lc);
          map_row(samples, u_grows_with_index_, near_m, far_m, s.flags.data(), s.range.data(),
                  s.local_incidence.data(), tile.valid.data() + at, tile.mask.data() + at,
                  tile.deg.data() + at);
        } else if (lc >= 0) {
          for (int j = 0; j < samples; ++j) {
            const std::size_t jj = static_cast<std::size_t>(j);
            int r = 0, c = 0;
            cell_of(j, r, c);
            const std::size_t cell = maps.index(r, c);
            scene_map_cell(in.valid[in.index(r, c)] != 0, s.flags[jj], s.range[jj],
                           s.local_incidence[jj], near_m, far_m, maps.mask[cell],
                           maps.local_incidence_deg[cell]);
          }
        }
      }
      if (tiled) tile.store_maps(lo, hi - lo + 1, maps);
    }
#pragma omp critical(ris_slar_line_counts)
    counts.add(local);
  }
  prof.samples_in_swath += in_swath;
}

bool fused_slar_image_applies(const Scene& scene, const SlarGeometry& layout) {
  return fused_slar_applies(scene, layout) || !layout.direct_sampling;
}

SlarImage form_slar_image_fused(const Scene& scene, SlarGeometry& g, SceneGeometryMaps& maps,
                                const Sigma0Lut& lut, const SlarImagingParams& p,
                                const std::string& radar_file) {
  RIS_CHECK(fused_slar_image_applies(scene, g));
  RIS_CHECK(p.range.count > 0 && p.range.bin_m > 0.0);
  RIS_CHECK(p.azimuth_beamwidth_rad > 0.0);
  SlarLineProfiles prof;
  prof.allocate(g.lines, p.range.count);
  // No fill (UninitVector): along a grid axis every cell is written by the
  // line on its row or column (one line per row or column, checked below);
  // the oblique path sets every cell first itself.
  maps.mask.resize(scene.size());
  maps.local_incidence_deg.resize(scene.size());
  SlarLineCounts counts;
  if (g.direct_sampling) {
    const SlarLineEngine engine(scene, g, lut, p, radar_file);
    {
      RIS_CHECK(static_cast<std::size_t>(g.lines) * static_cast<std::size_t>(g.samples) ==
                scene.size());
      std::vector<std::uint8_t> taken(static_cast<std::size_t>(g.lines), 0);
      for (int line = 0; line < g.lines; ++line) {
        const int cell = engine.cell_of_line(line);
        RIS_CHECK(cell >= 0 && cell < g.lines && !taken[static_cast<std::size_t>(cell)]);
        taken[static_cast<std::size_t>(cell)] = 1;
      }
    }
    const SceneMapsWindow out{
        0, 0, scene.rows, scene.cols, maps.mask.data(), maps.local_incidence_deg.data()};
    engine.run(0, g.lines, SceneWindow::whole(scene), prof, out, counts);
  } else {
    detail::run_oblique_lines(scene, g, lut, p, radar_file, prof, maps, counts);
  }
  g.nodata_samples = counts.nodata;
  g.shadow_samples = counts.shadow;
  g.back_facing_samples = counts.back_facing;
  g.layover_samples = counts.layover;
  // Counted by the threads (a serial count over the scene was a serial step).
  std::int64_t nodata_cells = 0;
  for_thread_ranges(scene.size(), [&](std::size_t i0, std::size_t i1) {
    const std::int64_t part = count_zero_bytes(scene.valid.data(), i0, i1);
#pragma omp atomic
    nodata_cells += part;
  });
  g.nodata_cells = nodata_cells;
  if (prof.samples_in_swath == 0) {
    throw InputError(radar_file, "sweep_delay",
                     fmt::format("the swath (slant range {:.1f} to {:.1f} m) misses the scene, "
                                 "which spans slant range {:.1f} to {:.1f} m; expected a sweep "
                                 "delay and length (or near range and range bins) that overlap it",
                                 p.range.near_m, p.range.far_m(), counts.r_min_m, counts.r_max_m));
  }
  SlarImage img;
  img.lines = g.lines;
  img.bins = p.range.count;
  img.range = p.range;
  img.line_spacing_m = g.line_spacing_m;
  img.samples_in_swath = prof.samples_in_swath;
  integrate_slar_azimuth(prof, p, g.line_spacing_m, img);
  img.mapped_count = std::move(prof.mapped_count);
  img.visible_count = std::move(prof.visible_count);
  return img;
}

}  // namespace ris
