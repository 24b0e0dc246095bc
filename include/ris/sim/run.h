// One simulation run, as `ris simulate` does it, callable from the command
// line, the HTTP server (`ris serve`) and the Python bindings alike: choose
// the mode from the radar (SLAR, SAR, coherent SAR, PPI), load what was given
// as paths, stream a scene raster too large for memory (or when asked), run,
// render speckle and greytones, measure point targets' impulse responses and
// write the products (docs/outputs.md) into one staged folder.
//
// Inputs come as paths or as objects already in memory (a server keeps its
// scene, radar and backscatter source loaded between runs); an object given
// wins over its path, and the path is still what metadata.json names.
//
// The result keeps the in-memory simulation (mean power, masks, geometry
// maps), so fading and film can be rendered again with another seed or film
// (rerender) without recomputing geometry.
//
// Example:
//   ris::RunRequest r;
//   r.scene_path = "scene.toml";  r.radar_path = "radar.toml";  r.out_dir = "out";
//   ris::RunResult res = ris::run_simulation(r);
//   ris::rerender(res, 7);  ris::write_run_products(res, "out-seed7");
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/cultural_object.h"
#include "ris/scene/scene.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/acquisition_simulation.h"
#include "ris/sim/acquisition_stream.h"
#include "ris/sim/fault_plan.h"
#include "ris/sim/object_centres.h"
#include "ris/sim/point_target.h"
#include "ris/sim/point_target_irf.h"
#include "ris/sim/ppi_simulation.h"
#include "ris/sim/ppi_stream.h"
#include "ris/sim/run_info.h"
#include "ris/sim/slar_simulation.h"
#include "ris/sim/slar_stream.h"

namespace ris {

struct RunRequest {
  // The scene: a .toml description or a raster (ris/scene/scene_source.h).
  std::string scene_path;
  std::shared_ptr<const Scene> scene;  // loaded already (not streamed)
  // With `scene`: its description's buildings and reflectors
  // (LoadedScene::cultural_objects), traced as a scene_path's would be.
  std::vector<CulturalObject> objects;
  // The radar description (TOML).
  std::string radar_path;
  std::optional<RadarParams> radar;
  // The backscatter library or table; empty path: the standard library.
  std::string backscatter_path;
  std::shared_ptr<const Sigma0Source> sigma0;
  // Point targets (TOML, [[target]] tables); none when both are empty.
  std::string targets_path;
  std::optional<std::vector<PointTarget>> targets;

  // Where the products go (one folder, written as a whole); empty: nothing
  // is written (the result holds the images).
  std::filesystem::path out_dir;
  std::uint64_t seed = 1;  // fading
  int threads = 0;         // OpenMP threads; 0: all cores
  // Stream the scene raster in blocks of azimuth lines (SLAR); also chosen
  // when the raster is too large for memory. block_lines > 0 implies it.
  bool stream = false;
  int block_lines = 0;
  bool quiet = false;  // no progress bar in a streamed run
  // Which products and how compressed (ris/sim/run_info.h).
  ProductSelection products;
  CompressionPreset compression = CompressionPreset::fast;
  bool overviews = true;  // internal overviews on large products
  // Geocoding's resampling, gdalwarp's names: "near" (default) or
  // "bilinear" (in-memory runs; ris/image/geocode.h).
  std::string geocode_resampling = "near";
  // Also the calibrated images (sigma0/beta0/gamma0, linear and dB;
  // in-memory SLAR and SAR scene runs; ris/image/radiometric_calibration.h).
  bool calibrated = false;

