#include "ris/sim/run.h"

#include <fmt/format.h>
#include <omp.h>
#include <spdlog/spdlog.h>

#include <cctype>
#include <chrono>
#include <set>

#include "ris/backscatter/library.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/io/safe_paths.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/scene_source.h"
#include "ris/scene/scene_stream.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/acquisition_products.h"
#include "ris/sim/acquisition_stream.h"
#include "ris/sim/ppi_products.h"
#include "ris/sim/quad_pol_products.h"
#include "ris/sim/sar_coherent.h"
#include "ris/sim/sar_quad_pol.h"
#include "ris/sim/slar_channel_products.h"
#include "ris/sim/slar_channels.h"
#include "ris/sim/slar_products.h"
#include "ris/util/error.h"
#include "ris/util/process_group.h"
#include "ris/util/resource_guard.h"
#include "sim/sources/acquisition_frame.h"

namespace ris {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

void warn(const RunCallbacks& cb, const std::string& message) {
  if (cb.warning) {
    cb.warning(message);
  } else {
    spdlog::warn("{}", message);
  }
}

// Whether to stream: asked for, or a scene raster too large for memory
// (only its header is read to decide).
void check_block_lines(const RunRequest& r) {
  if (r.block_lines < 0) {
    throw InputError("", "--block-lines",
                     fmt::format("expected a positive number of lines, got {}", r.block_lines));
  }
}

bool should_stream(const RunRequest& r, const RunCallbacks& cb) {
  check_block_lines(r);
  const bool is_raster = std::filesystem::path(r.scene_path).extension() != ".toml";
  if (r.stream || r.block_lines > 0) {
    if (r.scene != nullptr || !is_raster) {
      throw InputError(r.scene_path, "--stream",
                       "a streamed run reads a scene raster; build the description first with: "
                       "ris scene build " +
                           r.scene_path + " -o scene.tif");
    }
    return true;
  }
  if (r.scene != nullptr || !is_raster || dem_needs_import(r.scene_path)) return false;
  const SceneStreamReader probe(r.scene_path);
  if (!scene_needs_streaming(probe.grid().rows, probe.grid().cols)) return false;
  warn(cb, fmt::format("{}: {} x {} cells is too large for an in-memory run; streaming it in "
                       "blocks of azimuth lines",
                       r.scene_path, probe.grid().cols, probe.grid().rows));
  return true;
}

// The backscatter source, loaded unless given (default: the standard
// library).
struct LoadedSigma0 {
  std::string path;
  std::shared_ptr<const Sigma0Source> source;
};

// The backscatter source, loaded unless given: --backscatter, else the
// library a scene raster names (RIS_BACKSCATTER_LIBRARY: `ris scene import`
// and `ris scene fractal` write it), else the standard library.
LoadedSigma0 load_sigma0(const RunRequest& r) {
  LoadedSigma0 in;
  in.path = r.backscatter_path;
  if (r.backscatter_path.empty() && r.sigma0 == nullptr) {
    // A scene given in memory has no file to name a library.
    in.path = backscatter_library_for("", r.scene == nullptr ? r.scene_path : "");
  }
  in.source = r.sigma0 != nullptr ? r.sigma0 : load_sigma0_source(in.path);
  return in;
}

RadarParams load_radar_of(const RunRequest& r) {
  return r.radar ? *r.radar : load_radar(r.radar_path);
}

SlarRunInfo run_info(const RunRequest& r, const std::string& backscatter_path) {
  SlarRunInfo info{r.scene_path, r.radar_path, backscatter_path, r.seed,
                   r.threads > 0 ? r.threads : omp_get_max_threads()};
  info.products = r.products;
  info.compression = r.compression;
  info.overviews = r.overviews;
  info.geocode_resampling =
      parse_geocode_resampling(r.geocode_resampling, "", "--geocode-resampling");
  info.calibrated = r.calibrated;
  return info;
}

// Whether a request asks for calibrated images (--calibrated, or one named
// in --products).
bool asks_calibrated(const RunRequest& r) {
  return r.calibrated || names_calibrated(r.products);
}

// Calibrated images are an in-memory SLAR or SAR scene run's, with this
// radar's range and area terms in its pixels (ris/sim/slar_products.h).
void check_calibrated(const RunRequest& r, const RadarParams& radar) {
  if (!asks_calibrated(r)) return;
  if (radar.mode == RadarMode::ppi) {
    throw InputError(radar.source_file, "--calibrated",
                     "a PPI run writes no calibrated images (its scope has no calibration "
                     "convention yet); leave out --calibrated, or use mode = \"slar\" or "
                     "\"sar\"");
  }
  for (const auto& [on, key] : {std::pair{radar.switches.range, "film.terms.range"},
                                std::pair{radar.switches.area, "film.terms.area"}}) {
    if (on) continue;
    throw InputError(radar.source_file, key,
                     "is false, so the pixels carry the reference system's factor instead of "
                     "this radar's and cannot be calibrated; set it true or leave out "
                     "--calibrated");
  }
}

// A scene run's geometry is the flat-Earth frame's (its track is given in
// scene coordinates); the ellipsoid needs an acquisition's orbit and grid.
void check_scene_earth(const RunRequest& r, const RadarParams& radar) {
  const std::optional<EarthModel> earth = r.earth ? r.earth : radar.earth;
  if (earth.value_or(EarthModel::flat) == EarthModel::flat) return;
  throw InputError(r.earth ? "" : radar.source_file, r.earth ? "--earth" : "earth",
                   "\"ellipsoid\" needs an acquisition's orbit and radar grid (ris simulate "
                   "--acquisition P --dem D); a scene run's track lies in the flat-Earth frame: "
                   "expected \"flat\" or no earth key");
}

// About 10 bytes of products a scene cell: the streamed 40,000^2 example
// (1.6 G cells) wrote 16 GB (README.md, "Scenes larger than memory";
// measured 2026-12-02, with the overviews and GCPs of today's products:
// local_incidence_deg.tif alone is 6.4 GB). It was 7 (11 GB) before.
constexpr std::int64_t kProductBytesPerCell = 10;

// The output folder, checked once every input is read and before any work:
// no folder where a file is, no product over one of the run's inputs
// (ris/io/safe_paths.h), room for the products (ris/util/resource_guard.h;
// a PPI's are sized by its rays, bins and scope, not by the scene).
// temporary_bytes: what a streamed run also writes there for a while
// (streamed_temporary_bytes).
void check_out_dir(const RunRequest& r, const RadarParams& radar, std::int64_t rows,
                   std::int64_t cols, std::int64_t temporary_bytes = 0) {
  if (r.out_dir.empty()) return;
  const RadarMode mode = radar.mode;
  std::vector<std::string> stems{"metadata"};
  for (std::string_view s : mode == RadarMode::ppi ? ppi_product_stems() : slar_product_stems()) {
    stems.emplace_back(s);
  }
  require_safe_output_folder(r.out_dir, stems, "--out");
  if (mode == RadarMode::ppi) {  // the key of the larger part named
    const PpiProductSize z = ppi_product_size(radar);
    require_disk(z.bytes, r.out_dir, radar.source_file,
                 z.scope_bytes >= z.bscope_bytes ? "scan.pixel" : "scan.ray_spacing",
                 fmt::format("the products of a PPI run ({:.0f} rays x {:.0f} range bins, a "
                             "scope of {:.0f} x {:.0f} pixels)",
                             z.rays, z.bins, z.scope_pixels, z.scope_pixels));
    return;
  }
  const std::int64_t cells = checked_mul(rows, cols, r.scene_path, "");
  const std::int64_t products = checked_mul(cells, kProductBytesPerCell, r.scene_path, "");
  require_disk(checked_add(products, temporary_bytes, r.scene_path, ""), r.out_dir, "", "--out",
               fmt::format("the products of a {} x {} cell scene{}", cols, rows,
                           temporary_bytes > 0
                               ? fmt::format(" and {:.0f} MiB of temporary files (a streamed "
                                             "track off the grid axes)",
                                             double(temporary_bytes) / double(1 << 20))
                               : std::string()));
}

bool several_channels(const RadarParams& radar) {
  return radar.channels.size() > 1;
}

// What the engine cannot yet run on several channels, refused before any
// work naming the key (a radar listing one [[channel]] runs as any other).
// `how`: "streamed", "acquisition" or "" (an in-memory scene run).
void check_channels(const RunRequest& r, const RadarParams& radar, std::string_view how,
                    bool has_targets) {
  if (radar.mode == RadarMode::sar && radar.sar.quad_pol) {
    // A quad-pol SAR: an in-memory run of one polarimetric radar.
    if (several_channels(radar)) {
      throw InputError(radar.source_file, "sar.quad_pol",
                       "a quad-pol radar forms its four channels itself; drop the [[channel]] "
                       "tables or set quad_pol = false");
    }
    if (how == "streamed") {
      throw InputError(radar.source_file, "sar.quad_pol",
                       "quad-pol runs are in memory only for now; drop --stream and "
                       "--block-lines, or set quad_pol = false");
    }
    if (how == "acquisition") {
      throw InputError(radar.source_file, "sar.quad_pol",
                       "quad-pol runs on an acquisition's grid are not built yet; run on a scene "
                       "or set quad_pol = false");
    }
    if (asks_calibrated(r)) {
      throw InputError(radar.source_file, "sar.quad_pol",
                       "a quad-pol run writes no calibrated images yet; drop --calibrated (its "
                       "SLCs are in sqrt(W))");
    }
    return;
  }
  if (!several_channels(radar)) return;
  const std::string n = std::to_string(radar.channels.size());
  if (how == "streamed") {
    throw InputError(radar.source_file, "channel",
                     n + " channels: streamed runs take one channel; drop --stream and "
                         "--block-lines (an in-memory run images every channel over one "
                         "geometry) or list one [[channel]]");
  }
  if (how == "acquisition") {
    throw InputError(radar.source_file, "channel",
                     n + " channels: a run on an acquisition's grid takes one channel; list "
                         "one [[channel]]");
  }
  if (radar.mode == RadarMode::ppi) {
    throw InputError(radar.source_file, "channel",
                     n + " channels: a PPI takes one channel for now; list one [[channel]]");
  }
  if (radar.mode == RadarMode::sar && radar.sar.coherent) {
    throw InputError(radar.source_file, "sar.coherent",
                     n + " channels: the coherent SAR is a single-channel run for now; set "
                         "coherent = false or list one [[channel]]");
  }
  if (has_targets) {
    throw InputError(r.targets_path, "--targets",
                     n + " channels in " + radar.source_file +
                         ": point targets are placed in single-channel runs only for now; "
                         "drop --targets or list one [[channel]]");
  }
}

// A streamed run (asked for, or a scene too large for memory) writes no
// calibrated images yet.
void refuse_streamed_calibration(const RunRequest& r) {
  if (!asks_calibrated(r)) return;
  throw InputError(r.acquisition_path.empty() ? r.scene_path : r.acquisition_path, "--calibrated",
                   "a streamed run writes no calibrated images yet; leave out --stream and "
                   "--block-lines (a scene too large for memory streams by itself: crop it), "
                   "or leave out --calibrated");
}

void run_streamed(const RunRequest& r, const RunCallbacks& cb, RunResult& res) {
  refuse_streamed_calibration(r);
  res.strategy = RunStrategy::streamed;
  res.ranks = process_group().size();
  res.radar = load_radar_of(r);
  check_channels(r, res.radar, "streamed", false);
  check_scene_earth(r, res.radar);
  // As the in-memory run (the streams honour the selection and res.info's
  // compression).
  check_product_selection(
      r.products, res.radar.mode == RadarMode::ppi ? ppi_product_stems() : slar_product_stems(),
      "--products");
  const LoadedSigma0 sigma0 = load_sigma0(r);
  res.info = run_info(r, sigma0.path);
  if (res.info.geocode_resampling != GeocodeResampling::nearest) {
    throw InputError("", "--geocode-resampling",
                     "bilinear geocoding is made by in-memory runs only; a streamed run geocodes "
                     "nearest: leave out --stream/--block-lines, or warp its slant-range "
                     "products with gdalwarp -r bilinear (they carry GCPs)");
  }
  require_regular_input(r.scene_path, "--scene");
  {
    const SceneStreamReader probe(r.scene_path);  // the header only
    check_out_dir(r, res.radar, probe.grid().rows, probe.grid().cols,
                  streamed_temporary_bytes(probe.grid(), res.radar));
  }
  std::vector<PointTarget> targets;
  if (r.targets) {
    targets = *r.targets;
  } else if (!r.targets_path.empty()) {
    targets = load_point_targets(r.targets_path);
  }
  res.has_targets = !targets.empty();
  res.targets_path = r.targets_path;
  if (res.radar.mode == RadarMode::ppi) {  // rays in blocks (ris/sim/ppi_stream.h)
    PpiStreamOptions o;
    o.block_rays = r.block_lines;
    o.quiet = r.quiet;
    o.faults = r.faults;
    o.targets = std::move(targets);
    res.run = StreamedPpiRun{
        simulate_ppi_streamed(r.scene_path, res.radar, *sigma0.source, res.info, r.out_dir, o)};
    return;
  }
  SlarStreamOptions o;
  o.block_lines = r.block_lines;
  o.quiet = r.quiet;
  o.faults = r.faults;
  o.targets = std::move(targets);
  o.targets_file = r.targets_path;
  const StreamedSlarRun& run = res.run.emplace<StreamedSlarRun>(
      simulate_slar_streamed(r.scene_path, res.radar, *sigma0.source, res.info, r.out_dir, o));
  // Once, by rank 0, in an MPI run (every rank sets up the same stages).
  if (process_group().rank() == 0)
    for (const std::string& w : run.summary.sim.reported_warnings()) warn(cb, w);
}

// The scene's buildings and reflectors as point targets after the user's
// (ris/sim/object_centres.h). Refused where the centres do not follow the
// geometry yet, naming the scene's first object.
void add_object_centres(RunResult& res, const std::vector<CulturalObject>& objects,
                        const RadarParams& radar, SlarOptions& options, const RunCallbacks& cb) {
  if (several_channels(radar)) {
    throw InputError(objects[0].source, objects[0].label,
                     "scene objects are traced for single-channel radars only for now; list one "
                     "[[channel]] or use a scene without buildings and reflectors");
  }
  if (cb.progress) cb.progress("ray tracing scene objects", 0.05);
  ObjectCentreStats st;
  std::vector<PointTarget> centres = object_scattering_centres(objects, *res.scene, radar, &st);
  options.targets.insert(options.targets.end(), std::make_move_iterator(centres.begin()),
                         std::make_move_iterator(centres.end()));
  res.objects = std::move(st);
}

// The hidden list keeps the user's targets' names only.
void drop_object_centre_names(std::vector<std::string>& hidden,
                              const std::vector<PointTarget>& targets, std::size_t user_targets) {
  if (targets.size() == user_targets) return;
  std::set<std::string> centres;
  for (std::size_t i = user_targets; i < targets.size(); ++i) centres.insert(targets[i].name);
  std::erase_if(hidden, [&](const std::string& n) { return centres.count(n) > 0; });
}

// Speckle, greytones and point-target measurements of a kept SLAR/SAR run.
void render_slar_run(SlarRun& run, bool has_targets, std::uint64_t seed) {
  const SlarSimulation& sim = run.sim;
  run.pictures = run.coherent ? render_slar(sim, seed, coherent_sar_intensity(sim, seed))
                              : render_slar(sim, seed);
  run.irfs.clear();
  if (has_targets) {
    run.irfs = measure_point_targets(sim, run.pictures, run.coherent);
    std::erase_if(run.irfs,
                  [&](const PointTargetIrf& t) { return t.target.target >= run.user_targets; });
  }
}

// A radar with several channels over one geometry, in memory
// (ris/sim/slar_channels.h): one pass of the line engine, then each
// channel's speckle and greytones with the run's seed (each channel the
// bytes its own run gives). A channel's own backscatter source is loaded
// here.
void run_channels(RunResult& res, const LoadedSigma0& sigma0, const SlarOptions& options,
                  const RunCallbacks& cb, std::uint64_t seed) {
  std::vector<std::shared_ptr<const Sigma0Source>> sources;
  std::vector<SlarChannel> channels;
  MultiChannelSlarRun& run = res.run.emplace<MultiChannelSlarRun>();
  for (const RadarChannel& c : res.radar.channels) {
    std::shared_ptr<const Sigma0Source> source = sigma0.source;
    std::string path = sigma0.path;
    if (!c.backscatter_path.empty()) {
      source = load_sigma0_source(c.backscatter_path);
      path = c.backscatter_path;
    }
    sources.push_back(source);
    channels.push_back({*c.radar, source.get(), path});
    run.channels.push_back({c.name, path, {}});
  }
  std::vector<SlarSimulation> sims = simulate_slar_channels(*res.scene, channels, options);
  for (std::size_t c = 0; c < sims.size(); ++c) {
    SlarRun& one = run.channels[c].run;
    one.sim = std::move(sims[c]);
    for (const std::string& w : one.sim.reported_warnings())
      warn(cb, "channel " + run.channels[c].name + ": " + w);
    render_slar_run(one, false, seed);
  }
}

// The pictures of a quad-pol run's four channels from its images.
void render_quad_pol(MultiChannelSlarRun& run, std::uint64_t seed) {
  RIS_CHECK(run.quad_pol && run.channels.size() == 4);
  QuadPolRun& q = *run.quad_pol;
  q.images =
      form_quad_pol({&run.channels[0].run.sim, &run.channels[1].run.sim, &run.channels[3].run.sim},
                    q.shapes, q.targets, seed);
  for (std::size_t c = 0; c < 4; ++c) {
    SlarRun& one = run.channels[c].run;
    one.pictures = render_slar(one.sim, seed, q.images.intensity[c]);
  }
}

// A quad-pol SAR (ris/sim/sar_quad_pol.h), in memory: the HH, HV and VV
// channels over one geometry, each element's scattering vector from its
// category's covariance, HH, HV, VH and VV images with the run's seed.
void run_quad_pol(RunResult& res, const LoadedSigma0& sigma0, const SlarOptions& options,
                  const RunCallbacks& cb, std::uint64_t seed) {
  MultiChannelSlarRun& run = res.run.emplace<MultiChannelSlarRun>();
  run.quad_pol = std::make_shared<QuadPolRun>();
  run.quad_pol->shapes = scene_polarimetry(*res.scene, *sigma0.source, res.radar);
  run.quad_pol->targets = options.targets;
  std::vector<SlarSimulation> sims =
      simulate_quad_pol_channels(*res.scene, res.radar, *sigma0.source, options);
  RIS_CHECK(sims.size() == 3);
  // VH: HV's simulation (one reciprocal image), its own name and noise.
  SlarSimulation vh = sims[1];
  vh.radar.polarisation = Polarisation::VH;
  vh.image.element_power_w.clear();
  std::array<SlarSimulation*, 4> by_channel = {&sims[0], &sims[1], &vh, &sims[2]};
  for (std::size_t c = 0; c < 4; ++c) {
    std::string name(to_string(kQuadPolOrder[c]));
    for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    ChannelRun one{name, sigma0.path, {}};
    one.run.coherent = true;
    one.run.sim = std::move(*by_channel[c]);
    if (c == 0)
      for (const std::string& w : one.run.sim.reported_warnings()) warn(cb, w);
    run.channels.push_back(std::move(one));
  }
  if (cb.progress) cb.progress("quad-pol images", 0.8);
  render_quad_pol(run, seed);
}

// The channels' products as ris/sim/slar_channel_products.h writes them.
std::vector<SlarChannelProducts> channel_products(const MultiChannelSlarRun& run) {
  std::vector<SlarChannelProducts> out;
  for (const ChannelRun& c : run.channels) {
    out.push_back({c.name, &c.run.sim, &c.run.pictures, c.backscatter_path});
  }
  return out;
}

// Whether an acquisition run streams: on request (--stream, --block-lines),
// or when its window is over the in-memory run's cap and the run writes
// products (as a scene too large for memory streams, should_stream). An
// in-memory run's DEM is read whole into `dem`; a streamed run reads it in
// windows.
bool should_stream_acquisition(const RunRequest& r, const RunCallbacks& cb, const Acquisition& acq,
                               const EllipsoidalDemFile& file, std::optional<EllipsoidalDem>& dem) {
  check_block_lines(r);
  if (r.stream || r.block_lines > 0) return true;
  if (!r.out_dir.empty()) {
    // The window from the DEM read in bands (never whole: it may not fit).
    const GridWindow w =
        detail::acquisition_frame(acq, file.grid(), file.summarise(256), r.full_grid).window;
    if (w.size() > detail::kMaxInMemoryPixels) {
      warn(cb, fmt::format("{}: a window of {} lines x {} bins is too large for an in-memory run; "
                           "streaming it in blocks of azimuth lines",
                           r.acquisition_path, w.lines, w.bins));
      return true;
    }
  }
  dem = file.read(0, file.grid().rows, 0, file.grid().cols);
  return false;
}

// The simulation on an acquisition's radar grid (ris/sim/acquisition_simulation.h).
void run_acquisition(const RunRequest& r, const RunCallbacks& cb, RunResult& res) {
  if (!r.targets_path.empty() || (r.targets && !r.targets->empty())) {
    throw InputError(r.targets_path, "--targets",
                     "point targets are not placed on an acquisition's grid yet; drop --targets");
  }
  if (r.dem_path.empty()) {
    throw InputError(r.acquisition_path, "--dem",
                     "an acquisition run needs a DEM of the terrain (geographic WGS 84, as for "
                     "ris topo)");
  }
  if (cb.progress) cb.progress("reading inputs", 0.0);
  res.radar = load_radar_of(r);
  check_channels(r, res.radar, "acquisition", false);
  check_product_selection(r.products, acquisition_product_stems(), "--products");
  check_calibrated(r, res.radar);
  const Acquisition acq = read_acquisition(r.acquisition_path, r.acquisition);
  require_regular_input(r.dem_path, "--dem");
  const EllipsoidalDemFile dem_file(r.dem_path);  // its grid: the heights are read below
  if (!r.out_dir.empty()) {  // checked before any work, as a scene run's (check_out_dir)
    std::vector<std::string> stems{"metadata"};
    for (std::string_view s : acquisition_product_stems()) stems.emplace_back(s);
    require_safe_output_folder(r.out_dir, stems, "--out");
  }
  const LoadedSigma0 sigma0 = load_sigma0(r);
  res.info = run_info(r, sigma0.path);
  res.info.scene_path = r.dem_path;
  AcquisitionSimOptions o;
  o.earth = r.earth ? *r.earth : res.radar.earth.value_or(EarthModel::ellipsoid);
  o.category = r.category;
  o.full_grid = r.full_grid;
  std::optional<Scene> land_cover;
  if (!r.land_cover_path.empty()) {
    land_cover = load_scene_source(r.land_cover_path).scene;
    o.land_cover = &*land_cover;
    o.land_cover_source = r.land_cover_path;
  }
  o.backscatter_file = sigma0.path;
  std::optional<EllipsoidalDem> dem;
  if (should_stream_acquisition(r, cb, acq, dem_file, dem)) {  // ris/sim/acquisition_stream.h
    refuse_streamed_calibration(r);
    SlarStreamOptions so;
    so.block_lines = r.block_lines;
    so.quiet = r.quiet;
    so.faults = r.faults;
    AcquisitionStreamSummary s = simulate_acquisition_streamed(
        acq, dem_file, res.radar, *sigma0.source, o, res.info, r.out_dir, so);
    res.strategy = RunStrategy::streamed;
    res.ranks = process_group().size();
    const StreamedAcquisitionRun& run =
        res.run.emplace<StreamedAcquisitionRun>(std::move(s), r.acquisition_path);
    // Once, by rank 0, in an MPI run (every rank sets up the same stages).
    if (process_group().rank() == 0)
      for (const std::string& w : run.summary.acquisition.sim.warnings) warn(cb, w);
    return;
  }
  if (cb.progress) cb.progress("geometry + image formation on the acquisition's grid", 0.1);
  auto a = std::make_shared<AcquisitionSimulation>(
      simulate_acquisition(acq, *dem, res.radar, *sigma0.source, o));
  AcquisitionRun& run = res.run.emplace<AcquisitionRun>();
  run.image.sim = std::move(a->sim);
  run.grid = std::move(a);
  run.acquisition_path = r.acquisition_path;
  for (const std::string& w : run.image.sim.warnings) warn(cb, w);
  if (cb.progress) cb.progress("speckle and greytones", 0.9);
  render_slar_run(run.image, false, r.seed);
}

// metadata.json's point_targets of a SLAR/SAR run given targets (else none).
nlohmann::json slar_run_extra_metadata(const RunResult& res, const SlarRun& run) {
  nlohmann::json extra = nlohmann::json::object();
  if (res.has_targets) {
    extra["point_targets"] =
        point_target_irf_json(run.irfs, run.sim, res.targets_path, run.coherent);
  }
  if (res.objects) extra["objects"] = object_centre_stats_json(*res.objects);
  return extra;
}

}  // namespace

