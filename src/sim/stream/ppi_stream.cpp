#include "ris/sim/ppi_stream.h"

#include <fmt/format.h>
#include <gdal.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "kernels/image/slar_element.h"
#include "ris/backscatter/sigma0_lut.h"
#include "ris/geometry/ppi_geometry.h"
#include "ris/geometry/terrain_line.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/image/greytone.h"
#include "ris/image/ppi_scope.h"
#include "ris/image/slar_azimuth_integrator.h"
#include "ris/image/speckle.h"
#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/scene/scene_stream.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sim/ppi_products.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/run_metadata.h"
#include "ris/util/error.h"
#include "ris/util/process_group.h"
#include "ris/util/progress.h"
#include "ris/util/rank_select.h"
#include "sim/engine/block_schedule.h"
#include "sim/engine/slar_line_engine.h"
#include "sim/engine/texel_window.h"
#include "sim/sources/polar_lines.h"
#include "sim/stream/slant_stream_passes.h"
#include "sim/stream/slar_stream_targets.h"
#include "sim/targets/ppi_ray_targets.h"

namespace ris {

using detail::CellBox;
using detail::padded_box;
using detail::read_texel_window;
using detail::read_window;
using detail::sample_cells;
using detail::sample_from_window;
using detail::TexelWindow;
using detail::valid_power;

namespace {

constexpr std::int64_t kGdalCacheBytes = std::int64_t(256) << 20;
constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
constexpr int kDefaultSegmentSamples = 2048;
constexpr int kScopeStripRows = 256;

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

// The exact median's ranks and value (make_greytone_map's median of the
// valid pixels: the mean of the two middle values for an even count).
std::vector<std::uint64_t> median_ranks(std::uint64_t n) {
  if (n % 2 == 0) return {n / 2 - 1, n / 2};
  return {n / 2};
}

double median_value(const FloatRankSelect& sel, std::uint64_t n) {
  if (n % 2 != 0) return sel.value(0);
  return 0.5 * (double(sel.value(0)) + double(sel.value(1)));
}

// A block's counts of pass 1 (summed over the blocks; r_min and r_max: the
// slant range of the samples seen, for the swath-misses-the-scene message).
struct RayCounts {
  std::int64_t in_swath = 0, shadow = 0, layover = 0, back_facing = 0, nodata = 0;
  std::int64_t windows = 0, max_window_cells = 0;  // scene windows read
  float r_min = std::numeric_limits<float>::infinity();
  float r_max = -std::numeric_limits<float>::infinity();
  void add(const RayCounts& o) {
    in_swath += o.in_swath;
    shadow += o.shadow;
    layover += o.layover;
    back_facing += o.back_facing;
    nodata += o.nodata;
    windows += o.windows;
    max_window_cells = std::max(max_window_cells, o.max_window_cells);
    r_min = std::min(r_min, o.r_min);
    r_max = std::max(r_max, o.r_max);
  }
};

// A block of rays as computed by any rank of an MPI run and consumed, in
// ray order, by rank 0 (src/sim/engine/block_schedule.h): its range profiles,
// counts and its point targets' results (src/sim/targets/ppi_ray_targets.h).
struct RayBlock {
  int k0 = 0, k1 = 0;
  SlarLineProfiles prof;
  RayCounts counts;
  detail::BlockTargets targets;
};

void pack_ray_block(const RayBlock& k, std::vector<char>& out) {
  const auto put = [&](const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    out.insert(out.end(), c, c + n);
  };
  const int head[5] = {k.k0, k.k1, k.prof.line0, k.prof.lines, k.prof.bins};
  put(head, sizeof(head));
  put(&k.counts, sizeof(RayCounts));
  const std::size_t np = k.prof.power_w.size();
  put(k.prof.power_w.data(), np * sizeof(float));
  put(k.prof.area_m2.data(), np * sizeof(float));
  put(k.prof.touch.data(), np);
  put(k.prof.mapped_count.data(), np * sizeof(std::uint16_t));
  put(k.prof.visible_count.data(), np * sizeof(std::uint16_t));
  detail::pack_block_targets(k.targets, out);
}

RayBlock unpack_ray_block(const char* p, std::size_t n) {
  const char* const end = p + n;
  const auto get = [&](void* to, std::size_t bytes) {
    RIS_CHECK(std::size_t(end - p) >= bytes);
    std::memcpy(to, p, bytes);
    p += bytes;
  };
  RayBlock k;
  int head[5] = {};
  get(head, sizeof(head));
  k.k0 = head[0];
  k.k1 = head[1];
  k.prof.allocate(head[3], head[4], head[2]);
  get(&k.counts, sizeof(RayCounts));
  const std::size_t np = k.prof.power_w.size();
  get(k.prof.power_w.data(), np * sizeof(float));
  get(k.prof.area_m2.data(), np * sizeof(float));
  get(k.prof.touch.data(), np);
  get(k.prof.mapped_count.data(), np * sizeof(std::uint16_t));
  get(k.prof.visible_count.data(), np * sizeof(std::uint16_t));
  k.targets = detail::unpack_block_targets(p, end);
  RIS_CHECK(p == end);
  return k;
}

class PpiStreamRun {
 public:
  PpiStreamRun(const std::filesystem::path& scene_path, const RadarParams& radar,
               const SlarRunInfo& info, const std::filesystem::path& out_dir,
               const PpiStreamOptions& options)
      : in_(scene_path),
        order_{detail::block_schedule_from_environment(), options.faults.kill_block},
        fail_block_(options.faults.line_block),
        options_(options),
        info_(info),
        out_dir_(out_dir) {
    summary_.grid = in_.grid();
    sim().radar = radar;
    RIS_CHECK(radar.mode == RadarMode::ppi);
  }

