#include "ris/sim/acquisition_stream.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <type_traits>

#include "ris/image/acquisition_georef.h"
#include "ris/image/greytone.h"
#include "ris/image/slar_azimuth_integrator.h"
#include "ris/image/speckle.h"
#include "ris/io/atomic_file.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/scene/scene_stream.h"
#include "ris/sim/acquisition_products.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/util/error.h"
#include "ris/util/process_group.h"
#include "ris/util/progress.h"
#include "ris/util/resource_guard.h"
#include "sim/engine/block_pass.h"
#include "sim/engine/block_schedule.h"
#include "sim/modes/acquisition_setup.h"
#include "sim/stream/slant_line_sink.h"
#include "sim/stream/slant_stream_passes.h"

namespace ris {

namespace {

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

// Block buffers a range bin of a line takes: a scene run's 72 (the
// profile, the integrator's running sums, the written lines and their
// copies; ris/sim/slar_stream.h) and the radar-grid layers' 5.
constexpr std::int64_t kBytesPerBin = 72 + 5;

// The products' bytes a pixel of the window at most: the five rasters
// uncompressed (4 + 4 + 4 + 1 + 1) and the two greytone pictures (about a
// byte a pixel each). Compressed they take less (Winnipeg's: 12).
constexpr std::int64_t kProductBytesPerPixel = 16;

// DEM rows read at a time by the passes over the whole DEM.
constexpr int kDemBandRows = 256;

// The run's state and its passes, in the order run() calls them.
class AcquisitionStream {
 public:
  AcquisitionStream(const Acquisition& acq, const EllipsoidalDemFile& dem, const RadarParams& radar,
                    const Sigma0Source& sigma0, const AcquisitionSimOptions& options,
                    const SlarRunInfo& info, const std::filesystem::path& out_dir,
                    const SlarStreamOptions& stream)
      : dem_(dem),
        options_(options),
        order_{detail::block_schedule_from_environment(), stream.faults.kill_block},
        fail_block_(stream.faults.line_block),
        info_(info),
        out_dir_(out_dir),
        stream_(stream) {
    if (!stream.targets.empty()) {
      throw InputError(stream.targets_file, "--targets",
                       "point targets are not placed on an acquisition's grid yet; drop --targets");
    }
    // Every rank sets the same run up (the inputs are read by each).
    detail::check_acquisition_radar(radar, options);
    // The DEM's heights in bands of rows, never all held: their range and
    // the land cover's categories over the whole DEM.
    const detail::AcquisitionFrame frame =
        detail::acquisition_frame(acq, dem.grid(), dem.summarise(kDemBandRows), options.full_grid);
    // Room for the products, before any work (the window has no cap).
    const GridWindow& w = frame.window;
    require_disk(checked_mul(checked_mul(w.lines, w.bins, acq.source, ""), kProductBytesPerPixel,
                             acq.source, ""),
                 out_dir, acq.source, "--out",
                 fmt::format("the products of a {} x {} pixel window", w.lines, w.bins));
    std::vector<std::uint16_t> categories;
    if (options.land_cover != nullptr) categories = land_cover_categories();
    detail::set_up_acquisition(acq, dem.grid(), radar, sigma0, options, frame, s_,
                               options.land_cover != nullptr ? &categories : nullptr);
    SlarImage& img = sim().image;
    img.lines = lines();
    img.bins = bins();
    img.range = s_.rs.imaging.range;
    img.line_spacing_m = sim().geometry.line_spacing_m;
    detail::set_acquisition_ground_grid(s_.out);
    set_georef(acq);
    summary_.block_lines =
        detail::stream_block_lines(lines(), std::int64_t(std::max(bins(), 1)) * kBytesPerBin,
                                   stream.block_lines, stream.memory_budget_bytes, group_.size());
  }

