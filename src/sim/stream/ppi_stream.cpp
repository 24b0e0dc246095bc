#include "ris/sim/ppi_stream.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ris/geometry/ppi_geometry.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/image/greytone.h"
#include "ris/image/ppi_scope.h"
#include "ris/image/speckle.h"
#include "ris/image/swath_miss.h"
#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/scene/scene_stream.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sim/ppi_products.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/run_metadata.h"
#include "ris/util/error.h"
#include "ris/util/process_group.h"
#include "ris/util/progress.h"
#include "ris/util/rank_select.h"
#include "sim/engine/block_pass.h"
#include "sim/engine/block_schedule.h"
#include "sim/stream/ppi_ray_blocks.h"
#include "sim/stream/ppi_rays_pass.h"
#include "sim/stream/ppi_scope_passes.h"
#include "sim/stream/scene_summary.h"
#include "sim/stream/slar_stream_targets.h"
#include "sim/targets/ppi_ray_targets.h"

namespace ris {

namespace {

constexpr std::int64_t kGdalCacheBytes = std::int64_t(256) << 20;
constexpr int kDefaultSegmentSamples = 2048;

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

// A streamed PPI: its set-up and its passes, in the order run() calls them.
// Pass 0: scene_summary.h; pass 1: ppi_ray_blocks.h (computing) and
// ppi_rays_pass.h (integrating, writing); passes 1b, 2 and 2b:
// ppi_scope_passes.h.
class PpiStreamRun {
 public:
  PpiStreamRun(const std::filesystem::path& scene_path, const RadarParams& radar,
               const SlarRunInfo& info, const std::filesystem::path& out_dir,
               const PpiStreamOptions& options)
      : in_(scene_path),
        order_{detail::block_schedule_from_environment(), options.faults.kill_block},
        options_(options),
        info_(info),
        out_dir_(out_dir) {
    summary_.grid = in_.grid();
    sim().radar = radar;
    RIS_CHECK(radar.mode == RadarMode::ppi);
  }

  // Every rank of an MPI run (ris/util/process_group.h) runs passes 0 and 1
  // on its part (scene rows, blocks of rays); rank 0 alone writes, and runs
  // the passes after 1 (ppi_scope_passes.h).
  PpiStreamSummary run(const Sigma0Source& sigma0) {
    const bool root = group_.rank() == 0;
    backscatter_file_ =
        info_.backscatter_path.empty() ? sigma0.description() : info_.backscatter_path;
    scene_block_rows_ = std::min(grid().rows, std::max(in_.block_rows(), 256));
    bar_.emplace("simulate (streamed PPI)", 2 * std::int64_t(grid().rows) * grid().cols, "cells",
                 options_.quiet || !root);
    stage("scene statistics");
    ss_ = detail::summarise_scene_on_ranks(in_, group_, scene_block_rows_, *bar_, sigma0,
                                           backscatter_file_, detail::SceneSummaryElevation::skip);
    stage_done();
    set_up(sigma0);
    if (root) dir_.emplace(out_dir_);
    stage("rays: terrain, geometry, image formation, fading (pass 1)");
    rays_pass();
    stage_done();
    if (!root) return std::move(summary_);
    const detail::PpiReadback back{*dir_, sim(), info_, bins(), scan_rays(), readback_rays()};
    double median = std::numeric_limits<double>::quiet_NaN();
    if (sim().radar.reference.automatic && power_.total() > 0) {
      stage("median mean power (pass 1b)");
      median = detail::ppi_median_mean_power(back, power_);
      stage_done();
    }
    const GreytoneMap map = make_greytone_map_for_median(sim().radar, median);
    // Passes 2 and 2b only for the products selected (--products).
    const ProductSelection& want = info_.products;
    stage("B-scope greytones (pass 2)");
    if (want.wants("bscope")) detail::ppi_bscope_picture(back, map);
    stage_done();
    stage("scope (pass 2b)");
    if (want.wants("ppi_scope") || want.wants("ppi_scope_power") || want.wants("ppi_scope_mask"))
      detail::ppi_scope_picture(back, map, specs_);
    stage_done();
    write_metadata(map);
    remove_unselected_products(dir_->path(""), info_.products);
    bar_->finish();
    dir_->commit();
    return std::move(summary_);
  }

 private:
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
    if (ss_.valid_cells == 0) throw InputError("scene", "", "the scene has no cell with data");
    RadarParams& radar = sim().radar;
    sim().derived = derive(radar);
    site_radar_ = ppi_site_on_scene(radar, grid());
    check_ppi_site_inside(grid(), site_radar_);
    const double ground = check_ppi_site_terrain(
        site_radar_, site_terrain(site_radar_.ppi.site_x_m, site_radar_.ppi.site_y_m));
    sim().geometry = ppi_rays_layout(grid(), site_radar_, ground, ss_.h_min);
    rs_ = prepare_radiometry(ss_.categories, radar, sim().derived, sigma0, backscatter_file_);
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
    layout_.segment_samples =
        options_.segment_samples > 0 ? options_.segment_samples : kDefaultSegmentSamples;
    // A window: elevation, category, validity (7 bytes) and texel (16) a
    // cell, a quarter of the budget (a group of one ray's segment is read
    // whatever its size: a diagonal one spans segment / 2 cells a side).
    layout_.window_cells = std::max(
        options_.window_cells > 0 ? options_.window_cells : budget / 4 / 23, std::int64_t(16));
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
    layout_.block_rays = summary_.block_rays;
    layout_.fail_block = options_.faults.line_block;
  }