  // Every rank of an MPI run (ris/util/process_group.h) runs passes 0 and 1
  // on its part (scene rows, blocks of rays); rank 0 alone writes, and runs
  // the passes after 1.
  PpiStreamSummary run(const Sigma0Source& sigma0) {
    const bool root = group_.rank() == 0;
    backscatter_file_ =
        info_.backscatter_path.empty() ? sigma0.description() : info_.backscatter_path;
    scene_block_rows_ = std::min(grid().rows, std::max(in_.block_rows(), 256));
    bar_.emplace("simulate (streamed PPI)", 2 * std::int64_t(grid().rows) * grid().cols, "cells",
                 options_.quiet || !root);
    stage("scene statistics");
    summarise_scene(sigma0);
    reduce_scene_summary();
    stage_done();
    set_up(sigma0);
    if (root) dir_.emplace(out_dir_);
    stage("rays: terrain, geometry, image formation, fading (pass 1)");
    rays_pass();
    stage_done();
    if (!root) return std::move(summary_);
    const GreytoneMap map = make_greytone_map_for_median(sim().radar, median_mean_power());
    // Passes 2 and 2b only for the products selected (--products).
    const ProductSelection& want = info_.products;
    stage("B-scope greytones (pass 2)");
    if (want.wants("bscope")) bscope_picture(map);
    stage_done();
    stage("scope (pass 2b)");
    if (want.wants("ppi_scope") || want.wants("ppi_scope_power") || want.wants("ppi_scope_mask"))
      scope_pass(map);
    stage_done();
    write_metadata(map);
    remove_unselected_products(dir_->path(""), info_.products);
    bar_->finish();
    dir_->commit();
    return std::move(summary_);
  }

 private:
  using ByteWriter = std::unique_ptr<GeoTiffBlockWriter<std::uint8_t>>;
  using FloatWriter = std::unique_ptr<GeoTiffBlockWriter<float>>;

  const Scene& grid() const { return summary_.grid; }
  PpiSimulation& sim() { return summary_.sim; }
  const PpiGeometry& pg() const { return summary_.sim.geometry; }
  int bins() const { return summary_.sim.derived.range_bins; }
  int all_rays() const { return summary_.sim.geometry.rays.lines; }
  int scan_rays() const { return summary_.sim.geometry.scan_rays; }
  int pad() const { return summary_.sim.geometry.pad; }

  void stage(const std::string& name) {
    summary_.stage_seconds.emplace_back(name, 0.0);
    bar_->set_stage(name);
    mark_ = std::chrono::steady_clock::now();
  }
  void stage_done() {
    summary_.stage_seconds.back().second =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - mark_).count();
  }

  // ---- Pass 0: what simulate_ppi learns from the whole scene ------------
  void summarise_scene(const Sigma0Source& sigma0) {
    std::vector<std::uint8_t> seen(65536, 0);
    const std::size_t cap = sz(scene_block_rows_) * sz(grid().cols);
    std::vector<float> z(cap);
    std::vector<std::uint16_t> cat(cap);
    std::vector<std::uint8_t> ok(cap);
    // This rank's rows: whole blocks of scene_block_rows_, split evenly.
    const int row_blocks = (grid().rows + scene_block_rows_ - 1) / scene_block_rows_;
    const auto part_row = [&](int rank) {
      const auto b = std::int64_t(row_blocks) * rank / group_.size();
      return static_cast<int>(std::min<std::int64_t>(b * scene_block_rows_, grid().rows));
    };
    const int row_end = part_row(group_.rank() + 1);
    for (int r0 = part_row(group_.rank()); r0 < row_end; r0 += scene_block_rows_) {
      const int n = std::min(scene_block_rows_, row_end - r0);
      in_.read(r0, n, 0, grid().cols, z.data(), cat.data(), ok.data());
      const std::size_t cells = sz(n) * sz(grid().cols);
      for (std::size_t i = 0; i < cells; ++i) {
        if (!ok[i]) {
          ++nodata_cells_;
          continue;
        }
        ++valid_cells_;
        const std::uint16_t c = cat[i];
        if (seen[c] == 0 && c != kNoDataCategory && !sigma0.has_category(c)) {
          throw InputError(backscatter_file_, "",
                           fmt::format("no backscatter for category {} (the scene {} uses it, "
                                       "first at row {}, column {}; add it to the backscatter "
                                       "file or give another with --backscatter)",
                                       c, in_.path(), r0 + static_cast<int>(i / sz(grid().cols)),
                                       static_cast<int>(i % sz(grid().cols))));
        }
        seen[c] = 1;
        h_min_ = std::min(h_min_, z[i]);
        h_max_ = std::max(h_max_, z[i]);
      }
      bar_->advance(static_cast<std::int64_t>(cells));
    }
    for (std::size_t c = 0; c < seen.size(); ++c)
      if (seen[c]) categories_.push_back(static_cast<std::uint16_t>(c));
  }

