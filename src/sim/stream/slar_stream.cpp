#include "ris/sim/slar_stream.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ris/geometry/slar_geometry.h"
#include "ris/geometry/swath_coverage.h"
#include "ris/image/greytone.h"
#include "ris/image/ground_range.h"
#include "ris/image/speckle.h"
#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "ris/scene/scene_stream.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/sim/slar_run_setup.h"
#include "ris/util/error.h"
#include "ris/util/process_group.h"
#include "ris/util/progress.h"
#include "ris/util/rank_select.h"
#include "ris/util/resource_guard.h"
#include "sim/engine/block_pass.h"
#include "sim/engine/block_schedule.h"
#include "sim/stream/sar_coherent_stream.h"
#include "sim/stream/scene_line_blocks.h"
#include "sim/stream/scene_lines_pass.h"
#include "sim/stream/scene_product_writers.h"
#include "sim/stream/scene_row_passes.h"
#include "sim/stream/scene_summary.h"
#include "sim/stream/slant_line_sink.h"
#include "sim/stream/slant_stream_passes.h"
#include "sim/stream/slar_stream_targets.h"

namespace ris {

namespace {

constexpr std::int64_t kGdalCacheBytes = std::int64_t(256) << 20;

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

}  // namespace

// An in-memory run holds the scene (7 bytes a cell), its scene-grid maps (5),
// the geocoded products and their copies while writing: its peak RSS was 27.6
// bytes a cell on an 8,000^2 scene (docs/performance.md).
constexpr std::int64_t kInMemoryBytesPerCell = 28;

bool scene_needs_streaming(std::int64_t rows, std::int64_t cols) {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long page_size = sysconf(_SC_PAGE_SIZE);
  const double physical = (pages > 0 && page_size > 0) ? double(pages) * double(page_size) : 8e9;
  return double(rows) * double(cols) * double(kInMemoryBytesPerCell) > physical / 2.0;
}

std::int64_t in_memory_run_bytes(std::int64_t rows, std::int64_t cols, const std::string& file,
                                 const std::string& key) {
  return checked_mul(checked_mul(rows, cols, file, key), kInMemoryBytesPerCell, file, key);
}

// Pass 1m's input: a mask byte and a float a sample.
constexpr std::int64_t kSpillBytesPerSample = 5;

std::int64_t streamed_temporary_bytes(const Scene& grid, const RadarParams& radar) {
  if (!(radar.mode == RadarMode::slar || radar.mode == RadarMode::sar)) return 0;
  const Track track = resolve_track(radar.track, grid, radar.source_file);
  const SlarGeometry g = slar_geometry_layout(grid, track, radar.azimuth_line_spacing_m);
  if (fused_slar_applies(grid, g)) return 0;
  return checked_mul(checked_mul(g.lines, g.samples, radar.source_file, "azimuth_line_spacing"),
                     kSpillBytesPerSample, radar.source_file, "azimuth_line_spacing");
}

namespace {

// A scene's streamed run: its set-up and its passes, in the order run()
// calls them. The passes are block passes (sim/engine/block_pass.h) in
// files of their own: pass 0 scene_summary.h, pass 1 scene_lines_pass.h
// (computing: scene_line_blocks.h; the slant image: slant_line_sink.h),
// pass 1m and 2b scene_row_passes.h, passes 1b and 2 slant_stream_passes.h.
class StreamRun {
 public:
  StreamRun(const std::filesystem::path& scene_path, const RadarParams& radar,
            const Sigma0Source& sigma0, const SlarRunInfo& info,
            const std::filesystem::path& out_dir, const SlarStreamOptions& options)
      : in_(scene_path),
        order_{detail::block_schedule_from_environment(), options.faults.kill_block},
        options_(options),
        info_(info),
        out_dir_(out_dir) {
    summary_.grid = in_.grid();
    summary_.sim.radar = radar;
    summary_.sim.derived = derive(summary_.sim.radar);
    backscatter_file_ =
        info.backscatter_path.empty() ? sigma0.description() : info.backscatter_path;
  }