  // A run on a real acquisition's radar grid instead of a scene
  // (ris/sim/acquisition_simulation.h; scene_path is not read): the product
  // (NISAR .h5, Sentinel-1 .SAFE, ris .toml), which part of it, the DEM
  // (geographic WGS 84) whose terrain is imaged, its one backscatter
  // category, and the whole grid rather than the DEM's window.
  std::string acquisition_path;
  AcquisitionOptions acquisition;
  std::string dem_path;
  // Land cover for it (optional): a ris scene (.toml or raster) whose
  // categories the DEM's terrain takes; none: `category` everywhere.
  std::string land_cover_path;
  std::uint16_t category = AcquisitionSimOptions{}.category;
  bool full_grid = false;
  // The Earth model (`--earth`); nullopt: the radar file's `earth` key, else
  // flat for a scene run and the ellipsoid for an acquisition. A scene run
  // takes only "flat" (its track is in the flat-Earth frame).
  std::optional<EarthModel> earth;
  // Failures injected on purpose (ris/sim/fault_plan.h; streamed runs):
  // none by default; `ris simulate` reads them from the environment.
  FaultPlan faults;
};

struct RunCallbacks {
  // At the start of each stage: its name and the fraction of the run done.
  std::function<void(std::string_view, double)> progress;
  // A warning for the user (SAR resolution finer than the scene, ...);
  // default: spdlog::warn.
  std::function<void(const std::string&)> warning;
};

// A SLAR or SAR run in memory on a scene (the mode is the radar's: SLAR,
// incoherent or coherent SAR): the simulation, its pictures and the point
// targets' measurements.
struct SlarRun {
  SlarSimulation sim;
  SlarPictures pictures;
  bool coherent = false;             // coherent SAR: speckle from the phase history
  std::vector<PointTargetIrf> irfs;  // point targets' impulse responses
  // The user's targets are the first this many of the run's; the rest are
  // scene objects' scattering centres (ris/sim/object_centres.h), imaged
  // alike and not measured.
  std::size_t user_targets = SIZE_MAX;
};

// A SLAR or incoherent SAR run of a radar with several channels
// ([[channel]] tables, ris/sim/slar_channels.h) in memory: each channel's
// run over the one geometry, in the radar file's order. Its products are
// each channel's, suffixed by the channel's name (ris/sim/slar_channel_products.h).
struct ChannelRun {
  std::string name;              // the products' suffix
  std::string backscatter_path;  // its backscatter source (the run's unless its own)
  SlarRun run;
};
struct QuadPolRun;  // ris/sim/sar_quad_pol.h
struct MultiChannelSlarRun {
  std::vector<ChannelRun> channels;
  // A quad-pol SAR (radar [sar] quad_pol): the channels are HH, HV, VH and
  // VV, their pictures made from these images (null: channels of a
  // [[channel]] radar).
  std::shared_ptr<QuadPolRun> quad_pol;
};

// A PPI run in memory.
struct PpiRun {
  PpiSimulation sim;
  PpiPictures pictures;
};

// A run in memory on an acquisition's radar grid: its image (as a SLAR/SAR
// run's, never coherent, no point targets) and its grid window and
// radar-grid layers (`grid->sim` is moved into `image.sim`).
struct AcquisitionRun {
  SlarRun image;
  std::shared_ptr<const AcquisitionSimulation> grid;
  std::string acquisition_path;  // --acquisition
};

// Streamed runs keep no arrays: their products are on disk.
struct StreamedSlarRun {
  SlarStreamSummary summary;
};
struct StreamedPpiRun {
  PpiStreamSummary summary;
};
struct StreamedAcquisitionRun {
  AcquisitionStreamSummary summary;
  std::string acquisition_path;  // --acquisition
};

using ModeRun = std::variant<SlarRun, MultiChannelSlarRun, PpiRun, AcquisitionRun, StreamedSlarRun,
                             StreamedPpiRun, StreamedAcquisitionRun>;

// How the run's lines were computed: the whole scene in memory, or streamed
// in blocks (over `ranks` MPI processes).
enum class RunStrategy { in_memory, streamed };

// One value of a summary line: a key, its value (a number or a string) and
// its unit ("" when it has none).
struct SummaryValue {
  std::string key;
  nlohmann::json value;
  std::string unit;
};

// One line of a run's report: the text `ris simulate` prints (without the
// newline) and the values it shows, for a program to read.
struct SummaryLine {
  std::string text;
  std::vector<SummaryValue> values;
};

// What a run reports of itself (run_summary): its mode ("SLAR", "SAR",
// "coherent SAR", "PPI"), strategy, lines, warnings and the products it
// writes (file stems in the output folder, metadata.json's included).
struct RunSummary {
  std::string mode;
  RunStrategy strategy = RunStrategy::in_memory;
  int ranks = 1;
  std::vector<SummaryLine> lines;
  std::vector<std::string> warnings;
  std::vector<std::string> products;
};

struct RunResult {
  ModeRun run;
  RunStrategy strategy = RunStrategy::in_memory;
  int ranks = 1;  // MPI processes of a streamed run
  RadarParams radar;
  SlarRunInfo info;  // paths, seed, threads, products, compression
  // In-memory scene runs: the scene (shared with the request when it gave one).
  std::shared_ptr<const Scene> scene;
  bool has_targets = false;  // point targets were given
  // The scene's buildings and reflectors as traced (ris/sim/object_centres.h),
  // when it has any.
  std::optional<ObjectCentreStats> objects;
  std::string targets_path;  // where from (metadata.json)
  // Wall time: the whole run, and writing the products.
  double seconds = 0.0;
  double write_seconds = 0.0;

  bool in_memory() const { return strategy == RunStrategy::in_memory; }
};

// The in-memory SLAR/SAR image of a run (a scene's or an acquisition's);
// nullptr for a PPI, a multi-channel (its channels are in
// MultiChannelSlarRun) or a streamed run.
const SlarRun* slar_image_run(const RunResult& result);
SlarRun* slar_image_run(RunResult& result);

// The run as one word: "slar", "sar", "coherent_sar", "ppi" (in memory) or
// "streamed" (what the server and the Python bindings call its kind).
std::string run_kind_name(const RunResult& result);

// The run's report (what `ris simulate` prints before its time and output
// folder), from the mode's own result.
RunSummary run_summary(const RunResult& result);

// The summary as JSON: {"mode", "strategy", "ranks", "lines": [{"text",
// "values": [{"key", "value", "unit"}]}], "warnings", "products"}.
nlohmann::json run_summary_json(const RunSummary& summary);

// Runs one simulation. Throws InputError for bad input (naming the file or
// option and what was expected); nothing is written then.
RunResult run_simulation(const RunRequest& request, const RunCallbacks& callbacks = {});

// The backscatter library a run on `scene_path` uses: `backscatter_path`
// (--backscatter) when given, else the library the scene raster names
// (RIS_BACKSCATTER_LIBRARY: `ris scene import` and `ris scene fractal` write
// it; logged), else the standard library. `ris serve` chooses the same way.
std::string backscatter_library_for(const std::string& backscatter_path,
                                    const std::string& scene_path);

// Speckle and greytones again on the kept simulation with another seed and,
// when given, other film constants (equation 15's X, gamma, k, m); point
// targets are measured again. The geometry and mean power are not
// recomputed. Not for a streamed run (InputError).
void rerender(RunResult& result, std::uint64_t seed, const FilmParams* film = nullptr);

// metadata.json of an in-memory run, as write_run_products writes it. Not
// for a streamed run (InputError: read the metadata.json it wrote).
nlohmann::json run_metadata(const RunResult& result);

// Writes the result's products into out_dir (as run_simulation does);
// returns the seconds taken. Not for a streamed run (InputError).
double write_run_products(const RunResult& result, const std::filesystem::path& out_dir);

}  // namespace ris