  // The whole scene's pass 0 from every rank's rows, on every rank: counts
  // summed, categories merged, the extremes folded in rank order (rows in
  // order) with summarise_scene's comparisons, so they are one process's.
  void reduce_scene_summary() {
    if (group_.size() == 1) return;
    std::vector<std::uint64_t> counts(65536 + 2, 0);
    counts[0] = static_cast<std::uint64_t>(valid_cells_);
    counts[1] = static_cast<std::uint64_t>(nodata_cells_);
    for (std::uint16_t c : categories_) counts[2 + sz(c)] = 1;
    group_.sum(counts);
    valid_cells_ = static_cast<std::int64_t>(counts[0]);
    nodata_cells_ = static_cast<std::int64_t>(counts[1]);
    categories_.clear();
    for (std::size_t c = 0; c < 65536; ++c)
      if (counts[2 + c] > 0) categories_.push_back(static_cast<std::uint16_t>(c));
    const float mine[2] = {h_min_, h_max_};
    std::vector<char> bytes(sizeof(mine));
    std::memcpy(bytes.data(), mine, sizeof(mine));
    h_min_ = std::numeric_limits<float>::infinity();
    h_max_ = -std::numeric_limits<float>::infinity();
    for (const std::vector<char>& b : group_.all_gather(bytes)) {
      float e[2] = {};
      RIS_CHECK(b.size() == sizeof(e));
      std::memcpy(e, b.data(), sizeof(e));
      h_min_ = std::min(h_min_, e[0]);
      h_max_ = std::max(h_max_, e[1]);
    }
  }

  // The terrain at the site as bilinear_terrain_sample gives it on the whole
  // scene (elevation and validity of its four cells, read as a window).
  TerrainSample site_terrain(double x_m, double y_m) {
    TerrainSample ts;
    const auto [cf, rf] = grid().grid_from_world(x_m, y_m);
    if (!(cf >= 0.0 && cf <= grid().cols && rf >= 0.0 && rf <= grid().rows)) return ts;
    ts.inside = true;
    const auto b = bilinear_cells<std::int64_t>(grid().rows, grid().cols, cf, rf);
    const int r = static_cast<int>(b.cell00 / grid().cols);
    const int c = static_cast<int>(b.cell00 % grid().cols);
    const int rows = b.step_row != 0 ? 2 : 1, cols = b.step_col != 0 ? 2 : 1;
    float z[4];
    std::uint16_t cat[4];
    std::uint8_t ok[4];
    in_.read(r, rows, c, cols, z, cat, ok);
    const int index[4] = {0, b.step_col != 0 ? 1 : 0, b.step_row != 0 ? cols : 0,
                          (b.step_row != 0 ? cols : 0) + (b.step_col != 0 ? 1 : 0)};
    float h = 0.0f;
    for (int k = 0; k < 4; ++k) {
      const float w = b.weight[k];
      if (!(w > 0.0f)) continue;
      if (!ok[index[k]]) return ts;
      h += w * z[index[k]];
    }
    ts.valid = true;
    ts.height_m = h;
    return ts;
  }

  // After pass 0: the checks and set-up of simulate_ppi and
  // compute_ppi_geometry, and the block sizes.
  void set_up(const Sigma0Source& sigma0) {
    if (valid_cells_ == 0) throw InputError("scene", "", "the scene has no cell with data");
    RadarParams& radar = sim().radar;
    sim().derived = derive(radar);
    site_radar_ = ppi_site_on_scene(radar, grid());
    check_ppi_site_inside(grid(), site_radar_);
    const double ground = check_ppi_site_terrain(
        site_radar_, site_terrain(site_radar_.ppi.site_x_m, site_radar_.ppi.site_y_m));
    sim().geometry = ppi_rays_layout(grid(), site_radar_, ground, h_min_);
    rs_ = prepare_radiometry(categories_, radar, sim().derived, sigma0, backscatter_file_);
    site_radar_.reference = radar.reference;
    place_targets();
    sim().categories = rs_.categories;
    sim().category_names = rs_.category_names;
    sim().backscatter_description = rs_.backscatter_description;
    sim().beam_rays = radar.azimuth_beamwidth_rad / pg().ray_spacing_rad;
    rs_.imaging.azimuth_window_lines = sim().beam_rays;
    RIS_CHECK(rs_.imaging.range.count == bins() && bins() > 0);
    SlarImage& b = sim().bscope;
    b.lines = scan_rays();
    b.bins = bins();
    b.range = rs_.imaging.range;
    sim().scope_grid =
        ppi_scope_grid(radar, b.range, b.lines, pg().altitude_m - pg().site_ground_m);

    const std::int64_t budget = std::max<std::int64_t>(options_.memory_budget_bytes, 64 << 20);
    const int samples = pg().rays.samples;
    segment_ = options_.segment_samples > 0 ? options_.segment_samples : kDefaultSegmentSamples;
    // A window: elevation, category, validity (7 bytes) and texel (16) a
    // cell, a quarter of the budget (a group of one ray's segment is read
    // whatever its size: a diagonal one spans segment / 2 cells a side).
    window_cells_ = options_.window_cells > 0 ? options_.window_cells : budget / 4 / 23;
    window_cells_ = std::max(window_cells_, std::int64_t(16));
    const std::int64_t per_ray = std::int64_t(samples) * 46 + std::int64_t(bins()) * 50;
    const int block = options_.block_rays > 0
                          ? options_.block_rays
                          : static_cast<int>(std::clamp<std::int64_t>(budget / 2 / per_ray, 1,
                                                                      std::max(all_rays(), 1)));
    // Over several MPI ranks, at least 4 blocks a rank, so the queue has
    // blocks to balance (the bytes do not depend on the block length).
    const int ranks = group_.size();
    const int for_ranks = ranks > 1 && options_.block_rays <= 0
                              ? std::max(16, (all_rays() + 4 * ranks - 1) / (4 * ranks))
                              : all_rays();
    summary_.block_rays = std::max(1, std::min({block, all_rays(), for_ranks}));
  }