  // The targets checked on the scene (as check_point_targets_on_scene, on
  // every rank) and placed on the padded rays (ray_candidates, their base
  // heights read from the scene file: streamed_target_heights).
  void place_targets() {
    const std::vector<PointTarget>& targets = options_.targets;
    if (targets.empty()) return;
    const std::vector<double> base = detail::streamed_target_heights(targets, in_);
    candidates_ = detail::ray_candidates(targets, base, pg(), target_of_);
    results_.lit.assign(candidates_.size(), 0);
    results_.power_w.assign(candidates_.size(), 0.0);
  }

  // ---- Pass 1: rays in blocks (ppi_ray_blocks.h, ppi_rays_pass.h) -------
  void rays_pass() {
    const bool root = group_.rank() == 0;
    std::optional<detail::PpiRaySinks> sinks;
    if (root) {
      specs_ = ppi_raster_specs(grid(), sim());
      const auto open = [&](const std::string& file, const std::string& band) {
        return detail::ppi_product_writer<float>(*dir_, info_, file, bins(), scan_rays(),
                                                 specs_.bscope, band, nullptr);
      };
      sinks.emplace(detail::PpiRaySinks{
          open("mean_power_bscope.tif", "mean_power_w"),
          open("speckled_power_bscope.tif", "speckled_power_w"),
          detail::ppi_product_writer<std::uint8_t>(*dir_, info_, "mask_bscope.tif", bins(),
                                                   scan_rays(), specs_.bscope, "mask", nullptr)});
      const SlarImage& b = sim().bscope;
      looks_.resize(sz(bins()));
      for (int k = 0; k < bins(); ++k)
        looks_[sz(k)] =
            independent_samples(sim().radar, b.range.near_m + (k + 0.5) * b.range.bin_m);
    }
    std::vector<detail::RayBlock> spare;  // consumed blocks, their buffers reused
    detail::PpiRayBlocks blocks(in_, pg(), rs_, sim().radar.source_file, bins(), layout_,
                                candidates_, spare);
    detail::PpiRaysPass pass(blocks, sim(), rs_, root ? &*sinks : nullptr,
                             root ? &results_ : nullptr, looks_, info_.seed, power_, *bar_,
                             std::int64_t(grid().rows) * grid().cols, spare);
    detail::run_pass(group_, order_, pass);
    summary_.blocks = pass.consumed();
    if (!root) return;
    pass.close();
    finish_rays(pass.counts());
  }

  // Rank 0, after pass 1: the swath checked, the counts and the point
  // targets' returns as simulate_ppi sets them.
  void finish_rays(const detail::RayCounts& counts) {
    const SlarImage& b = sim().bscope;
    if (counts.in_swath == 0) {
      throw_swath_misses_scene(sim().radar.source_file, b.range, counts.r_min, counts.r_max,
                               "site.position");
    }
    summary_.windows = counts.windows;
    summary_.max_window_cells = counts.max_window_cells;
    SlarGeometry& g = sim().geometry.rays;
    g.nodata_samples = counts.nodata;
    g.shadow_samples = counts.shadow;
    g.back_facing_samples = counts.back_facing;
    g.layover_samples = counts.layover;
    g.nodata_cells = ss_.nodata_cells;
    sim().bscope.samples_in_swath = counts.in_swath;
    detail::fold_ray_targets(options_.targets, candidates_, target_of_, results_.lit,
                             results_.power_w, sim().point_returns, sim().bscope.point_power_w,
                             sim().hidden_targets);
  }

  // B-scope rays read back at a time by passes 1b and 2: up to a tile's
  // height (256), within an eighth of the budget (~10 bytes a pixel).
  int readback_rays() const {
    const std::int64_t fit = options_.memory_budget_bytes / 8 / (std::int64_t(bins()) * 10);
    return std::max(summary_.block_rays, static_cast<int>(std::clamp<std::int64_t>(fit, 1, 256)));
  }

  void write_metadata(const GreytoneMap& map) {
    PpiPictures pic;
    pic.seed = info_.seed;
    pic.looks = looks_;
    pic.reference_power_w = map.reference_power_w();
    pic.reference_greytone = map.reference_greytone();
    pic.greytones_per_decade = map.greytones_per_decade();
    pic.film_offset = map.film_offset();
    const SceneSummary scene{grid(), ss_.h_min, ss_.h_max, ss_.nodata_cells};
    write_text_file_atomic(dir_->path("metadata.json"),
                           ppi_metadata(scene, sim(), pic, info_).dump(2) + "\n");
  }

  const SceneStreamReader in_;
  ProcessGroup& group_ = process_group();
  const detail::BlockOrder order_;  // schedule, and the fault plan's kill_block
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
  detail::PpiRayLayout layout_;
  detail::SceneSummary ss_;  // pass 0
  // Set-up.
  RadiometrySetup rs_;
  PpiRasterSpecs specs_;
  std::vector<double> looks_;
  // Point targets: the candidates on the padded rays (in target and ray
  // order), each one's target, and (rank 0) whether lit and its power.
  std::vector<PointCandidate> candidates_;
  std::vector<std::size_t> target_of_;
  detail::RayTargetResults results_;
  FloatRankSelect power_;  // the median mean power's two passes
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