  // Every rank runs pass 1 and 2's blocks; rank 0 alone writes.
  AcquisitionStreamSummary run() {
    const bool root = group_.rank() == 0;
    // Passes 1 and 2 each stand for the window's lines on the bar.
    bar_.emplace("simulate (streamed)", 2 * std::int64_t(lines()), "lines", stream_.quiet || !root);
    if (root) dir_.emplace(out_dir_);
    lines_pass();
    const double median =
        root ? detail::median_mean_power_pass(passes(), power_, radar().reference.automatic, clock_)
             : 0.0;
    const auto [median_all, slant_dir] =
        detail::share_from_rank0(group_, median, root ? dir_->path("").string() : std::string());
    const GreytoneMap map = make_greytone_map_for_median(radar(), median_all);
    stage("greytones, ground range, PNGs (pass 2)");
    const ProductSelection& want = info_.products;
    if (want.wants("slant_range") || want.wants("ground_range"))
      detail::pictures_pass(passes(), map, slant_dir);
    stage_done();
    if (!root) {
      sim().warnings.clear();  // rank 0 reports them
    } else {
      write_text_file_atomic(
          dir_->path("metadata.json"),
          acquisition_metadata(s_.out, sim(), detail::picture_metadata(map, info_.seed, looks_),
                               info_)
                  .dump(2) +
              "\n");
      remove_unselected_products(dir_->path(""), info_.products);
      bar_->finish();
      dir_->commit();
    }
    summary_.acquisition = std::move(s_.out);
    return std::move(summary_);
  }

 private:
  using LineBlock = detail::StreamLineBlock;
  template <typename T>
  using Writer = std::unique_ptr<GeoTiffBlockWriter<T>>;

  SlarSimulation& sim() { return s_.out.sim; }
  const RadarParams& radar() const { return s_.out.sim.radar; }
  int lines() const { return s_.out.window.lines; }
  int bins() const { return s_.out.window.bins; }
  int block_lines() const { return summary_.block_lines; }

  void stage(const std::string& name) { clock_.start(name, *bar_); }
  void stage_done() { clock_.done(); }

  detail::SlantImagePasses passes() {
    return {group_,
            order_,
            sim(),
            info_,
            block_lines(),
            dir_ ? &*dir_ : nullptr,
            &*bar_,
            acquisition_grid_metadata(s_.out),
            s_.out.georef.gcps.empty() ? nullptr : &s_.out.georef,
            lines()};
  }

  // The products' GCPs (ris/image/acquisition_georef.h), before any block
  // is written (the writers set them when they open): the grid and the
  // orbit are known from the set-up, and each tie line's ground is found on
  // the DEM window its own block would read (dem_rect_of_lines), so they
  // are the in-memory run's.
  void set_georef(const Acquisition& acq) {
    const GridWindow& w = s_.out.window;
    const AcquisitionTieGrid tie = acquisition_tie_grid(w);
    const double h_mid = 0.5 * (double(s_.out.dem_min_m) + s_.out.dem_max_m);
    Georef& g = s_.out.georef;
    g = acquisition_georef_frame();
    for (const int l : tie.lines) {
      const detail::DemRect rect = detail::dem_rect_of_lines(*s_.run, l, l + 1);
      const EllipsoidalDem dem = dem_.read(rect.row0, rect.rows, rect.col0, rect.cols);
      add_acquisition_tie_line(acq, dem, w, l, tie.bins, h_mid, g);
    }
  }

  // A product on the window's grid, as write_acquisition_products writes it
  // (with the window's GCPs).
  template <typename T>
  Writer<T> open_writer(const std::string& file) {
    const SlarRasterSpec spec = acquisition_raster_spec(file, s_.out, sim().image);
    const Georef* gcps = s_.out.georef.gcps.empty() ? nullptr : &s_.out.georef;
    return std::make_unique<GeoTiffBlockWriter<T>>(
        dir_->path(file), bins(), lines(), std::vector<std::string>{spec.band}, gcps, spec.nodata,
        spec.metadata, product_tiff_settings(info_, std::is_floating_point_v<T>),
        BlockOrder::top_down);
  }

  // ---- Pass 1: lines in blocks through the line engine ------------------
  // Rank 0's files of pass 1 besides the slant image: the radar-grid layers.
  struct LayerWriters {
    Writer<float> local_incidence;
    Writer<std::uint8_t> layover_shadow;
  };