  // The targets checked on the scene (as check_point_targets_on_scene, on
  // every rank) and placed on the padded rays (ray_candidates, their base
  // heights read from the scene file: streamed_target_heights).
  void place_targets() {
    const std::vector<PointTarget>& targets = options_.targets;
    if (targets.empty()) return;
    const std::vector<double> base = detail::streamed_target_heights(targets, in_);
    candidates_ = detail::ray_candidates(targets, base, pg(), target_of_);
    lit_.assign(candidates_.size(), 0);
    target_power_.assign(candidates_.size(), 0.0);
  }

  // The candidates on rays [k0, k1) for a block (none: nullopt).
  std::optional<detail::LinePointTargets> candidates_on_rays(int k0, int k1) const {
    std::vector<PointCandidate> on;
    for (const PointCandidate& c : candidates_)
      if (c.ret.line >= k0 && c.ret.line < k1) on.push_back(c);
    if (on.empty()) return std::nullopt;
    return detail::LinePointTargets(std::move(on));
  }

  template <typename T>
  std::unique_ptr<GeoTiffBlockWriter<T>> open_writer(const std::string& file, int cols, int rows,
                                                     const RasterMetadata& meta,
                                                     const std::string& band,
                                                     const Georef* georef) {
    return std::make_unique<GeoTiffBlockWriter<T>>(
        dir_->path(file), cols, rows, std::vector<std::string>{band}, georef,
        std::is_floating_point_v<T>
            ? std::optional<double>(std::numeric_limits<double>::quiet_NaN())
            : std::nullopt,
        meta, product_tiff_settings(info_, std::is_floating_point_v<T>));
  }

  // ---- Pass 1: rays in blocks -------------------------------------------
  // The terrain of rays [k0, k1) (padded ray numbers), sampled into
  // terrain_* (ray k - k0 at row (k - k0) x samples, sample j at j - begin).
  void sample_block_terrain(int k0, int k1) {
    const int n = k1 - k0, samples = pg().rays.samples;
    const std::size_t cap = sz(n) * sz(samples);
    t_height_.resize(cap);
    t_dzdx_.resize(cap);
    t_dzdy_.resize(cap);
    t_cat_.resize(cap);
    t_flags_.resize(cap);
    lines_.resize(sz(n));
    span_.resize(sz(n));
    for (int k = k0; k < k1; ++k) {
      lines_[sz(k - k0)] = ppi_ray_line(grid(), pg(), k);
      span_[sz(k - k0)] = inside_samples(lines_[sz(k - k0)], grid().rows, grid().cols, samples);
    }
    // Range segment by segment; within one, groups of consecutive rays whose
    // cells fit a window.
    for (int a = 0; a < samples; a += segment_) {
      const int b = std::min(samples, a + segment_);
      CellBox group;
      int g0 = -1;
      for (int k = 0; k < n; ++k) {
        const CellBox box = ray_cells(k, a, b);
        if (box.empty()) continue;
        const CellBox u = group.united(box);
        if (g0 >= 0 && padded_cells(u) > window_cells_) {
          sample_group(g0, k, a, b, group);
          group = box;
          g0 = k;
        } else {
          if (g0 < 0) g0 = k;
          group = u;
        }
      }
      if (g0 >= 0) sample_group(g0, n, a, b, group);
    }
  }

  // The cells ray k - k0's samples [a, b) touch (positions are monotone
  // along a ray: its first and last sample bound them).
  CellBox ray_cells(int k, int a, int b) const {
    const auto [begin, end] = span_[sz(k)];
    const int js = std::max(a, begin), je = std::min(b, end);
    if (js >= je) return {};
    return sample_cells(grid(), lines_[sz(k)], js)
        .united(sample_cells(grid(), lines_[sz(k)], je - 1));
  }

  // The cells of a box grown by the one cell each side the slopes read.
  std::int64_t padded_cells(const CellBox& c) const { return padded_box(c, grid()).cells(); }