  // Every rank of an MPI run (ris/util/process_group.h) runs passes 0 and
  // 1 on its part; rank 0 alone writes, and runs the passes after 1.
  SlarStreamSummary run(const Sigma0Source& sigma0) {
    plan();
    const bool root = group_.rank() == 0;
    // Passes 0, 1, 2b and 2 each stand for the scene's cells on the bar.
    bar_.emplace("simulate (streamed)", 4 * std::int64_t(grid().rows) * grid().cols, "cells",
                 options_.quiet || !root);
    stage("scene statistics");
    ss_ = detail::summarise_scene_on_ranks(in_, group_, scene_block_rows_, *bar_, sigma0,
                                           backscatter_file_);
    stage_done();
    set_up_stages(sigma0);
    if (root) {
      dir_.emplace(out_dir_);
      writers_.emplace(*dir_, info_, in_, sim(), 0.5 * (double(ss_.h_min) + double(ss_.h_max)));
    }
    lines_pass();
    // Rank 0's median mean power (pass 1b) and the folder holding the slant
    // products, for every rank's share of the geocoding.
    const double median =
        root ? detail::median_mean_power_pass(passes(), power_, radar().reference.automatic, clock_)
             : 0.0;
    const auto [median_all, slant_dir] =
        detail::share_from_rank0(group_, median, root ? dir_->path("").string() : std::string());
    const GreytoneMap map = make_greytone_map_for_median(picture_radar(), median_all);
    set_ground_grid();
    stage("geocoded products (pass 2b)");
    // Passes 2b and 2 only for the products selected (--products).
    const ProductSelection& want = info_.products;
    if (want.wants("geocoded_power") || want.wants("geocoded_grey")) geocoded_pass(map, slant_dir);
    stage_done();
    if (root) {
      summary_.cpu_parts.emplace_back(
          fmt::format("CPU of pass 2b on rank 0: {} of {} blocks computed", geo_cpu_.computed,
                      geo_blocks_),
          geo_cpu_.compute);
      summary_.cpu_parts.emplace_back("CPU of pass 2b on rank 0: writing (every block)",
                                      geo_cpu_.consume);
    }
    stage("greytones, ground range, PNGs (pass 2)");
    if (want.wants("slant_range") || want.wants("ground_range"))
      detail::pictures_pass(passes(), map, slant_dir);
    stage_done();
    if (!root) {
      summary_.sim.warnings.clear();  // rank 0 reports them
      summary_.sim.summary_warnings.clear();
      return std::move(summary_);
    }
    write_metadata(map);
    remove_unselected_products(dir_->path(""), info_.products);
    bar_->finish();
    dir_->commit();
    return std::move(summary_);
  }

 private:
  const Scene& grid() const { return summary_.grid; }
  SlarSimulation& sim() { return summary_.sim; }
  RadarParams& radar() { return summary_.sim.radar; }
  int lines() const { return summary_.sim.geometry.lines; }
  int bins() const { return summary_.sim.derived.range_bins; }
  // The radar the pictures are made with (render_slar): the coherent SAR's
  // speckle is in its intensity, so without fading.
  RadarParams picture_radar() {
    RadarParams r = radar();
    if (r.mode == RadarMode::sar && r.sar.coherent) r.switches.fading = false;
    return r;
  }

  void stage(const std::string& name) { clock_.start(name, *bar_); }
  void stage_done() { clock_.done(); }

  // What the stream runs and the block sizes (plan_scene_lines).
  void plan() {
    const RadarParams& r = radar();
    if (!(r.mode == RadarMode::slar || r.mode == RadarMode::sar)) {
      throw InputError(r.source_file, "mode",
                       "a streamed SLAR run simulates SLAR and SAR; PPI streams through "
                       "simulate_ppi_streamed");
    }
    layout_ = detail::plan_scene_lines(grid(), sim(), options_.block_lines,
                                       options_.memory_budget_bytes, group_.size());
    layout_.fail_block = options_.faults.line_block;
    summary_.block_lines = layout_.block_lines;
    // Scene rows read at a time by the passes over whole rows.
    scene_block_rows_ = std::min(grid().rows, std::max(in_.block_rows(), 256));
  }

  // After pass 0: the checks simulate_slar makes on the whole scene, and the
  // stages' radiometric set-up (as simulate_slar: slar_run_setup.h).
  void set_up_stages(const Sigma0Source& sigma0) {
    if (ss_.valid_cells == 0) throw InputError("scene", "", "the scene has no cell with data");
    check_terrain_below_sensor(ss_.h_max, ss_.max_row, ss_.max_col, sim().track.altitude_m,
                               radar().source_file);
    rs_ = prepare_radiometry(ss_.categories, radar(), sim().derived, sigma0, backscatter_file_);
    complete_slar_setup(sim(), rs_, grid());
    RIS_CHECK(rs_.imaging.range.count == bins() && bins() > 0);
    n_elev_ = ss_.elevation.total();
    ss_.elevation.select(detail::median_ranks(n_elev_, false));
    // The image's layout (for the products' metadata and geocoding).
    SlarImage& img = sim().image;
    img.lines = lines();
    img.bins = bins();
    img.range = rs_.imaging.range;
    img.line_spacing_m = sim().geometry.line_spacing_m;
    // Point targets checked on the scene and placed on their lines.
    if (!options_.targets.empty())
      targets_.emplace(options_.targets, options_.targets_file, in_, sim().geometry, img);
    if (radar().mode == RadarMode::sar && radar().sar.coherent)
      coherent_.emplace(sim(), info_.seed);
  }

