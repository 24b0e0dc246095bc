#include "ris/sim/slar_stream.h"

#include <fmt/format.h>
#include <gdal.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/geocode.h"
#include "ris/image/geocoded_grey.h"
#include "ris/image/greytone.h"
#include "ris/image/ground_range.h"
#include "ris/image/shadow_map.h"
#include "ris/image/slant_georef.h"
#include "ris/image/slar_azimuth_integrator.h"
#include "ris/image/speckle.h"
#include "ris/image/thermal_noise.h"
#include "ris/io/atomic_file.h"
#include "ris/io/compression_preset.h"
#include "ris/io/gdal_util.h"
#include "ris/io/geotiff_block_writer.h"
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
#include "sim/engine/block_schedule.h"
#include "sim/stream/sar_coherent_stream.h"
#include "sim/stream/slant_stream_passes.h"
#include "sim/stream/slar_stream_oblique.h"
#include "sim/stream/slar_stream_targets.h"

namespace ris {

using detail::process_cpu_seconds;
using detail::read_rows;
using detail::read_window;

namespace {

constexpr std::int64_t kGdalCacheBytes = std::int64_t(256) << 20;
constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

// Pass 0: what simulate_slar learns from the whole scene before it starts.
struct SceneSummary {
  std::int64_t valid_cells = 0;
  std::int64_t nodata_cells = 0;
  std::vector<std::uint16_t> categories;  // of the cells with data, sorted
  float h_min = std::numeric_limits<float>::infinity();
  float h_max = -std::numeric_limits<float>::infinity();
  int max_row = -1, max_col = -1;  // the first highest cell with data
  FloatRankSelect elevation;       // pass 1 of the median elevation
};

// on_new_category(c, row, col): called at the first cell of each category,
// so a category the backscatter source lacks stops the run there rather
// than after the whole pass.
// Rows [row_begin, row_end) (an MPI rank's part; reduce_scene_summary
// combines the parts).
SceneSummary summarise_scene(const SceneStreamReader& in, int row_begin, int row_end,
                             int block_rows, ProgressBar& bar,
                             const std::function<void(std::uint16_t, int, int)>& on_new_category) {
  const Scene& g = in.grid();
  SceneSummary s;
  std::vector<std::uint8_t> seen(65536, 0);
  const std::size_t cap = sz(block_rows) * sz(g.cols);
  std::vector<float> z(cap);
  std::vector<std::uint16_t> cat(cap);
  std::vector<std::uint8_t> ok(cap);
  for (int r0 = row_begin; r0 < row_end; r0 += block_rows) {
    const int n = std::min(block_rows, row_end - r0);
    in.read(r0, n, 0, g.cols, z.data(), cat.data(), ok.data());
    const std::size_t cells = sz(n) * sz(g.cols);
    for (std::size_t i = 0; i < cells; ++i) {
      if (!ok[i]) {
        ++s.nodata_cells;
        continue;
      }
      ++s.valid_cells;
      if (seen[cat[i]] == 0) {
        on_new_category(cat[i], r0 + static_cast<int>(i / sz(g.cols)),
                        static_cast<int>(i % sz(g.cols)));
      }
      seen[cat[i]] = 1;
      const float h = z[i];
      if (h < s.h_min) s.h_min = h;
      if (h > s.h_max) {
        s.h_max = h;
        s.max_row = r0 + static_cast<int>(i / sz(g.cols));
        s.max_col = static_cast<int>(i % sz(g.cols));
      }
      if (std::isfinite(h)) s.elevation.count(h);
    }
    bar.advance(static_cast<std::int64_t>(cells));
  }
  for (std::size_t c = 0; c < seen.size(); ++c)
    if (seen[c]) s.categories.push_back(static_cast<std::uint16_t>(c));
  return s;
}

// The whole scene's summary from every rank's part (rows in rank order),
// on every rank: counts summed, categories merged, and the extremes folded
// in rank order with the same strict comparisons as summarise_scene, so the
// highest cell is the first in row order, as one process finds it.
void reduce_scene_summary(ProcessGroup& g, SceneSummary& s) {
  if (g.size() == 1) return;
  std::vector<std::uint64_t> counts(65536 + 2, 0);
  counts[0] = static_cast<std::uint64_t>(s.valid_cells);
  counts[1] = static_cast<std::uint64_t>(s.nodata_cells);
  for (std::uint16_t c : s.categories) counts[2 + sz(c)] = 1;
  g.sum(counts);
  s.valid_cells = static_cast<std::int64_t>(counts[0]);
  s.nodata_cells = static_cast<std::int64_t>(counts[1]);
  s.categories.clear();
  for (std::size_t c = 0; c < 65536; ++c)
    if (counts[2 + c] > 0) s.categories.push_back(static_cast<std::uint16_t>(c));
  std::vector<std::uint64_t> top = s.elevation.counters();
  g.sum(top);
  s.elevation.set_counters(top);
  struct Extremes {
    float h_min, h_max;
    int max_row, max_col;
  };
  const Extremes mine{s.h_min, s.h_max, s.max_row, s.max_col};
  std::vector<char> bytes(sizeof(Extremes));
  std::memcpy(bytes.data(), &mine, sizeof(Extremes));
  const std::vector<std::vector<char>> all = g.all_gather(bytes);
  s.h_min = std::numeric_limits<float>::infinity();
  s.h_max = -std::numeric_limits<float>::infinity();
  s.max_row = s.max_col = -1;
  for (const std::vector<char>& b : all) {
    Extremes e{};
    RIS_CHECK(b.size() == sizeof(Extremes));
    std::memcpy(&e, b.data(), sizeof(Extremes));
    if (e.h_min < s.h_min) s.h_min = e.h_min;
    if (e.h_max > s.h_max) {
      s.h_max = e.h_max;
      s.max_row = e.max_row;
      s.max_col = e.max_col;
    }
  }
}

// Whether the track runs along y (lines are cell rows), as fused_slar_applies.
bool along_y_axis(const Track& t) {
  return std::abs(std::abs(t.along_y) - 1.0) < 1e-9;
}

// A band of scene rows [r0, r0 + rows) as a rank sends it to rank 0: a
// float and a byte per cell (pass 1m's incidence and mask, pass 2b's power
// and greytone).
void pack_row_band(int r0, int rows, const std::vector<float>& values,
                   const std::vector<std::uint8_t>& bytes, std::vector<char>& out) {
  const int head[2] = {r0, rows};
  const char* h = reinterpret_cast<const char*>(head);
  out.insert(out.end(), h, h + sizeof(head));
  const char* v = reinterpret_cast<const char*>(values.data());
  out.insert(out.end(), v, v + values.size() * sizeof(float));
  out.insert(out.end(), bytes.begin(), bytes.end());
}

// pack_row_band's inverse, for rows of `cols` cells.
void unpack_row_band(const char* p, std::size_t n, int cols, int& r0, int& rows,
                     std::vector<float>& values, std::vector<std::uint8_t>& bytes) {
  int head[2] = {};
  RIS_CHECK(n >= sizeof(head));
  std::memcpy(head, p, sizeof(head));
  r0 = head[0];
  rows = head[1];
  const std::size_t nc = std::size_t(rows) * std::size_t(cols);
  RIS_CHECK(n == sizeof(head) + nc * (sizeof(float) + 1));
  values.resize(nc);
  std::memcpy(values.data(), p + sizeof(head), nc * sizeof(float));
  bytes.assign(p + sizeof(head) + nc * sizeof(float), p + n);
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

// A streamed run's state and its passes, in the order run() calls them.
class StreamRun {
 public:
  StreamRun(const std::filesystem::path& scene_path, const RadarParams& radar,
            const Sigma0Source& sigma0, const SlarRunInfo& info,
            const std::filesystem::path& out_dir, const SlarStreamOptions& options)
      : in_(scene_path),
        order_{detail::block_schedule_from_environment(), options.faults.kill_block},
        fail_block_(options.faults.line_block),
        fail_geo_block_(options.faults.geocoding_block),
        options_(options),
        info_(info),
        out_dir_(out_dir) {
    summary_.grid = in_.grid();
    summary_.sim.radar = radar;
    summary_.sim.derived = derive(summary_.sim.radar);
    backscatter_file_ =
        info.backscatter_path.empty() ? sigma0.description() : info.backscatter_path;
    georef_ = Georef{grid().geotransform(), grid().crs_wkt};
  }

  // Every rank of an MPI run (ris/util/process_group.h) runs passes 0 and
  // 1 on its part; rank 0 alone writes, and runs the passes after 1.
  SlarStreamSummary run(const Sigma0Source& sigma0) {
    plan();
    const bool root = group_.rank() == 0;
    bar_.emplace("simulate (streamed)", 3 * std::int64_t(grid().rows) * grid().cols, "cells",
                 options_.quiet || !root);
    stage("scene statistics");
    // This rank's rows: whole blocks of scene_block_rows_, split evenly.
    const int row_blocks = (grid().rows + scene_block_rows_ - 1) / scene_block_rows_;
    const auto part_row = [&](int rank) {
      const auto b = std::int64_t(row_blocks) * rank / group_.size();
      return static_cast<int>(std::min<std::int64_t>(b * scene_block_rows_, grid().rows));
    };
    // Every category checked against the backscatter source at its first
    // cell (a scene of one undefined category fails at once, not after the
    // pass; in an MPI run, the first in the rank's rows).
    ss_ = summarise_scene(in_, part_row(group_.rank()), part_row(group_.rank() + 1),
                          scene_block_rows_, *bar_, [&](std::uint16_t c, int row, int col) {
                            if (c == kNoDataCategory || sigma0.has_category(c)) return;
                            throw InputError(
                                backscatter_file_, "",
                                fmt::format("no backscatter for category {} (the scene {} uses "
                                            "it, first at row {}, column {}; add it to the "
                                            "backscatter file or give another with --backscatter)",
                                            c, in_.path(), row, col));
                          });
    reduce_scene_summary(group_, ss_);
    stage_done();
    set_up_stages(sigma0);
    if (root) dir_.emplace(out_dir_);
    lines_pass();
    // Rank 0's median mean power (pass 1b) and the folder holding the slant
    // products, for every rank's share of the geocoding.
    const double median =
        root ? detail::median_mean_power_pass(passes(), power_, radar().reference.automatic, clock_)
             : 0.0;
    const auto [median_all, slant_dir] =
        share_from_rank0(median, root ? dir_->path("").string() : std::string());
    const GreytoneMap map = make_greytone_map_for_median(picture_radar(), median_all);
    set_ground_grid();
    stage("geocoded products (pass 2b)");
    // Passes 2b and 2 only for the products selected (--products).
    const ProductSelection& want = info_.products;
    if (want.wants("geocoded_power") || want.wants("geocoded_grey")) geocoded_pass(map, slant_dir);
    stage_done();
    if (root) {
      summary_.cpu_parts.emplace_back(
          fmt::format("CPU of pass 2b on rank 0: {} of {} blocks computed", geo_.computed,
                      geo_.blocks),
          geo_.compute_cpu);
      summary_.cpu_parts.emplace_back("CPU of pass 2b on rank 0: writing (every block)",
                                      geo_.consume_cpu);
    }
    stage("greytones, ground range, PNGs (pass 2)");
    if (want.wants("slant_range") || want.wants("ground_range"))
      detail::pictures_pass(passes(), map, slant_dir);
    stage_done();
    if (!root) {
      summary_.sim.warnings.clear();  // rank 0 reports them
      return std::move(summary_);
    }
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
  SlarSimulation& sim() { return summary_.sim; }
  RadarParams& radar() { return summary_.sim.radar; }
  int lines() const { return summary_.sim.geometry.lines; }
  int bins() const { return summary_.sim.derived.range_bins; }
  int block_lines() const { return summary_.block_lines; }
  // The radar the pictures are made with (render_slar): the coherent SAR's
  // speckle is in its intensity, so without fading.
  RadarParams picture_radar() {
    RadarParams r = radar();
    if (r.mode == RadarMode::sar && r.sar.coherent) r.switches.fading = false;
    return r;
  }

  void stage(const std::string& name) { clock_.start(name, *bar_); }
  void stage_done() { clock_.done(); }

  // What the stream runs (SLAR and SAR: along a grid axis the direct line
  // engine, off the axes slar_stream_oblique.h; the coherent SAR's blocks
  // with their halo, sar_coherent_stream.h) and the block sizes.
  void plan() {
    const RadarParams& r = radar();
    if (!(r.mode == RadarMode::slar || r.mode == RadarMode::sar)) {
      throw InputError(r.source_file, "mode",
                       "a streamed SLAR run simulates SLAR and SAR; PPI streams through "
                       "simulate_ppi_streamed");
    }
    sim().track = resolve_track(r.track, grid(), r.source_file);
    sim().geometry = slar_geometry_layout(grid(), sim().track, r.azimuth_line_spacing_m);
    const SlarGeometry& g = sim().geometry;
    // A track off the axes: its lines through slar_stream_oblique.h, ~30
    // bytes a sample (the sampled terrain, map values and their copies).
    oblique_ = !g.direct_sampling;
    // The coherent SAR also keeps each element's power and slant range (8
    // bytes a sample), and per bin its range-compressed lines, z and
    // intensity (twice: sent).
    const bool coherent = r.mode == RadarMode::sar && r.sar.coherent;
    // Lines not one per cell row or column (off the axes, or along one at
    // a spacing other than the cell size): each sample's map values are
    // spilled and pass 1m takes each cell's (as scene_geometry_maps).
    spill_maps_ = !fused_slar_applies(grid(), g);
    cross_cells_ = oblique_ ? static_cast<int>(std::max<std::int64_t>(
                                  1, std::int64_t(grid().rows) * grid().cols / lines()))
                            : (along_y_axis(sim().track) ? grid().cols : grid().rows);
    // Along an axis a line reads spacing / cell rows or columns (at least
    // one) and, spilled, keeps 5 bytes a sample.
    const double cells_per_line =
        oblique_ ? 1.0
                 : std::max(1.0, g.line_spacing_m /
                                     (along_y_axis(sim().track) ? grid().dy_m : grid().dx_m));
    const std::int64_t per_line =
        (oblique_ ? std::int64_t(g.samples) * (coherent ? 38 : 30)
                  : std::int64_t(std::ceil(cross_cells_ * cells_per_line)) * (coherent ? 26 : 18) +
                        (spill_maps_ ? std::int64_t(g.samples) * 5 : 0)) +
        std::int64_t(std::max(bins(), 1)) * (coherent ? 112 : 72);
    summary_.block_lines = detail::stream_block_lines(lines(), per_line, options_.block_lines,
                                                      options_.memory_budget_bytes, group_.size());
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

  template <typename T>
  std::unique_ptr<GeoTiffBlockWriter<T>> open_writer(const std::string& file, int cols, int rows,
                                                     BlockOrder order = BlockOrder::top_down) {
    const SlarRasterSpec spec = slar_raster_spec(file, sim().image);
    auto w = std::make_unique<GeoTiffBlockWriter<T>>(
        dir_->path(file), cols, rows, std::vector<std::string>{spec.band},
        spec.georeferenced ? &georef_ : &slant_georef(), spec.nodata, spec.metadata,
        product_tiff_settings(info_, std::is_floating_point_v<T>), order);
    if (spec.mask_band) w->add_mask_band();
    return w;
  }

  // The slant-range products' GCPs, as an in-memory run's (slant_georef).
  const Georef& slant_georef() {
    if (!slant_georef_) {
      slant_georef_ = ris::slant_georef(grid(), sim().track, sim().image, streamed_elevation(in_),
                                        0.5 * (double(ss_.h_min) + double(ss_.h_max)));
    }
    return *slant_georef_;
  }

  // ---- Pass 1: lines in blocks through the line engine ------------------
  // The sinks of pass 1: the slant-range products, the scene-grid maps and
  // the shadow map, written block by block.
  struct LineSinks {
    FloatWriter mean, speckled;
    ByteWriter mask;
    ByteWriter scene_mask;
    FloatWriter incidence;
    std::ofstream shadow_text;
  };

  LineSinks open_line_sinks() {
    const BlockOrder line_order = scene_line_order(sim().track);
    LineSinks k;
    k.mean = open_writer<float>("mean_power_slant.tif", bins(), lines());
    k.speckled = open_writer<float>("speckled_power_slant.tif", bins(), lines());
    k.mask = open_writer<std::uint8_t>("mask_slant.tif", bins(), lines());
    if (spill_maps_) {
      // Off the axes (or lines not one per cell), the blocks' per-sample
      // map values (pass 1m's input).
      k.scene_mask = open_spill<std::uint8_t>(kSpillMask);
      k.incidence = open_spill<float>(kSpillIncidence);
    } else {
      k.scene_mask =
          open_writer<std::uint8_t>("scene_mask.tif", grid().cols, grid().rows, line_order);
      k.incidence =
          open_writer<float>("local_incidence_deg.tif", grid().cols, grid().rows, line_order);
    }
    k.shadow_text.open(dir_->path("shadowmap.txt"), std::ios::binary);
    if (!k.shadow_text) throw InputError(dir_->path("shadowmap.txt").string(), "", "cannot write");
    return k;
  }

  // A block of lines as computed by any rank and consumed, in line order, by
  // rank 0 (src/sim/engine/block_schedule.h; slant_stream_passes.h).
  using LineBlock = detail::StreamLineBlock;

  void lines_pass() {
    const SlarGeometry& g = sim().geometry;
    std::optional<SlarLineEngine> engine;
    std::optional<detail::ObliqueBlockLines> oblique;
    if (oblique_) {
      oblique.emplace(grid(), g, rs_.lut, rs_.imaging, radar().source_file, bins());
    } else {
      engine.emplace(grid(), g, rs_.lut, rs_.imaging, radar().source_file);
    }
    const bool root = group_.rank() == 0;
    std::optional<SlarAzimuthIntegrator> az;
    std::optional<LineSinks> sinks;
    if (root) {
      az.emplace(rs_.imaging, g.line_spacing_m, lines(), bins());
      sinks.emplace(open_line_sinks());
    }
    // N per range bin, as make_greytone_image.
    looks_.resize(sz(bins()));
    for (int k = 0; k < bins(); ++k)
      looks_[sz(k)] = independent_samples(picture_radar(), rs_.imaging.range.centre_m(k));
    const int halo = coherent_ ? 2 * coherent_->halo_lines() : 0;  // the coherent SAR's
    const std::size_t win_cap = oblique_ ? 0 : sz(block_lines() + halo + 2) * sz(cross_cells_);
    z_.resize(win_cap);
    cat_.resize(win_cap);
    ok_.resize(win_cap);
    window_incidence_.resize(win_cap);
    window_mask_.resize(win_cap);
    SlarLineCounts counts;
    std::int64_t samples_in_swath = 0;
    const int blocks = (lines() + block_lines() - 1) / block_lines();

    stage("geometry, image formation, scene maps, fading (pass 1)");
    // This process's CPU time (all its threads) in the two halves of pass 1,
    // reported with the passes: what a rank computes, and what rank 0 alone
    // does (docs/scale.md's cost model).
    double compute_cpu = 0.0, consume_cpu = 0.0;
    int computed = 0;
    detail::run_blocks_in_order<LineBlock>(
        group_, blocks, order_,
        [&](int b) {
          const double t0 = process_cpu_seconds();
          LineBlock k = oblique ? compute_oblique_block(*oblique, b) : compute_block(*engine, b);
          compute_cpu += process_cpu_seconds() - t0;
          ++computed;
          return k;
        },
        detail::pack_line_block, detail::unpack_line_block,
        [&](int, LineBlock& k) {
          const double t0 = process_cpu_seconds();
          counts.add(k.counts);
          if (targets_) targets_->add(k.targets);
          if (coherent_) coherent_->add(std::move(k.coherent));
          samples_in_swath += k.prof.samples_in_swath;
          write_block_maps(k, *sinks);
          write_shadow_text(k.prof, k.l0, k.l1, sinks->shadow_text);
          az->push(k.prof, k.l1 - k.l0);
          emit_ready(*az, *sinks);
          bar_->advance(std::int64_t(k.l1 - k.l0) * cross_cells_);
          ++summary_.blocks;
          if (spare_.size() < 2) spare_.push_back(std::move(k));
          consume_cpu += process_cpu_seconds() - t0;
        });
    if (spill_maps_) oblique_maps_pass(sinks);
    // The median elevation's second pass: every rank refined its blocks.
    if (group_.size() > 1) {
      std::vector<std::uint64_t> low = ss_.elevation.counters();
      group_.sum(low);
      ss_.elevation.set_counters(low);
    }
    if (!root) return;
    RIS_CHECK(az->lines_emitted() == lines());
    finish_counts(counts, samples_in_swath);
    if (targets_) {
      targets_->finish(sim());
      summary_.irfs = targets_->measure(sim(), coherent_.has_value());
    }
    sinks->mean->close();
    sinks->speckled->close();
    sinks->mask->close();
    if (sinks->scene_mask) sinks->scene_mask->close();  // pass 1m closed the spills
    if (sinks->incidence) sinks->incidence->close();
    sinks->shadow_text.close();
    if (!sinks->shadow_text)
      throw InputError(dir_->path("shadowmap.txt").string(), "", "write failed");
    stage_done();
    summary_.cpu_parts.emplace_back(
        fmt::format("CPU of pass 1 on rank 0: {} of {} blocks computed", computed, blocks),
        compute_cpu);
    summary_.cpu_parts.emplace_back(
        "CPU of pass 1 on rank 0: integration, fading, writing (every block)", consume_cpu);
  }

  // Block b's lines through the line engine, on this rank: its window (the
  // lines' cells and their halo) read from the scene file, geometry, image
  // formation and its own cells' maps; the median elevation's second pass
  // over its own cells.
  LineBlock compute_block(const SlarLineEngine& engine, int b) {
    LineBlock k = start_block(b);
    int row0 = 0, rows = 0, col0 = 0, cols = 0;
    // The coherent SAR reads its halo of lines too.
    const auto [r0, r1] = coherent_ ? coherent_->lines_read(k.l0, k.l1) : std::pair{k.l0, k.l1};
    engine.window_for_lines(r0, r1, row0, rows, col0, cols);
    const std::size_t cells = sz(rows) * sz(cols);
    if (cells > z_.size()) {  // lines spaced wider than a cell
      z_.resize(cells);
      cat_.resize(cells);
      ok_.resize(cells);
      window_incidence_.resize(cells);
      window_mask_.resize(cells);
    }
    in_.read(row0, rows, col0, cols, z_.data(), cat_.data(), ok_.data());
    const SceneWindow win{row0, col0, rows, cols, z_.data(), cat_.data(), ok_.data()};
    const SceneMapsWindow maps{
        row0, col0, rows, cols, window_mask_.data(), window_incidence_.data()};
    // Lines not one per cell: each sample's map values, spilled for pass
    // 1m (which also refines the median elevation over the cells); only
    // the block's own lines (a coherent halo's belong to its neighbours).
    SampleMapRows values{k.l0, nullptr, nullptr};
    if (spill_maps_) {
      k.scene_mask.resize(sz(k.l1 - k.l0) * sz(sim().geometry.samples));
      k.incidence.resize(k.scene_mask.size());
      values = SampleMapRows{k.l0, k.scene_mask.data(), k.incidence.data()};
    }
    if (coherent_) {
      const auto run = [&](int a, int e, bool own, SlarLineProfiles& prof, SlarLineCounts& counts,
                           const detail::LineKeep& keep) {
        if (spill_maps_) {
          engine.run(a, e, win, prof, SceneMapsWindow{}, counts, &keep, own ? &values : nullptr);
        } else {
          engine.run(a, e, win, prof, own ? maps : SceneMapsWindow{}, counts, &keep);
        }
      };
      coherent_->run_block(run, k.l0, k.l1, targets_ ? &*targets_ : nullptr, k.prof, k.counts,
                           k.targets, k.coherent);
      if (!spill_maps_) keep_block_maps(engine, win, maps, k);
      return k;
    }
    k.prof.allocate(k.l1 - k.l0, bins(), k.l0);
    k.prof.samples_in_swath = 0;
    // The point targets on the block's lines, found lit or hidden there.
    std::optional<detail::LinePointTargets> on_lines;
    if (targets_) on_lines = targets_->candidates_on_lines(k.l0, k.l1);
    const detail::LineKeep keep{nullptr, nullptr, on_lines ? &*on_lines : nullptr};
    if (spill_maps_) {
      engine.run(k.l0, k.l1, win, k.prof, SceneMapsWindow{}, k.counts, on_lines ? &keep : nullptr,
                 &values);
    } else {
      engine.run(k.l0, k.l1, win, k.prof, maps, k.counts, on_lines ? &keep : nullptr);
      keep_block_maps(engine, win, maps, k);
    }
    k.targets = on_lines ? targets_->block_result(*on_lines) : detail::BlockTargets{};
    return k;
  }

  // Block b's lines and a block's buffers (a consumed block's, reused).
  LineBlock start_block(int b) {
    return detail::start_line_block(b, block_lines(), lines(), fail_block_, spare_);
  }

  // Block b of a track off the axes (slar_stream_oblique.h): its profile
  // rows and counts, and its samples' map values as the block's maps (the
  // spilled rasters' rows: lines x samples). The coherent SAR runs its halo
  // of lines too (sar_coherent_stream.h), their map values dropped.
  LineBlock compute_oblique_block(detail::ObliqueBlockLines& oblique, int b) {
    LineBlock k = start_block(b);
    detail::ObliqueMapValues v{std::move(k.scene_mask), std::move(k.incidence)};
    if (coherent_) {
      detail::ObliqueMapValues halo;
      const auto run = [&](int a, int e, bool own, SlarLineProfiles& prof, SlarLineCounts& counts,
                           const detail::LineKeep& keep) {
        oblique.run(in_, a, e, prof, counts, own ? v : halo, &keep);
      };
      coherent_->run_block(run, k.l0, k.l1, targets_ ? &*targets_ : nullptr, k.prof, k.counts,
                           k.targets, k.coherent);
      k.scene_mask = std::move(v.mask);
      k.incidence = std::move(v.incidence_deg);
      return k;
    }
    k.prof.allocate(k.l1 - k.l0, bins(), k.l0);
    k.prof.samples_in_swath = 0;
    // The point targets on the block's lines, found lit or hidden there (as
    // compute_block).
    std::optional<detail::LinePointTargets> on_lines;
    if (targets_) on_lines = targets_->candidates_on_lines(k.l0, k.l1);
    const detail::LineKeep keep{nullptr, nullptr, on_lines ? &*on_lines : nullptr};
    oblique.run(in_, k.l0, k.l1, k.prof, k.counts, v, on_lines ? &keep : nullptr);
    k.targets = on_lines ? targets_->block_result(*on_lines) : detail::BlockTargets{};
    k.scene_mask = std::move(v.mask);
    k.incidence = std::move(v.incidence_deg);
    return k;
  }

  // The block's own cells (its lines' rows or columns, without the halo):
  // their scene-grid maps kept for the writers (count rows x cols along y,
  // rows x count across), the median elevation's second pass.
  void keep_block_maps(const SlarLineEngine& engine, const SceneWindow& win,
                       const SceneMapsWindow& maps, LineBlock& k) {
    const int c_a = engine.cell_of_line(k.l0), c_b = engine.cell_of_line(k.l1 - 1);
    RIS_CHECK(c_a >= 0 && c_b >= 0 && std::abs(c_b - c_a) == k.l1 - k.l0 - 1);
    const int lo = std::min(c_a, c_b), count = k.l1 - k.l0;
    const int cols = win.cols;
    if (along_y_axis(sim().track)) {
      const std::size_t at = sz(lo - win.row0) * sz(cols);
      const std::size_t n = sz(count) * sz(cols);
      k.scene_mask.assign(maps.mask + at, maps.mask + at + n);
      k.incidence.assign(maps.local_incidence_deg + at, maps.local_incidence_deg + at + n);
      for (std::size_t i = at; i < at + n; ++i)
        if (ok_[i] && std::isfinite(z_[i])) ss_.elevation.refine(z_[i]);
    } else {
      const std::size_t at = sz(lo - win.col0);
      k.scene_mask.resize(sz(win.rows) * sz(count));
      k.incidence.resize(k.scene_mask.size());
      for (int r = 0; r < win.rows; ++r) {
        const std::size_t from = sz(r) * sz(cols) + at, to = sz(r) * sz(count);
        std::copy_n(maps.mask + from, count, k.scene_mask.data() + to);
        std::copy_n(maps.local_incidence_deg + from, count, k.incidence.data() + to);
        for (int c = lo; c < lo + count; ++c) {
          const std::size_t i = sz(r) * sz(cols) + sz(c - win.col0);
          if (ok_[i] && std::isfinite(z_[i])) ss_.elevation.refine(z_[i]);
        }
      }
    }
  }

  // A block's maps out, in line order (rank 0).
  void write_block_maps(const LineBlock& k, LineSinks& sinks) {
    const int count = k.l1 - k.l0;
    sinks.scene_mask->write(k.scene_mask.data(), count);
    sinks.incidence->write(k.incidence.data(), count);
  }

  // The seed's shadow map, line by line (ris/image/shadow_map.h).
  void write_shadow_text(const SlarLineProfiles& prof, int l0, int l1, std::ofstream& out) {
    text_.clear();
    for (int line = l0; line < l1; ++line) {
      for (int b = 0; b < bins(); ++b) {
        const std::size_t i = prof.index(line, b);
        text_.push_back(shadow_map_char(prof.mapped_count[i], prof.visible_count[i]));
      }
      text_.push_back('\n');
    }
    out.write(text_.data(), static_cast<std::streamsize>(text_.size()));
  }

  // The image lines the integrator has ready: switch corrections and noise
  // (finish_slar_image), NaN for no data, fading, written out (render_slar
  // + write_slar_products).
  void emit_ready(SlarAzimuthIntegrator& az, LineSinks& sinks) {
    const int n = az.lines_ready();
    if (n == 0) return;
    const int k0 = az.lines_emitted();
    const std::size_t np = sz(n) * sz(bins());
    const SlarImage block = detail::emit_finished_lines(az, n, sim(), rs_.terms, mask_);
    // The point targets' measurement windows (of the mean power before
    // NaN for no data, as measure_point_targets reads it).
    if (targets_ && !coherent_) targets_->observe(k0, n, block.mean_power_w.data());
    detail::count_and_blank_no_data(block, mask_, power_, mean_);
    if (coherent_) {  // the coherent intensity stands in for the faded mean
      speckled_.resize(np);
      coherent_->finish_lines(n, mask_.data(), block.area_m2.data(), speckled_.data());
    } else {
      speckled_ = mean_;
      if (radar().switches.fading)
        apply_fading(speckled_, n, bins(), looks_, radar().fading, info_.seed, k0);
    }
    if (targets_ && coherent_) targets_->observe(k0, n, speckled_.data());  // the intensity
    sinks.mean->write(mean_.data(), n);
    sinks.speckled->write(speckled_.data(), n);
    sinks.mask->write(mask_.data(), n);
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

  // ---- Pass 1m: a track off the axes' scene maps -----------------------
  // Pass 1 spilled each sample's map values (lines x samples, uncompressed,
  // in the staging folder); here blocks of scene rows take each cell's value
  // from the sample nearest its centre (slar_stream_oblique.h), on every
  // rank (the spills read from rank 0's staging folder, as pass 2b reads
  // the slant products), written by rank 0 in row order; then the spills
  // are removed. The median elevation's second pass over each block's rows.
  template <typename T>
  std::unique_ptr<GeoTiffBlockWriter<T>> open_spill(const char* file) {
    GeoTiffCompression none;
    none.method = "NONE";
    none.overviews = false;
    return std::make_unique<GeoTiffBlockWriter<T>>(dir_->path(file), sim().geometry.samples,
                                                   lines(), std::vector<std::string>{file}, nullptr,
                                                   std::nullopt, RasterMetadata{}, none);
  }

  // A block of scene rows' maps (any rank) for rank 0 to write.
  struct MapBand {
    int r0 = 0, rows = 0;
    std::vector<std::uint8_t> mask;
    std::vector<float> incidence;
  };

  void oblique_maps_pass(std::optional<LineSinks>& sinks) {
    const bool root = group_.rank() == 0;
    if (root) stage_done();  // pass 1's lines; lines_pass ends this stage
    stage("scene maps (pass 1m)");
    ByteWriter mask_out;
    FloatWriter incidence_out;
    if (root) {
      sinks->scene_mask->close();
      sinks->incidence->close();
      sinks->scene_mask.reset();
      sinks->incidence.reset();
      mask_out = open_writer<std::uint8_t>("scene_mask.tif", grid().cols, grid().rows);
      incidence_out = open_writer<float>("local_incidence_deg.tif", grid().cols, grid().rows);
    }
    const std::filesystem::path dir(
        share_from_rank0(0.0, root ? dir_->path("").string() : std::string()).second);
    const int fail = options_.faults.maps_block;
    detail::ObliqueSceneMaps maps(grid(), sim().geometry, rs_.imaging.range.near_m,
                                  rs_.imaging.range.far_m());
    std::optional<GdalDataset> mask_ds, incidence_ds;  // at the first block (see geocoded_pass)
    const detail::SpilledValuesReader read = [&](int l0, int nl, int j0, int nj, std::uint8_t* mask,
                                                 float* incidence) {
      read_window(handle(*mask_ds), l0, nl, j0, nj, mask, GDT_Byte, kSpillMask);
      read_window(handle(*incidence_ds), l0, nl, j0, nj, incidence, GDT_Float32, kSpillIncidence);
    };
    const int block_rows = scene_block_rows_;
    const std::size_t cap = sz(block_rows) * sz(grid().cols);
    z_.resize(std::max(z_.size(), cap));
    cat_.resize(z_.size());
    ok_.resize(z_.size());
    detail::run_blocks_in_order<MapBand>(
        group_, (grid().rows + block_rows - 1) / block_rows, order_,
        [&](int b) {
          if (b == fail) {
            throw std::runtime_error(
                fmt::format("scene maps block {}: a failure injected by RIS_FAIL_MAPS_BLOCK", b));
          }
          if (!mask_ds) {
            mask_ds.emplace(open_raster((dir / kSpillMask).string()));
            incidence_ds.emplace(open_raster((dir / kSpillIncidence).string()));
          }
          MapBand k;
          k.r0 = b * block_rows;
          k.rows = std::min(block_rows, grid().rows - k.r0);
          const std::size_t nc = sz(k.rows) * sz(grid().cols);
          in_.read(k.r0, k.rows, 0, grid().cols, z_.data(), cat_.data(), ok_.data());
          for (std::size_t i = 0; i < nc; ++i) {
            if (ok_[i] && std::isfinite(z_[i])) ss_.elevation.refine(z_[i]);  // the band's cells
          }
          k.mask.resize(nc);
          k.incidence.resize(nc);
          maps.rows(k.r0, k.rows, ok_.data(), read, k.mask.data(), k.incidence.data());
          return k;
        },
        [](const MapBand& k, std::vector<char>& out) {
          pack_row_band(k.r0, k.rows, k.incidence, k.mask, out);
        },
        [&](const char* p, std::size_t n) {
          MapBand k;
          unpack_row_band(p, n, grid().cols, k.r0, k.rows, k.incidence, k.mask);
          return k;
        },
        [&](int, MapBand& k) {
          mask_out->write(k.mask.data(), k.rows);
          incidence_out->write(k.incidence.data(), k.rows);
        });
    mask_ds.reset();
    incidence_ds.reset();
    if (!root) return;
    mask_out->close();
    incidence_out->close();
    std::filesystem::remove(dir_->path(kSpillMask));
    std::filesystem::remove(dir_->path(kSpillIncidence));
  }

  // What passes 1b and 2 need (slant_stream_passes.h).
  detail::SlantImagePasses passes() {
    return {group_, order_, sim(),          info_, block_lines(), dir_ ? &*dir_ : nullptr,
            &*bar_, {},     &slant_georef()};
  }

  // The ground-range grid over the median elevation (simulate_slar).
  void set_ground_grid() {
    const double h_ref = options_.reference_height_m
                             ? *options_.reference_height_m
                             : (n_elev_ > 0 ? double(ss_.elevation.value(0)) : 0.0);
    const SlarImage& img = sim().image;
    sim().ground_grid =
        ground_range_grid(img.range, sim().geometry.altitude_m, h_ref, img.line_spacing_m);
  }

  // ---- Pass 2b: geocoded products, scene rows top down ------------------
  // (median, folder) as rank 0 has them, on every rank.
  std::pair<double, std::string> share_from_rank0(double median, const std::string& folder) {
    return detail::share_from_rank0(group_, median, folder);
  }

  // A block of scene rows geocoded (any rank) for rank 0 to write.
  struct GeoBlock {
    int r0 = 0, rows = 0;
    std::vector<float> power;
    std::vector<std::uint8_t> grey;
  };

  // Every rank geocodes blocks of scene rows, reading the slant products
  // rank 0 wrote into `slant_dir` (its staging folder: on a file system
  // every rank sees); rank 0 writes them in row order.
  void geocoded_pass(const GreytoneMap& map, const std::string& slant_dir) {
    const std::filesystem::path dir(slant_dir);
    // Opened at a rank's first block, so that a rank that cannot read them
    // (an output folder not on a shared file system) fails through the
    // schedule: rank 0 reports it and removes its staging folder.
    std::optional<GdalDataset> sp_ds, mask_ds;
    FloatWriter power_out;
    ByteWriter grey_out;
    if (group_.rank() == 0) {
      power_out = open_writer<float>("geocoded_power.tif", grid().cols, grid().rows);
      grey_out = open_writer<std::uint8_t>("geocoded_grey.tif", grid().cols, grid().rows);
    }
    // Scene rows a tile row at a time (pass 1's window is freed).
    const int block_rows = scene_block_rows_;
    const std::size_t cap = sz(block_rows) * sz(grid().cols);
    z_.resize(std::max(z_.size(), cap));
    cat_.resize(z_.size());
    ok_.resize(z_.size());
    pix_line_.resize(cap);
    pix_bin_.resize(cap);
    const int blocks = (grid().rows + block_rows - 1) / block_rows;
    geo_.blocks = blocks;
    detail::run_blocks_in_order<GeoBlock>(
        group_, blocks, order_,
        [&](int b) {
          const double t0 = process_cpu_seconds();
          if (b == fail_geo_block_) {
            throw std::runtime_error(
                fmt::format("geocoding block {}: a failure injected by RIS_FAIL_GEO_BLOCK", b));
          }
          if (!sp_ds) {
            sp_ds.emplace(open_raster((dir / "speckled_power_slant.tif").string()));
            mask_ds.emplace(open_raster((dir / "mask_slant.tif").string()));
          }
          GeoBlock k;
          k.r0 = b * block_rows;
          k.rows = std::min(block_rows, grid().rows - k.r0);
          const std::size_t nc = sz(k.rows) * sz(grid().cols);
          in_.read(k.r0, k.rows, 0, grid().cols, z_.data(), cat_.data(), ok_.data());
          k.power.assign(nc, kNaNf);
          k.grey.assign(nc, std::uint8_t{0});
          geocode_rows(map, k.r0, k.rows, *sp_ds, *mask_ds, k.power.data(), k.grey.data());
          geo_.compute_cpu += process_cpu_seconds() - t0;
          ++geo_.computed;
          return k;
        },
        [](const GeoBlock& k, std::vector<char>& out) {
          pack_row_band(k.r0, k.rows, k.power, k.grey, out);
        },
        [&](const char* p, std::size_t n) {
          GeoBlock k;
          unpack_row_band(p, n, grid().cols, k.r0, k.rows, k.power, k.grey);
          return k;
        },
        [&](int, GeoBlock& k) {
          const double t0 = process_cpu_seconds();
          power_out->write(k.power.data(), k.rows);
          grey_out->write(k.grey.data(), k.rows, 0, geocoded_validity(k.power).data());
          bar_->advance(static_cast<std::int64_t>(k.power.size()));
          geo_.consume_cpu += process_cpu_seconds() - t0;
        });
    if (group_.rank() != 0) return;
    power_out->close();
    grey_out->close();
    if (picture_file("geocoded_grey", grid().cols, grid().rows, info_.max_png_pixels) ==
        "geocoded_grey.png") {
      write_png_gray_from_raster(dir_->path("geocoded_grey.png"), dir_->path("geocoded_grey.tif"),
                                 png_compression_level(info_.compression));
    }
  }

  // Scene rows [r0, r0 + n) (read into z_, ok_): each cell's pixel, then the
  // window of the image they need read back, its greytones, and each cell's
  // power and greytone.
  void geocode_rows(const GreytoneMap& map, int r0, int n, GdalDataset& sp_ds, GdalDataset& mask_ds,
                    float* out_power, std::uint8_t* out_grey) {
    const SlarImage& img = sim().image;
    const int cols = grid().cols;
    const std::size_t nc = sz(n) * sz(cols);
    int l_lo = lines(), l_hi = -1, b_lo = bins(), b_hi = -1;
    for (int r = r0; r < r0 + n; ++r) {
      for (int c = 0; c < cols; ++c) {
        const std::size_t i = sz(r - r0) * sz(cols) + sz(c);
        int line = -1, bin = -1;
        if (!(ok_[i] && geocode_pixel(grid(), sim().track, img, r, c, z_[i], line, bin))) {
          line = -1;
        } else {
          l_lo = std::min(l_lo, line);
          l_hi = std::max(l_hi, line);
          b_lo = std::min(b_lo, bin);
          b_hi = std::max(b_hi, bin);
        }
        pix_line_[i] = line;
        pix_bin_[i] = bin;
      }
    }
    if (l_hi < 0) return;
    const int wl = l_hi - l_lo + 1, wb = b_hi - b_lo + 1;
    const std::size_t np = sz(wl) * sz(wb);
    speckled_.resize(np);
    mask_.resize(np);
    read_window(handle(sp_ds), l_lo, wl, b_lo, wb, speckled_.data(), GDT_Float32,
                "speckled_power_slant.tif");
    read_window(handle(mask_ds), l_lo, wl, b_lo, wb, mask_.data(), GDT_Byte, "mask_slant.tif");
    std::vector<std::uint8_t> no_data(np), grey(np);
    for (std::size_t i = 0; i < np; ++i) no_data[i] = (mask_[i] & pixel_flag::kNoData) ? 1 : 0;
    greytones(speckled_, grey, map, no_data);
    for (std::size_t i = 0; i < nc; ++i) {
      if (pix_line_[i] < 0) continue;
      const std::size_t p = sz(pix_line_[i] - l_lo) * sz(wb) + sz(pix_bin_[i] - b_lo);
      out_power[i] = speckled_[p];
      out_grey[i] = grey[p];
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
  const int fail_block_;            // FaultPlan::line_block, -1: none
  const int fail_geo_block_;        // FaultPlan::geocoding_block, -1: none
  const SlarStreamOptions& options_;
  const SlarRunInfo& info_;
  const std::filesystem::path out_dir_;
  SlarStreamSummary summary_;
  std::string backscatter_file_;
  Georef georef_;
  std::optional<Georef> slant_georef_;
  // Made at the points the passes need them: a refused run shows no bar
  // and stages no folder.
  std::optional<ProgressBar> bar_;
  std::optional<StagedDirectory> dir_;
  detail::StageClock clock_{summary_.stage_seconds, summary_.stage_cpu_seconds};
  int cross_cells_ = 0;
  bool oblique_ = false;     // a track off the grid axes (slar_stream_oblique.h)
  bool spill_maps_ = false;  // scene maps through pass 1m (lines not one per cell)
  static constexpr const char* kSpillMask = ".oblique_mask.tmp.tif";
  static constexpr const char* kSpillIncidence = ".oblique_incidence.tmp.tif";
  int scene_block_rows_ = 0;
  SceneSummary ss_;
  std::uint64_t n_elev_ = 0;
  RadiometrySetup rs_;
  std::optional<detail::StreamTargets> targets_;    // with point targets
  std::optional<detail::CoherentStream> coherent_;  // the coherent SAR
  std::vector<double> looks_;
  FloatRankSelect power_;  // the median mean power's two passes
  // Buffers reused across blocks and passes.
  std::vector<float> z_;
  std::vector<std::uint16_t> cat_;
  std::vector<std::uint8_t> ok_;
  std::vector<float> window_incidence_;
  std::vector<std::uint8_t> window_mask_;
  std::vector<LineBlock> spare_;  // pass 1's consumed blocks, their buffers reused
  struct {
    int blocks = 0, computed = 0;
    double compute_cpu = 0.0, consume_cpu = 0.0;
  } geo_;  // pass 2b's CPU time on this rank
  std::vector<float> mean_, speckled_;
  std::vector<std::uint8_t> mask_;
  std::vector<std::int32_t> pix_line_, pix_bin_;
  std::string text_;
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