  // Rays [g0, g1) (block-relative), samples [a, b), from one window.
  void sample_group(int g0, int g1, int a, int b, const CellBox& cells) {
    const TexelWindow tw = read_texel_window(in_, cells, ws_);
    const std::size_t nc = sz(tw.rows) * sz(tw.cols);
    ++block_counts_->windows;
    block_counts_->max_window_cells = std::max(block_counts_->max_window_cells, std::int64_t(nc));
    const int samples = pg().rays.samples;
#pragma omp parallel for schedule(dynamic, 1)
    for (int k = g0; k < g1; ++k) {
      const auto [begin, end] = span_[sz(k)];
      const int js = std::max(a, begin), je = std::min(b, end);
      if (js >= je) continue;
      const std::size_t at = sz(k) * sz(samples) + sz(js - begin);
      sample_from_window(tw, grid(), lines_[sz(k)], js, je,
                         {t_height_.data() + at, t_dzdx_.data() + at, t_dzdy_.data() + at,
                          t_cat_.data() + at, t_flags_.data() + at});
    }
  }

  // Rays [k0, k1) through the line engine: the windowed polar source's
  // geometry from the sampled terrain, then each ray's range profile and
  // point returns (the in-memory run's per-line stages,
  // sim/sources/polar_lines.h), a ray per engine block as the threads take
  // them.
  void block_profiles(int k0, int k1, SlarLineProfiles& prof, RayCounts& counts,
                      detail::LinePointTargets* targets) {
    prof.allocate(k1 - k0, bins(), k0);
    prof.samples_in_swath = 0;
    const detail::LineKeep keep{nullptr, nullptr, targets};
    const detail::LineStages stages{*ctx_, LineLookFrame{}, false, rs_.imaging.range_window_bins,
                                    targets != nullptr ? &keep : nullptr};
    const detail::SampledRays rays{
        pg(),           k0, span_, t_height_.data(), t_dzdx_.data(), t_dzdy_.data(), t_cat_.data(),
        t_flags_.data()};
    SlarLineCounts c;
    detail::run_line_blocks(pg().rays, stages, k0, k1, 1, prof, c, [&](detail::LineScratch&) {
      return detail::WindowedPolarThreadSource{rays};
    });
    counts.in_swath += prof.samples_in_swath;
    counts.shadow += c.shadow;
    counts.layover += c.layover;
    counts.back_facing += c.back_facing;
    counts.nodata += c.nodata;
    counts.r_min = std::min(counts.r_min, c.r_min_m);
    counts.r_max = std::max(counts.r_max, c.r_max_m);
  }

  struct Sinks {
    FloatWriter mean, speckled;
    ByteWriter mask;
  };

  Sinks open_sinks() {
    Sinks sinks;
    sinks.mean = open_writer<float>("mean_power_bscope.tif", bins(), scan_rays(), specs_.bscope,
                                    "mean_power_w", nullptr);
    sinks.speckled = open_writer<float>("speckled_power_bscope.tif", bins(), scan_rays(),
                                        specs_.bscope, "speckled_power_w", nullptr);
    sinks.mask = open_writer<std::uint8_t>("mask_bscope.tif", bins(), scan_rays(), specs_.bscope,
                                           "mask", nullptr);
    return sinks;
  }

  // Blocks of rays computed on any rank (compute_block) and integrated,
  // faded and written by rank 0 in ray order: the azimuth integrator's
  // running sums are summed in ray order, as in one process
  // (docs/scale.md).
  void rays_pass() {
    const bool root = group_.rank() == 0;
    const SlarImage& b = sim().bscope;
    std::optional<Sinks> sinks;
    std::optional<SlarAzimuthIntegrator> az;
    if (root) {
      specs_ = ppi_raster_specs(grid(), sim());
      sinks.emplace(open_sinks());
      looks_.resize(sz(bins()));
      for (int k = 0; k < bins(); ++k)
        looks_[sz(k)] =
            independent_samples(sim().radar, b.range.near_m + (k + 0.5) * b.range.bin_m);
      az.emplace(rs_.imaging, pg().rays.line_spacing_m, all_rays(), bins());
    }
    const TwoWayGainTable gain2(rs_.imaging.elevation_gain, rs_.imaging.peak_gain,
                                sim().radar.source_file);
    ctx_.emplace(detail::element_context(rs_.imaging, gain2, rs_.lut, bins()));
    const std::int64_t cells = std::int64_t(grid().rows) * grid().cols;
    const int blocks = (all_rays() + summary_.block_rays - 1) / summary_.block_rays;
    RayCounts counts;
    detail::run_blocks_in_order<RayBlock>(
        group_, blocks, order_, [&](int k) { return compute_block(k); }, pack_ray_block,
        unpack_ray_block,
        [&](int, RayBlock& k) {
          counts.add(k.counts);
          add_block_targets(k.targets);
          az->push(k.prof, k.k1 - k.k0);
          emit_ready(*az, *sinks);
          ++summary_.blocks;
          bar_->advance(cells * (k.k1 - k.k0) / std::max(all_rays(), 1));
          if (spare_.size() < 2) spare_.push_back(std::move(k));
        });
    if (!root) return;
    RIS_CHECK(az->lines_emitted() == all_rays());
    if (counts.in_swath == 0) {
      throw InputError(sim().radar.source_file, "sweep_delay",
                       fmt::format("the swath (slant range {:.1f} to {:.1f} m) misses the scene, "
                                   "which spans slant range {:.1f} to {:.1f} m; expected a sweep "
                                   "delay and length (or near range and range bins) that overlap "
                                   "it",
                                   b.range.near_m, b.range.far_m(), counts.r_min, counts.r_max));
    }
    summary_.windows = counts.windows;
    summary_.max_window_cells = counts.max_window_cells;
    SlarGeometry& g = sim().geometry.rays;
    g.nodata_samples = counts.nodata;
    g.shadow_samples = counts.shadow;
    g.back_facing_samples = counts.back_facing;
    g.layover_samples = counts.layover;
    g.nodata_cells = nodata_cells_;
    sim().bscope.samples_in_swath = counts.in_swath;
    detail::fold_ray_targets(options_.targets, candidates_, target_of_, lit_, target_power_,
                             sim().point_returns, sim().bscope.point_power_w, sim().hidden_targets);
    sinks->mean->close();
    sinks->speckled->close();
    sinks->mask->close();
  }