std::string backscatter_library_for(const std::string& backscatter_path,
                                    const std::string& scene_path) {
  if (!backscatter_path.empty()) return backscatter_path;
  const std::string named = scene_backscatter_library(scene_path);
  if (named.empty()) return default_sigma0_library_path();
  spdlog::info(
      "{}: backscatter from {}, the library the scene names (--backscatter to choose another)",
      scene_path, named);
  return named;
}

RunResult run_simulation(const RunRequest& r, const RunCallbacks& cb) {
  // Checked against the cap before OpenMP sees it (libgomp crashes on
  // 100000 threads; ris/util/resource_guard.h).
  if (checked_thread_count(r.threads, "--threads") > 0 && r.threads > 0) {
    omp_set_num_threads(r.threads);
  }
  const Clock::time_point t0 = Clock::now();
  RunResult res;
  if (process_group().size() > 1 && !(r.stream || r.block_lines > 0)) {
    // Else every rank would run the whole simulation and write the same folder.
    throw InputError(r.acquisition_path.empty() ? r.scene_path : r.acquisition_path, "--stream",
                     fmt::format("a run over {} MPI ranks is a streamed run (docs/scale.md); add "
                                 "--stream, or run without mpirun",
                                 process_group().size()));
  }
  if (!r.acquisition_path.empty()) {
    run_acquisition(r, cb, res);
    if (res.in_memory() && !r.out_dir.empty()) {
      if (cb.progress) cb.progress("writing products", 0.95);
      res.write_seconds = write_run_products(res, r.out_dir);
    }
    if (cb.progress && res.in_memory()) cb.progress("done", 1.0);
    res.seconds = seconds_since(t0);
    return res;
  }
  if (!r.dem_path.empty() || r.full_grid || !r.land_cover_path.empty()) {
    throw InputError(r.dem_path,
                     r.full_grid                  ? "--full-grid"
                     : !r.land_cover_path.empty() ? "--land-cover"
                                                  : "--dem",
                     "goes with --acquisition (a run on a product's radar grid); a scene run "
                     "reads its terrain from --scene");
  }
  if (r.stream || r.block_lines > 0) refuse_streamed_calibration(r);
  if (should_stream(r, cb)) {
    run_streamed(r, cb, res);
    res.seconds = seconds_since(t0);
    return res;
  }
  const auto stage = [&](std::string_view name, double fraction) {
    if (cb.progress) cb.progress(name, fraction);
  };
  stage("reading inputs", 0.0);
  // In the order the command line has always read them (the first bad input
  // is the one reported).
  const RadarParams radar = load_radar_of(r);
  res.radar = radar;
  check_scene_earth(r, radar);
  check_product_selection(r.products,
                          radar.mode == RadarMode::ppi ? ppi_product_stems() : slar_product_stems(),
                          "--products");
  check_calibrated(r, radar);
  std::vector<CulturalObject> cultural;
  if (r.scene != nullptr) {
    res.scene = r.scene;
    cultural = r.objects;
  } else {
    LoadedScene loaded = load_scene_source(r.scene_path);
    cultural = std::move(loaded.cultural_objects);
    res.scene = std::make_shared<const Scene>(std::move(loaded.scene));
  }
  const LoadedSigma0 sigma0 = load_sigma0(r);
  res.info = run_info(r, sigma0.path);
  SlarOptions options;
  options.backscatter_file = sigma0.path;
  options.progress = cb.progress;
  if (r.targets) {
    options.targets = *r.targets;
  } else if (!r.targets_path.empty()) {
    options.targets = load_point_targets(r.targets_path);
  }
  res.has_targets = !options.targets.empty();
  res.targets_path = r.targets_path;
  check_channels(r, radar, "", res.has_targets);
  check_out_dir(r, radar, res.scene->rows, res.scene->cols);
  const std::size_t user_targets = options.targets.size();
  if (!cultural.empty()) add_object_centres(res, cultural, radar, options, cb);

  if (radar.mode == RadarMode::ppi) {
    PpiRun& run = res.run.emplace<PpiRun>();
    run.sim = simulate_ppi(*res.scene, radar, *sigma0.source, options);
    for (const std::string& w : run.sim.warnings) warn(cb, w);
    stage("speckle and greytones", 0.9);
    run.pictures = render_ppi(run.sim, r.seed);
  } else if (radar.mode == RadarMode::sar && radar.sar.quad_pol) {
    run_quad_pol(res, sigma0, options, cb, r.seed);
    stage("speckle and greytones", 0.9);
  } else if (several_channels(radar)) {
    run_channels(res, sigma0, options, cb, r.seed);
    stage("speckle and greytones", 0.9);
  } else {
    SlarRun& run = res.run.emplace<SlarRun>();
    run.coherent = radar.mode == RadarMode::sar && radar.sar.coherent;
    run.user_targets = user_targets;
    run.sim = simulate_slar(*res.scene, radar, *sigma0.source, options);
    drop_object_centre_names(run.sim.hidden_targets, options.targets, user_targets);
    for (const std::string& w : run.sim.reported_warnings()) warn(cb, w);
    stage("speckle and greytones", 0.9);
    render_slar_run(run, res.has_targets, r.seed);
  }
  if (!r.out_dir.empty()) {
    stage("writing products", 0.95);
    res.write_seconds = write_run_products(res, r.out_dir);
  }
  stage("done", 1.0);
  res.seconds = seconds_since(t0);
  return res;
}