  // ---- Pass 1: lines in blocks through the line engine ------------------
  void lines_pass() {
    const bool root = group_.rank() == 0;
    detail::StreamTargets* targets = targets_ ? &*targets_ : nullptr;
    detail::CoherentStream* coherent = coherent_ ? &*coherent_ : nullptr;
    // N per range bin, as make_greytone_image.
    looks_.resize(sz(bins()));
    for (int k = 0; k < bins(); ++k)
      looks_[sz(k)] = independent_samples(picture_radar(), rs_.imaging.range.centre_m(k));
    std::vector<detail::StreamLineBlock> spare;  // consumed blocks, their buffers reused
    detail::SceneLineBlocks blocks(in_, sim(), rs_, radar().source_file, layout_, targets, coherent,
                                   ss_.elevation, spare);
    std::optional<detail::SceneLineSinks> sinks;
    if (root) {
      detail::SceneProductWriters& w = *writers_;
      sinks.emplace(detail::open_scene_line_sinks(w, grid(), sim(), layout_.spill_maps));
      sinks->image.emplace(
          sim(), rs_,
          detail::SlantImageWriters{w.open<float>("mean_power_slant.tif", bins(), lines()),
                                    w.open<float>("speckled_power_slant.tif", bins(), lines()),
                                    w.open<std::uint8_t>("mask_slant.tif", bins(), lines())},
          looks_, info_.seed, power_, targets, coherent);
    }
    stage("geometry, image formation, scene maps, fading (pass 1)");
    detail::SceneLinesPass pass(blocks, root ? &*sinks : nullptr, *bar_, layout_.cross_cells,
                                spare);
    detail::run_pass(group_, order_, pass);
    summary_.blocks = pass.consumed();
    if (layout_.spill_maps) {
      if (root) stage_done();  // pass 1's lines; this stage ends below
      stage("scene maps (pass 1m)");
      detail::scene_maps_pass(group_, order_, in_, scene_block_rows_, sim(),
                              options_.faults.maps_block, ss_.elevation,
                              root ? &*writers_ : nullptr, root ? &*sinks : nullptr);
    }
    // The median elevation's second pass: every rank refined its blocks.
    if (group_.size() > 1) {
      std::vector<std::uint64_t> low = ss_.elevation.counters();
      group_.sum(low);
      ss_.elevation.set_counters(low);
    }
    if (!root) return;
    sinks->image->close();
    finish_counts(sinks->image->counts(), sinks->image->samples_in_swath());
    if (targets_) {
      targets_->finish(sim());
      summary_.irfs = targets_->measure(sim(), coherent_.has_value());
    }
    if (sinks->scene_mask) sinks->scene_mask->close();  // pass 1m closed the spills
    if (sinks->incidence) sinks->incidence->close();
    sinks->shadow_text.close();
    if (!sinks->shadow_text)
      throw InputError(dir_->path("shadowmap.txt").string(), "", "write failed");
    stage_done();
    const detail::PassCpu& cpu = pass.cpu();
    summary_.cpu_parts.emplace_back(fmt::format("CPU of pass 1 on rank 0: {} of {} blocks computed",
                                                cpu.computed, pass.blocks()),
                                    cpu.compute);
    summary_.cpu_parts.emplace_back(
        "CPU of pass 1 on rank 0: integration, fading, writing (every block)", cpu.consume);
  }

  void finish_counts(const SlarLineCounts& counts, std::int64_t samples_in_swath) {
    SlarGeometry& g = sim().geometry;
    g.nodata_samples = counts.nodata;
    g.shadow_samples = counts.shadow;
    g.back_facing_samples = counts.back_facing;
    g.layover_samples = counts.layover;
    g.nodata_cells = ss_.nodata_cells;
    sim().image.samples_in_swath = samples_in_swath;
    check_swath_hits_scene(samples_in_swath, rs_.imaging.range, counts, radar().source_file);
  }

  // What passes 1b and 2 need (slant_stream_passes.h).
  detail::SlantImagePasses passes() {
    return {group_,
            order_,
            sim(),
            info_,
            summary_.block_lines,
            dir_ ? &*dir_ : nullptr,
            &*bar_,
            {},
            writers_ ? &writers_->slant_georef() : nullptr,
            std::int64_t(grid().rows) * grid().cols};
  }