  // Pass 1 as a block pass (sim/engine/block_pass.h): blocks of lines
  // computed on any rank (compute_block), and on rank 0, in line order,
  // their radar-grid layers written and their lines made into the image
  // (slant_line_sink.h).
  struct LinesPass {
    using Block = LineBlock;
    AcquisitionStream& run;
    LayerWriters* layers;          // rank 0's
    detail::SlantLineSink* image;  // rank 0's
    detail::PassCpu cpu;
    int blocks() const { return (run.lines() + run.block_lines() - 1) / run.block_lines(); }
    Block compute(int b) {
      const double t0 = detail::process_cpu_seconds();
      Block k = run.compute_block(b);
      cpu.compute += detail::process_cpu_seconds() - t0;
      ++cpu.computed;
      return k;
    }
    void pack(const Block& k, std::vector<char>& out) const { detail::pack_line_block(k, out); }
    Block unpack(const char* p, std::size_t n) const { return detail::unpack_line_block(p, n); }
    void consume(int, Block& k) {
      const double t0 = detail::process_cpu_seconds();
      const int n = k.l1 - k.l0;
      layers->local_incidence->write(k.incidence.data(), n);
      layers->layover_shadow->write(k.scene_mask.data(), n);
      image->take(k);
      run.bar_->advance(n);
      ++run.summary_.blocks;
      if (run.spare_.size() < 2) run.spare_.push_back(std::move(k));
      cpu.consume += detail::process_cpu_seconds() - t0;
    }
  };

  void lines_pass() {
    stage("terrain profiles, image formation, radar-grid layers, fading (pass 1)");
    const bool root = group_.rank() == 0;
    // N per range bin, as make_greytone_image.
    looks_.resize(sz(bins()));
    for (int k = 0; k < bins(); ++k)
      looks_[sz(k)] = independent_samples(radar(), s_.rs.imaging.range.centre_m(k));
    std::optional<LayerWriters> layers;
    std::optional<detail::SlantLineSink> image;
    if (root) {
      image.emplace(sim(), s_.rs,
                    detail::SlantImageWriters{open_writer<float>("mean_power_slant.tif"),
                                              open_writer<float>("speckled_power_slant.tif"),
                                              open_writer<std::uint8_t>("mask_slant.tif")},
                    looks_, info_.seed, power_, nullptr, nullptr);
      layers.emplace(LayerWriters{open_writer<float>("local_incidence.tif"),
                                  open_writer<std::uint8_t>("layover_shadow_mask.tif")});
    }
    LinesPass pass{*this, root ? &*layers : nullptr, root ? &*image : nullptr, {}};
    detail::run_pass(group_, order_, pass);
    if (!root) {
      stage_done();
      return;
    }
    image->close();
    const SlarLineCounts& counts = image->counts();
    set_sample_counts(sim().geometry, counts);
    sim().image.samples_in_swath = image->samples_in_swath();
    check_swath_hits_scene(image->samples_in_swath(), s_.rs.imaging.range, counts,
                           radar().source_file);
    layers->local_incidence->close();
    layers->layover_shadow->close();
    stage_done();
    summary_.cpu_parts.emplace_back(fmt::format("CPU of pass 1 on rank 0: {} of {} blocks computed",
                                                pass.cpu.computed, pass.blocks()),
                                    pass.cpu.compute);
    summary_.cpu_parts.emplace_back(
        "CPU of pass 1 on rank 0: integration, fading, writing (every block)", pass.cpu.consume);
  }