const SlarRun* slar_image_run(const RunResult& res) {
  if (const auto* s = std::get_if<SlarRun>(&res.run)) return s;
  if (const auto* a = std::get_if<AcquisitionRun>(&res.run)) return &a->image;
  return nullptr;
}

SlarRun* slar_image_run(RunResult& res) {
  return const_cast<SlarRun*>(slar_image_run(std::as_const(res)));
}

void rerender(RunResult& res, std::uint64_t seed, const FilmParams* film) {
  if (!res.in_memory()) {
    throw InputError(res.info.scene_path, "",
                     "a streamed run keeps no images in memory to render again");
  }
  res.info.seed = seed;
  if (auto* ppi = std::get_if<PpiRun>(&res.run)) {
    if (film != nullptr) ppi->sim.radar.film = *film;
    ppi->pictures = render_ppi(ppi->sim, seed);
    return;
  }
  if (auto* multi = std::get_if<MultiChannelSlarRun>(&res.run)) {
    for (ChannelRun& c : multi->channels) {
      if (film != nullptr) c.run.sim.radar.film = *film;
      if (!multi->quad_pol) render_slar_run(c.run, false, seed);
    }
    if (multi->quad_pol) render_quad_pol(*multi, seed);
    return;
  }
  SlarRun& run = *slar_image_run(res);
  if (film != nullptr) run.sim.radar.film = *film;
  render_slar_run(run, res.has_targets, seed);
}