  // The ground-range grid over the median elevation (simulate_slar).
  void set_ground_grid() {
    const double h_ref = options_.reference_height_m
                             ? *options_.reference_height_m
                             : (n_elev_ > 0 ? double(ss_.elevation.value(0)) : 0.0);
    const SlarImage& img = sim().image;
    sim().ground_grid =
        ground_range_grid(img.range, sim().geometry.altitude_m, h_ref, img.line_spacing_m);
    // Less than half of the scene in the swath: said, as simulate_slar does.
    if (auto w = swath_coverage_warning(swath_coverage(sim().track, grid(), img.range, h_ref)))
      sim().summary_warnings.push_back(*w);
  }

  // ---- Pass 2b: geocoded products, scene rows top down ------------------
  // Every rank geocodes bands of scene rows, reading the slant products
  // rank 0 wrote into `slant_dir` (its staging folder: on a file system
  // every rank sees); rank 0 writes them in row order.
  void geocoded_pass(const GreytoneMap& map, const std::string& slant_dir) {
    const bool root = group_.rank() == 0;
    std::unique_ptr<GeoTiffBlockWriter<float>> power_out;
    std::unique_ptr<GeoTiffBlockWriter<std::uint8_t>> grey_out;
    if (root) {
      power_out = writers_->open<float>("geocoded_power.tif", grid().cols, grid().rows);
      grey_out = writers_->open<std::uint8_t>("geocoded_grey.tif", grid().cols, grid().rows);
    }
    detail::SceneGeocodedPass pass(in_, scene_block_rows_, sim(), map, slant_dir,
                                   options_.faults.geocoding_block, power_out.get(), grey_out.get(),
                                   *bar_);
    geo_blocks_ = pass.blocks();
    detail::run_pass(group_, order_, pass);
    geo_cpu_ = pass.cpu();
    if (!root) return;
    power_out->close();
    grey_out->close();
    if (picture_file("geocoded_grey", grid().cols, grid().rows, info_.max_png_pixels) ==
        "geocoded_grey.png") {
      write_png_gray_from_raster(dir_->path("geocoded_grey.png"), dir_->path("geocoded_grey.tif"),
                                 png_compression_level(info_.compression));
    }
  }

  // metadata.json, with make_greytone_image's map and N per bin.
  void write_metadata(const GreytoneMap& map) {
    const SlarPictures pic_meta = detail::picture_metadata(map, info_.seed, looks_);
    nlohmann::json meta = slar_metadata(grid(), ss_.h_min, ss_.h_max, sim(), pic_meta, info_);
    if (targets_)
      meta["point_targets"] = targets_->metadata(summary_.irfs, sim(), coherent_.has_value());
    write_text_file_atomic(dir_->path("metadata.json"), meta.dump(2) + "\n");
  }

  const SceneStreamReader in_;
  ProcessGroup& group_ = process_group();
  const detail::BlockOrder order_;  // schedule, and the fault plan's kill_block
  const SlarStreamOptions& options_;
  const SlarRunInfo& info_;
  const std::filesystem::path out_dir_;
  SlarStreamSummary summary_;
  std::string backscatter_file_;
  // Made at the points the passes need them: a refused run shows no bar
  // and stages no folder.
  std::optional<ProgressBar> bar_;
  std::optional<StagedDirectory> dir_;
  std::optional<detail::SceneProductWriters> writers_;  // rank 0's
  detail::StageClock clock_{summary_.stage_seconds, summary_.stage_cpu_seconds};
  detail::SceneLineLayout layout_;
  int scene_block_rows_ = 0;
  detail::SceneSummary ss_;
  std::uint64_t n_elev_ = 0;
  RadiometrySetup rs_;
  std::optional<detail::StreamTargets> targets_;    // with point targets
  std::optional<detail::CoherentStream> coherent_;  // the coherent SAR
  std::vector<double> looks_;
  FloatRankSelect power_;    // the median mean power's two passes
  detail::PassCpu geo_cpu_;  // pass 2b's on this rank (none: not run)
  int geo_blocks_ = 0;
};

}  // namespace

SlarStreamSummary simulate_slar_streamed(const std::filesystem::path& scene_path,
                                         const RadarParams& radar, const Sigma0Source& sigma0,
                                         const SlarRunInfo& info,
                                         const std::filesystem::path& out_dir,
                                         const SlarStreamOptions& options) {
  bound_gdal_cache(kGdalCacheBytes);
  StreamRun run(scene_path, radar, sigma0, info, out_dir, options);
  return run.run(sigma0);
}

}  // namespace ris
