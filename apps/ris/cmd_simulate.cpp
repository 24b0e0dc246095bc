// `ris simulate`: a SLAR, SAR or PPI simulation of a scene into one output
// folder, by the radar file's `mode` (ris/sim/slar_simulation.h and
// slar_products.h; ris/sim/ppi_simulation.h and ppi_products.h; docs/modes.md).
//
//   ris simulate [--scene S] [--radar R] [--backscatter B] [--targets T]
//                [--out DIR] [--seed N] [--threads N] [--quiet]
//                [--stream] [--block-lines N] [--products LIST] [--calibrated]
//                [--compress fast|small|none]
//   ris simulate --acquisition P --dem D [--frequency A|B] [--burst N] [--swath S]
//                [--category N] [--full-grid] [--earth flat|ellipsoid] [--radar R] ...
//
// With --acquisition: the simulation on that product's own radar grid
// (ris/sim/acquisition_simulation.h): the DEM's terrain imaged with the
// product's orbit, lines and range bins, so the image lines up with the real
// one (docs/geometry.md).
//
// With no arguments: the standard scene (built from its TOML description on
// the fly) with the seed's figure-4-5 radar and the standard backscatter
// library, into ./out.
//
// A scene raster too large for an in-memory run (scene_needs_streaming) is
// streamed from its file in blocks of azimuth lines (ris/sim/slar_stream.h;
// the same products, bounded memory); --stream or --block-lines N asks for
// that on any scene raster (SLAR only).
//
// The run itself is the library's run_simulation (ris/sim/run.h), which the
// server and the Python bindings call too; this file parses, calls, prints.
#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "acquisition_options.h"
#include "command_registry.h"
#include "ris/sim/run.h"
#include "ris/util/process_group.h"
#include "ris/util/progress.h"
#include "run_input_options.h"
#include "seed_option.h"

namespace ris::app {
namespace {

struct SimulateArgs {
  RunRequest request;
  std::string out = "out";
  std::vector<std::string> products;
  std::string compress = "fast";
  AcquisitionArgs acquisition;
  std::string earth;
};

std::string absolute_out(const std::filesystem::path& out) {
  return std::filesystem::absolute(out).lexically_normal().string();
}

void run_simulate(SimulateArgs& a) {
  RunRequest& r = a.request;
  r.out_dir = a.out;
  r.products.stems = a.products;
  r.compression = parse_compression_preset(a.compress, "--compress");
  if (!a.acquisition.path.empty()) {
    r.acquisition_path = a.acquisition.path;
    r.acquisition = a.acquisition.options();
  }
  if (!a.earth.empty()) r.earth = a.earth == "flat" ? EarthModel::flat : EarthModel::ellipsoid;
  // The tests' injected failures (ris/sim/fault_plan.h), read here only.
  r.faults = fault_plan_from_environment();
  // Progress unless --quiet (ris/util/progress.h): a bar on a terminal,
  // plain lines in a log; percent of the run by stage, rate, time remaining.
  auto bar = std::make_shared<ProgressBar>("simulate", 100, "%", r.quiet);
  auto done_pct = std::make_shared<std::int64_t>(0);
  RunCallbacks callbacks;
  if (bar->enabled()) {
    callbacks.progress = [bar, done_pct](std::string_view stage, double fraction) {
      const auto pct = static_cast<std::int64_t>(100.0 * fraction);
      bar->advance(pct - *done_pct);
      *done_pct = pct;
      bar->set_stage(std::string(stage));
    };
  }
  const RunResult res = run_simulation(r, callbacks);
  // The other ranks of an MPI run computed blocks; rank 0 wrote and reports.
  if (process_group().rank() != 0) return;
  if (res.in_memory()) bar->finish();  // a streamed run's passes drew their own
  // The mode's own report (ris/sim/run.h run_summary), then time and folder.
  for (const SummaryLine& line : run_summary(res).lines) fmt::print("{}\n", line.text);
  fmt::print("  {:.2f} s; outputs in {}\n", res.seconds, absolute_out(a.out));
}

void add_simulate(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  RunRequest& r = args->request;
  auto* cmd = app.add_subcommand(
      "simulate", "Simulate a SLAR, SAR or PPI image of a scene (the radar file's mode)");
  add_run_input_options(cmd, r.scene_path, r.radar_path, r.backscatter_path,
                        "Scene: a .toml description or a raster");
  cmd->add_option("--out", args->out, "Output folder (written as a whole)")->capture_default_str();
  cmd->add_option("--targets", r.targets_path,
                  "Point targets (TOML, [[target]] tables): corner reflectors etc.");
  add_seed_option(cmd, r.seed, "Fading seed");
  cmd->add_option("--threads", r.threads, "Threads (0: all cores)")->capture_default_str();
  cmd->add_flag("--quiet", r.quiet, "No progress (a bar on a terminal, else plain log lines)");
  cmd->add_flag("--stream", r.stream,
                "Stream the scene raster from its file in blocks of azimuth lines (bounded "
                "memory; automatic when the scene is too large for memory)");
  cmd->add_option("--block-lines", r.block_lines,
                  "Azimuth lines per streamed block (implies --stream; default: from a 512 MiB "
                  "budget)");
  cmd->add_option("--products", args->products,
                  "Write only these products, comma-separated file stems (docs/outputs.md; "
                  "default: all; metadata.json always)")
      ->delimiter(',');
  cmd->add_flag("--calibrated", r.calibrated,
                "Also write the image calibrated as a SAR product: sigma0, beta0 and gamma0 "
                "over the reference height, linear and in dB (sigma0_slant.tif, "
                "sigma0_slant_db.tif, ...; SLAR and SAR runs in memory, on a scene or an "
                "acquisition's grid; docs/outputs.md)");
  cmd->add_flag("--overviews,!--no-overviews", r.overviews,
                "Internal overviews on products larger than one 256-pixel tile, so a GIS opens "
                "them at any zoom (default; --no-overviews: none, a faster write)");
  cmd->add_option("--geocode-resampling", r.geocode_resampling,
                  "Geocoded products' resampling, as gdalwarp -r: near (default: each cell "
                  "takes the pixel it falls in) or bilinear (in-memory runs)")
      ->capture_default_str();
  cmd->add_option("--compress", args->compress,
                  "Compression: fast (default), small (smallest files, slower), none")
      ->capture_default_str();
  add_acquisition_options(cmd, args->acquisition, false);
  cmd->add_option("--dem", r.dem_path,
                  "With --acquisition: the DEM imaged (geographic WGS 84; geoid heights "
                  "converted where PROJ can)");
  cmd->add_option("--land-cover", r.land_cover_path,
                  "With --acquisition: a ris scene (.toml or raster, projected CRS) whose "
                  "categories the DEM's terrain takes (nearest cell)");
  cmd->add_option("--category", r.category,
                  "With --acquisition: the backscatter category of the DEM's terrain")
      ->capture_default_str();
  cmd->add_flag("--full-grid", r.full_grid,
                "With --acquisition: the product's whole grid, not the window the DEM covers");
  cmd->add_option("--earth", args->earth,
                  "Earth model: flat or ellipsoid (default: the radar file's earth key, else "
                  "ellipsoid with --acquisition and flat without)")
      ->check(CLI::IsMember({"flat", "ellipsoid"}));
  cmd->callback([args] { run_simulate(*args); });
}

const Registration reg{"simulate", add_simulate};

}  // namespace
}  // namespace ris::app