nlohmann::json run_metadata(const RunResult& res) {
  if (!res.in_memory()) {
    throw InputError(res.info.scene_path, "",
                     "a streamed run's metadata is the metadata.json it wrote");
  }
  if (const auto* a = std::get_if<AcquisitionRun>(&res.run)) {
    return acquisition_metadata(*a->grid, a->image.sim, a->image.pictures, res.info);
  }
  if (const auto* ppi = std::get_if<PpiRun>(&res.run)) {
    return ppi_metadata(*res.scene, ppi->sim, ppi->pictures, res.info);
  }
  if (const auto* multi = std::get_if<MultiChannelSlarRun>(&res.run)) {
    return slar_channels_metadata(*res.scene, channel_products(*multi), res.info);
  }
  const SlarRun& run = std::get<SlarRun>(res.run);
  return slar_metadata(*res.scene, run.sim, run.pictures, res.info,
                       slar_run_extra_metadata(res, run));
}

double write_run_products(const RunResult& res, const std::filesystem::path& out_dir) {
  if (!res.in_memory()) {
    throw InputError(res.info.scene_path, "",
                     "a streamed run writes its products while it runs; none are kept");
  }
  const Clock::time_point t0 = Clock::now();
  if (const auto* a = std::get_if<AcquisitionRun>(&res.run)) {
    write_acquisition_products(out_dir, *a->grid, a->image.sim, a->image.pictures, res.info);
  } else if (const auto* ppi = std::get_if<PpiRun>(&res.run)) {
    write_ppi_products(out_dir, *res.scene, ppi->sim, ppi->pictures, res.info);
  } else if (const auto* multi = std::get_if<MultiChannelSlarRun>(&res.run)) {
    ExtraRunProducts extra;
    if (multi->quad_pol) {
      extra = [&](const std::filesystem::path& staging) {
        return write_quad_pol_products(staging, *res.scene, multi->channels[0].run.sim,
                                       multi->quad_pol->images);
      };
    }
    write_slar_channel_products(out_dir, *res.scene, channel_products(*multi), res.info, extra);
  } else {
    const SlarRun& run = std::get<SlarRun>(res.run);
    write_slar_products(out_dir, *res.scene, run.sim, run.pictures, res.info,
                        slar_run_extra_metadata(res, run));
  }
  return seconds_since(t0);
}

}  // namespace ris