  // Block b's lines through the engine, on this rank: their range profiles,
  // counts and radar-grid layers (lines x bins).
  LineBlock compute_block(int b) {
    LineBlock k = detail::start_line_block(b, block_lines(), lines(), fail_block_, spare_);
    k.prof.allocate(k.l1 - k.l0, bins(), k.l0);
    k.prof.samples_in_swath = 0;
    k.incidence.resize(sz(k.l1 - k.l0) * sz(bins()));
    k.scene_mask.resize(k.incidence.size());
    // The block's window of the DEM (and of the land cover on it), read
    // by this rank; the run as the set-up made it, on that window.
    const detail::AcquisitionRun& base = *s_.run;
    const detail::DemRect rect = detail::dem_rect_of_lines(base, k.l0, k.l1);
    const EllipsoidalDem dem = dem_.read(rect.row0, rect.rows, rect.col0, rect.cols);
    std::vector<std::uint16_t> land;
    if (options_.land_cover != nullptr) {
      land = detail::categories_on_dem(dem, *options_.land_cover, options_.land_cover_source,
                                       options_.category);
    }
    detail::AcquisitionRun run{base.acq,
                               dem,
                               base.window,
                               base.earth,
                               base.category,
                               options_.land_cover != nullptr ? land.data() : nullptr,
                               base.dem_min_m,
                               base.dem_max_m,
                               base.samples_per_bin,
                               base.max_points,
                               base.layout,
                               k.incidence.data(),
                               k.scene_mask.data(),
                               k.l0};
    // Lines handed to the threads a few at a time, so that a short block
    // still keeps every thread busy (each line's profile row is its own:
    // the bytes do not depend on it).
    const int chunk = std::clamp((k.l1 - k.l0) / (4 * omp_get_max_threads()), 1, 16);
    detail::run_line_blocks(sim().geometry, s_.stages(), k.l0, k.l1, chunk, k.prof, k.counts,
                            [&](detail::LineScratch&) {
                              return detail::AcquisitionThreadSource{run, {}, {}, {}, {},
                                                                     {},  {}, {}, {}};
                            });
    return k;
  }

  // The land cover's categories over the whole DEM (sorted, unique), the
  // DEM read in bands of rows (the radiometry's table needs them all).
  std::vector<std::uint16_t> land_cover_categories() const {
    std::vector<std::uint8_t> seen(65536, 0);
    const EllipsoidalDem& g = dem_.grid();
    for (int r0 = 0; r0 < g.rows; r0 += kDemBandRows) {
      const EllipsoidalDem band = dem_.read(r0, std::min(kDemBandRows, g.rows - r0), 0, g.cols);
      for (std::uint16_t c : detail::categories_on_dem(
               band, *options_.land_cover, options_.land_cover_source, options_.category))
        seen[c] = 1;
    }
    std::vector<std::uint16_t> out;
    for (std::size_t c = 0; c < seen.size(); ++c)
      if (seen[c]) out.push_back(static_cast<std::uint16_t>(c));
    return out;
  }

  const EllipsoidalDemFile& dem_;
  const AcquisitionSimOptions& options_;
  ProcessGroup& group_ = process_group();
  const detail::BlockOrder order_;  // schedule, and the fault plan's kill_block
  const int fail_block_;            // FaultPlan::line_block, -1: none
  const SlarRunInfo& info_;
  const std::filesystem::path out_dir_;
  const SlarStreamOptions& stream_;
  detail::AcquisitionSetup s_;
  AcquisitionStreamSummary summary_;
  // Made when run() starts: a refused run shows no bar and stages no folder.
  std::optional<ProgressBar> bar_;
  std::optional<StagedDirectory> dir_;
  detail::StageClock clock_{summary_.stage_seconds, summary_.stage_cpu_seconds};
  std::vector<double> looks_;
  FloatRankSelect power_;         // the median mean power's two passes
  std::vector<LineBlock> spare_;  // consumed blocks, their buffers reused
};

}  // namespace

AcquisitionStreamSummary simulate_acquisition_streamed(
    const Acquisition& acq, const EllipsoidalDemFile& dem, const RadarParams& radar,
    const Sigma0Source& sigma0, const AcquisitionSimOptions& options, const SlarRunInfo& info,
    const std::filesystem::path& out_dir, const SlarStreamOptions& stream) {
  bound_gdal_cache(std::int64_t(256) << 20);  // as a scene's streamed run
  AcquisitionStream run(acq, dem, radar, sigma0, options, info, out_dir, stream);
  return run.run();
}

}  // namespace ris