  // Rank 0: a block's candidates found lit or not, and their powers.
  void add_block_targets(const detail::BlockTargets& t) {
    for (std::size_t i = 0; i < t.candidate.size(); ++i) {
      const auto c = static_cast<std::size_t>(t.candidate[i]);
      RIS_CHECK(c < candidates_.size());
      lit_[c] = t.lit[i];
      target_power_[c] = t.power_w[i];
    }
  }

  // Block b's rays on this rank: their terrain from windows of the scene
  // file, geometry and range profiles.
  RayBlock compute_block(int b) {
    RayBlock k;
    if (!spare_.empty()) {  // buffers reused
      k = std::move(spare_.back());
      spare_.pop_back();
    }
    if (b == fail_block_) {
      throw std::runtime_error(fmt::format("block {}: a failure injected by RIS_FAIL_BLOCK", b));
    }
    k.k0 = b * summary_.block_rays;
    k.k1 = std::min(all_rays(), k.k0 + summary_.block_rays);
    k.counts = RayCounts();
    block_counts_ = &k.counts;
    sample_block_terrain(k.k0, k.k1);
    std::optional<detail::LinePointTargets> on_rays = candidates_on_rays(k.k0, k.k1);
    block_profiles(k.k0, k.k1, k.prof, k.counts, on_rays ? &*on_rays : nullptr);
    block_counts_ = nullptr;
    // Each candidate's result (by_line[i].target: the candidate's index).
    k.targets = detail::BlockTargets();
    if (on_rays) {
      for (std::size_t i = 0; i < on_rays->by_line.size(); ++i) {
        k.targets.candidate.push_back(static_cast<std::int32_t>(on_rays->by_line[i].target));
        k.targets.lit.push_back(on_rays->lit[i]);
        k.targets.power_w.push_back(on_rays->power_w[i]);
      }
    }
    return k;
  }

  // The rays the integrator has ready: switch corrections, then those of the
  // sector (the padding rays dropped) written with NaN for no data and
  // fading (keyed by seed, bin and sector ray, as render_ppi).
  void emit_ready(SlarAzimuthIntegrator& az, Sinks& sinks) {
    const int n = az.lines_ready();
    if (n == 0) return;
    const int k0 = az.lines_emitted();
    const std::size_t np = sz(n) * sz(bins());
    SlarImage block;
    block.lines = n;
    block.bins = bins();
    block.range = rs_.imaging.range;
    block.mean_power_w.resize(np);
    block.area_m2.resize(np);
    block.mask.resize(np);
    az.emit(n, block.mean_power_w.data(), block.area_m2.data(), block.mask.data());
    apply_switch_corrections(block, rs_.terms);
    const int s0 = std::max(k0, pad()), s1 = std::min(k0 + n, pad() + scan_rays());
    if (s1 <= s0) return;
    const int m = s1 - s0;
    const std::size_t at = block.index(s0 - k0, 0), nm = sz(m) * sz(bins());
    mean_.assign(block.mean_power_w.begin() + static_cast<std::ptrdiff_t>(at),
                 block.mean_power_w.begin() + static_cast<std::ptrdiff_t>(at + nm));
    mask_.assign(block.mask.begin() + static_cast<std::ptrdiff_t>(at),
                 block.mask.begin() + static_cast<std::ptrdiff_t>(at + nm));
    for (std::size_t i = 0; i < nm; ++i) {
      if (valid_power(mean_[i], mask_[i])) power_.count(mean_[i]);
      if (mask_[i] & pixel_flag::kNoData) mean_[i] = kNaNf;
    }
    speckled_ = mean_;
    if (sim().radar.switches.fading)
      apply_fading(speckled_, m, bins(), looks_, sim().radar.fading, info_.seed, s0 - pad());
    sinks.mean->write(mean_.data(), m);
    sinks.speckled->write(speckled_.data(), m);
    sinks.mask->write(mask_.data(), m);
  }

  // B-scope rays read back at a time by passes 1b and 2: up to a tile's
  // height (256), within an eighth of the budget (~10 bytes a pixel).
  int readback_rays() const {
    const std::int64_t fit = options_.memory_budget_bytes / 8 / (std::int64_t(bins()) * 10);
    return std::max(summary_.block_rays, static_cast<int>(std::clamp<std::int64_t>(fit, 1, 256)));
  }

