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

  std::int64_t in_swath = 0;
#pragma omp parallel reduction(+ : in_swath)
  {
    detail::LineScratch s(g, bins);
    SlarLineCounts local;
#pragma omp for schedule(dynamic, 16)
    for (int line = line0; line < line1; ++line) {
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
        gather_row(in, scene.rows, lc, scene.dx_m, scene.dy_m, s.none_valid.data(), s.none_z.data(),
                   !u_grows_with_index_, s);
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
                s.local_incidence.data(), in.valid + in.index(lc, 0), maps.mask + maps.index(lc, 0),
                maps.local_incidence_deg + maps.index(lc, 0));
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