  // ---- Pass 1b: the median mean power (auto greytone reference) ---------
  double median_mean_power() {
    const std::uint64_t n_power = power_.total();
    if (!(sim().radar.reference.automatic && n_power > 0))
      return std::numeric_limits<double>::quiet_NaN();
    stage("median mean power (pass 1b)");
    power_.select(median_ranks(n_power));
    GdalDataset mean_ds = open_raster(dir_->path("mean_power_bscope.tif").string());
    GdalDataset mask_ds = open_raster(dir_->path("mask_bscope.tif").string());
    const int step = readback_rays();
    for (int k0 = 0; k0 < scan_rays(); k0 += step) {
      const int n = std::min(step, scan_rays() - k0);
      const std::size_t np = sz(n) * sz(bins());
      mean_.resize(np);
      mask_.resize(np);
      read_window(handle(mean_ds), k0, n, 0, bins(), mean_.data(), GDT_Float32,
                  "mean_power_bscope.tif");
      read_window(handle(mask_ds), k0, n, 0, bins(), mask_.data(), GDT_Byte, "mask_bscope.tif");
      for (std::size_t i = 0; i < np; ++i)
        if (valid_power(mean_[i], mask_[i])) power_.refine(mean_[i]);
    }
    const double median = median_value(power_, n_power);
    stage_done();
    return median;
  }

  // ---- Pass 2: the B-scope's greytones ----------------------------------
  void bscope_picture(const GreytoneMap& map) {
    const std::filesystem::path tmp = dir_->path(".bscope.png.tmp.tif");
    {
      GeoTiffBlockWriter<std::uint8_t> out(tmp, bins(), scan_rays(), {""}, nullptr);
      GdalDataset sp_ds = open_raster(dir_->path("speckled_power_bscope.tif").string());
      GdalDataset mask_ds = open_raster(dir_->path("mask_bscope.tif").string());
      const int step = readback_rays();
      std::vector<std::uint8_t> no_data, grey;
      for (int k0 = 0; k0 < scan_rays(); k0 += step) {
        const int n = std::min(step, scan_rays() - k0);
        const std::size_t np = sz(n) * sz(bins());
        speckled_.resize(np);
        mask_.resize(np);
        read_window(handle(sp_ds), k0, n, 0, bins(), speckled_.data(), GDT_Float32,
                    "speckled_power_bscope.tif");
        read_window(handle(mask_ds), k0, n, 0, bins(), mask_.data(), GDT_Byte, "mask_bscope.tif");
        no_data.resize(np);
        for (std::size_t i = 0; i < np; ++i) no_data[i] = (mask_[i] & pixel_flag::kNoData) ? 1 : 0;
        grey.resize(np);
        greytones(speckled_, grey, map, no_data);
        out.write(grey.data(), n);
      }
      out.close();
    }
    write_png_gray_from_raster(dir_->path("bscope.png"), tmp,
                               png_compression_level(info_.compression));
    std::filesystem::remove(tmp);
  }

  // ---- Pass 2b: the scope, a strip of rows at a time --------------------
  // Each pixel's B-scope source (ppi_scope_source); per ray, the bins the
  // strip takes, read back as one span; then power, mask and greytones as
  // render_ppi (to_ppi_scope, to_ppi_scope_nearest, greytones, rings).
  void scope_pass(const GreytoneMap& map) {
    const PpiScopeGrid& sg = sim().scope_grid;
    const int size = sg.size;
    const Georef* ref = specs_.scope_georeferenced ? &specs_.georef : nullptr;
    const std::filesystem::path tmp = dir_->path(".ppi_scope.png.tmp.tif");
    {
      FloatWriter power_out = open_writer<float>("ppi_scope_power.tif", size, size, specs_.scope,
                                                 "speckled_power_w", ref);
      ByteWriter mask_out =
          open_writer<std::uint8_t>("ppi_scope_mask.tif", size, size, specs_.scope, "mask", ref);
      GeoTiffBlockWriter<std::uint8_t> grey_out(tmp, size, size, {""}, nullptr);
      GdalDataset sp_ds = open_raster(dir_->path("speckled_power_bscope.tif").string());
      GdalDataset mask_ds = open_raster(dir_->path("mask_bscope.tif").string());
      const int rays = scan_rays();
      std::vector<std::int64_t> src;
      std::vector<int> lo(sz(rays)), hi(sz(rays));
      std::vector<std::size_t> offset(sz(rays));
      std::vector<float> power, ray_power;
      std::vector<std::uint8_t> mask, no_data, grey, ray_mask;
      const double rings = sim().radar.ppi.ring_spacing_m;
      for (int r0 = 0; r0 < size; r0 += kScopeStripRows) {
        const int n = std::min(kScopeStripRows, size - r0);
        const std::size_t np = sz(n) * sz(size);
        src.resize(np);
        std::fill(lo.begin(), lo.end(), bins());
        std::fill(hi.begin(), hi.end(), -1);
#pragma omp parallel for schedule(static)
        for (int r = 0; r < n; ++r)
          for (int c = 0; c < size; ++c)
            src[sz(r) * sz(size) + sz(c)] = ppi_scope_source(sg, r0 + r, c);
        for (std::size_t i = 0; i < np; ++i) {
          if (src[i] < 0) continue;
          const auto ray = sz(src[i] / bins());
          const int bin = static_cast<int>(src[i] % bins());
          lo[ray] = std::min(lo[ray], bin);
          hi[ray] = std::max(hi[ray], bin);
        }
        std::size_t total = 0;
        for (int k = 0; k < rays; ++k) {
          offset[sz(k)] = total;
          if (hi[sz(k)] >= lo[sz(k)]) total += sz(hi[sz(k)] - lo[sz(k)] + 1);
        }
        ray_power.resize(total);
        ray_mask.resize(total);
        for (int k = 0; k < rays; ++k) {
          if (hi[sz(k)] < lo[sz(k)]) continue;
          const int w = hi[sz(k)] - lo[sz(k)] + 1;
          read_window(handle(sp_ds), k, 1, lo[sz(k)], w, ray_power.data() + offset[sz(k)],
                      GDT_Float32, "speckled_power_bscope.tif");
          read_window(handle(mask_ds), k, 1, lo[sz(k)], w, ray_mask.data() + offset[sz(k)],
                      GDT_Byte, "mask_bscope.tif");
        }
        power.assign(np, kNaNf);
        mask.assign(np, pixel_flag::kNoData);
        for (std::size_t i = 0; i < np; ++i) {
          if (src[i] < 0) continue;
          const auto ray = sz(src[i] / bins());
          const std::size_t at = offset[ray] + sz(src[i] % bins() - lo[ray]);
          power[i] = ray_power[at];
          mask[i] = ray_mask[at];
        }
        no_data.resize(np);
        for (std::size_t i = 0; i < np; ++i) no_data[i] = (mask[i] & pixel_flag::kNoData) ? 1 : 0;
        grey.resize(np);
        greytones(power, grey, map, no_data);
        if (rings > 0.0) {
          for (int r = 0; r < n; ++r)
            for (int c = 0; c < size; ++c)
              if (on_range_ring(sg, r0 + r, c, rings)) grey[sz(r) * sz(size) + sz(c)] = 255;
        }
        power_out->write(power.data(), n);
        mask_out->write(mask.data(), n);
        grey_out.write(grey.data(), n);
      }
      power_out->close();
      mask_out->close();
      grey_out.close();
    }
    write_png_gray_from_raster(dir_->path("ppi_scope.png"), tmp,
                               png_compression_level(info_.compression));
    std::filesystem::remove(tmp);
  }

  void write_metadata(const GreytoneMap& map) {
    PpiPictures pic;
    pic.seed = info_.seed;
    pic.looks = looks_;
    pic.reference_power_w = map.reference_power_w();
    pic.reference_greytone = map.reference_greytone();
    pic.greytones_per_decade = map.greytones_per_decade();
    pic.film_offset = map.film_offset();
    const SceneSummary scene{grid(), h_min_, h_max_, nodata_cells_};
    write_text_file_atomic(dir_->path("metadata.json"),
                           ppi_metadata(scene, sim(), pic, info_).dump(2) + "\n");
  }

  const SceneStreamReader in_;
  ProcessGroup& group_ = process_group();
  const detail::BlockOrder order_;  // schedule, and the fault plan's kill_block
  const int fail_block_;            // FaultPlan::line_block, -1: none
  const PpiStreamOptions& options_;
  const SlarRunInfo& info_;
  const std::filesystem::path out_dir_;
  PpiStreamSummary summary_;
  std::string backscatter_file_;
  RadarParams site_radar_;  // the radar with its site on the scene's grid
  std::optional<ProgressBar> bar_;
  std::optional<StagedDirectory> dir_;
  std::chrono::steady_clock::time_point mark_;
  int scene_block_rows_ = 0;
  int segment_ = kDefaultSegmentSamples;
  std::int64_t window_cells_ = 0;
  // Pass 0.
  std::int64_t valid_cells_ = 0, nodata_cells_ = 0;
  float h_min_ = std::numeric_limits<float>::infinity();
  float h_max_ = -std::numeric_limits<float>::infinity();
  std::vector<std::uint16_t> categories_;
  // Set-up.
  RadiometrySetup rs_;
  std::optional<detail::SlarElementContext> ctx_;
  PpiRasterSpecs specs_;
  std::vector<double> looks_;
  // Point targets: the candidates on the padded rays (in target and ray
  // order), each one's target, and (rank 0) whether lit and its power.
  std::vector<PointCandidate> candidates_;
  std::vector<std::size_t> target_of_;
  std::vector<std::uint8_t> lit_;
  std::vector<double> target_power_;
  // Pass 1: per block.
  std::vector<GridLine> lines_;
  std::vector<std::pair<int, int>> span_;  // inside_samples per ray
  std::vector<float> t_height_, t_dzdx_, t_dzdy_;
  std::vector<std::uint16_t> t_cat_;
  std::vector<std::uint8_t> t_flags_;
  Scene ws_;                           // the window
  RayCounts* block_counts_ = nullptr;  // the block being computed
  std::vector<RayBlock> spare_;        // consumed blocks, their buffers reused
  FloatRankSelect power_;
  std::vector<float> mean_, speckled_;
  std::vector<std::uint8_t> mask_;
};

}  // namespace

PpiStreamSummary simulate_ppi_streamed(const std::filesystem::path& scene_path,
                                       const RadarParams& radar, const Sigma0Source& sigma0,
                                       const SlarRunInfo& info,
                                       const std::filesystem::path& out_dir,
                                       const PpiStreamOptions& options) {
  bound_gdal_cache(kGdalCacheBytes);
  PpiStreamRun run(scene_path, radar, info, out_dir, options);
  return run.run(sigma0);
}

}  // namespace ris
