// What a run reports of itself (ris/sim/run.h run_summary): one function per
// mode result, each giving the lines `ris simulate` prints and their values;
// the command line prints the text, the server and the Python bindings
// serialise the values.
#include <fmt/format.h>

#include <algorithm>
#include <utility>

#include "ris/sim/acquisition_products.h"
#include "ris/sim/ppi_products.h"
#include "ris/sim/run.h"
#include "ris/sim/slar_channel_products.h"
#include "ris/sim/slar_products.h"

namespace ris {
namespace {

// A line under construction: its text and values.
SummaryLine line(std::string text, std::vector<SummaryValue> values = {}) {
  return SummaryLine{std::move(text), std::move(values)};
}

double percent_of(std::int64_t count, const SlarGeometry& g) {
  return 100.0 * double(count) / (double(g.lines) * double(g.samples));
}

const char* slar_mode_name(const RadarParams& radar) {
  if (radar.mode != RadarMode::sar) return "SLAR";
  return radar.sar.coherent ? "coherent SAR" : "SAR";
}

// An acquisition's image is never coherent (ris/sim/acquisition_simulation.h).
const char* acquisition_mode_name(const RadarParams& radar) {
  return radar.mode == RadarMode::sar ? "SAR" : "SLAR";
}

// The mode's product stems the run's selection keeps, metadata.json first.
std::vector<std::string> products_of(const std::vector<std::string_view>& stems,
                                     const SlarRunInfo& info) {
  std::vector<std::string> out{"metadata"};
  for (std::string_view s : stems) {
    if (info.products.wants(s)) out.emplace_back(s);
  }
  return out;
}

// "  shadow ..%, layover ..%, back-facing ..% of samples; N no-data cells".
SummaryLine geometry_counts(const SlarGeometry& g) {
  const double shadow = percent_of(g.shadow_samples, g);
  const double layover = percent_of(g.layover_samples, g);
  const double back = percent_of(g.back_facing_samples, g);
  return line(fmt::format("  shadow {:.2f}%, layover {:.2f}%, back-facing {:.2f}% of samples; "
                          "{} no-data cells",
                          shadow, layover, back, g.nodata_cells),
              {{"shadow", shadow, "%"},
               {"layover", layover, "%"},
               {"back_facing", back, "%"},
               {"nodata_cells", g.nodata_cells, ""}});
}

SummaryLine slar_image_line(const SlarSimulation& sim) {
  return line(fmt::format("  image: {} azimuth lines x {} range bins (slant), {} ground-range "
                          "pixels",
                          sim.image.lines, sim.image.bins, sim.ground_grid.count),
              {{"lines", sim.image.lines, ""},
               {"bins", sim.image.bins, ""},
               {"ground_range_pixels", sim.ground_grid.count, ""}});
}

// The point targets' measurements and the names of those hidden.
void add_point_targets(std::vector<SummaryLine>& out, const std::vector<PointTargetIrf>& irfs,
                       const std::vector<std::string>& hidden) {
  for (const PointTargetIrf& t : irfs) {
    out.push_back(line(
        fmt::format("  target at R {:.1f} m, s {:.1f} m: 3 dB width {:.2f} m (range) x {:.2f} m "
                    "(azimuth), PSLR {:.1f} dB, ISLR {:.1f} dB",
                    t.target.slant_range_m, t.target.along_m, t.irf.range.width_m,
                    t.irf.azimuth.width_m, t.irf.pslr_db, t.irf.islr_db),
        {{"slant_range", t.target.slant_range_m, "m"},
         {"along", t.target.along_m, "m"},
         {"range_width_3db", t.irf.range.width_m, "m"},
         {"azimuth_width_3db", t.irf.azimuth.width_m, "m"},
         {"pslr", t.irf.pslr_db, "dB"},
         {"islr", t.irf.islr_db, "dB"}}));
  }
  for (const std::string& h : hidden) {
    out.push_back(line(fmt::format("  target {} hidden", h), {{"hidden_target", h, ""}}));
  }
}

SummaryLine ppi_targets_line(const PpiSimulation& ppi) {
  return line(fmt::format("  point targets: {} seen, {} hidden", ppi.point_returns.size(),
                          ppi.hidden_targets.size()),
              {{"targets_seen", ppi.point_returns.size(), ""},
               {"targets_hidden", ppi.hidden_targets.size(), ""}});
}

// Each pass of a streamed run: wall time and, when known, this process's
// CPU time; then the named parts of passes.
void add_stage_times(std::vector<SummaryLine>& out,
                     const std::vector<std::pair<std::string, double>>& wall,
                     const std::vector<double>* cpu,
                     const std::vector<std::pair<std::string, double>>& parts) {
  for (std::size_t i = 0; i < wall.size(); ++i) {
    const auto& [name, t] = wall[i];
    if (cpu == nullptr) {
      out.push_back(line(fmt::format("  {:.2f} s  {}", t, name), {{name, t, "s"}}));
      continue;
    }
    const double c = i < cpu->size() ? (*cpu)[i] : 0.0;
    out.push_back(line(fmt::format("  {:.2f} s  {} ({:.2f} s CPU)", t, name, c),
                       {{name, t, "s"}, {name + " (CPU)", c, "s"}}));
  }
  for (const auto& [name, t] : parts) {
    out.push_back(line(fmt::format("  {:.2f} s  {}", t, name), {{name, t, "s"}}));
  }
}

// An acquisition's first lines (in memory or streamed): inputs, window, terrain.
void add_acquisition_lines(std::vector<SummaryLine>& out, const RunResult& res,
                           const AcquisitionSimulation& a, const SlarSimulation& sim,
                           const std::string& acquisition_path, const char* mode) {
  const char* earth = a.earth == EarthModel::flat ? "flat" : "ellipsoidal";
  out.push_back(
      line(fmt::format("simulated {} on {} ({}) with {} ({}, {} Earth)", res.info.scene_path,
                       acquisition_path, a.mission, res.info.radar_path, mode, earth),
           {{"dem", res.info.scene_path, ""},
            {"acquisition", acquisition_path, ""},
            {"mission", a.mission, ""},
            {"radar", res.info.radar_path, ""},
            {"mode", mode, ""},
            {"earth", earth, ""}}));
  const GridWindow& w = a.window;
  out.push_back(line(
      fmt::format("  image: lines {}..{} x bins {}..{} of the product's {} x {} grid; {:.2f} m "
                  "between lines on the ground, {} terrain points per line",
                  w.line0, w.line0 + w.lines - 1, w.bin0, w.bin0 + w.bins - 1, a.grid.lines,
                  a.grid.bins, a.ground_azimuth_spacing_m, a.profile_points),
      {{"first_line", w.line0, ""},
       {"lines", w.lines, ""},
       {"first_bin", w.bin0, ""},
       {"bins", w.bins, ""},
       {"grid_lines", a.grid.lines, ""},
       {"grid_bins", a.grid.bins, ""},
       {"ground_line_spacing", a.ground_azimuth_spacing_m, "m"},
       {"terrain_points_per_line", a.profile_points, ""}}));
  const SlarGeometry& g = sim.geometry;
  const double shadow = percent_of(g.shadow_samples, g);
  const double layover = percent_of(g.layover_samples, g);
  const double back = percent_of(g.back_facing_samples, g);
  out.push_back(
      line(fmt::format("  shadow {:.2f}%, layover {:.2f}%, back-facing {:.2f}% of "
                       "terrain points",
                       shadow, layover, back),
           {{"shadow", shadow, "%"}, {"layover", layover, "%"}, {"back_facing", back, "%"}}));
}

// "simulated S (C x R cells<how>) with R<mode>".
SummaryLine simulated_line(const RunResult& res, int cols, int rows, const std::string& how,
                           const std::string& mode_suffix, std::vector<SummaryValue> extra) {
  std::vector<SummaryValue> values{{"scene", res.info.scene_path, ""},
                                   {"cols", cols, ""},
                                   {"rows", rows, ""},
                                   {"radar", res.info.radar_path, ""}};
  for (SummaryValue& v : extra) values.push_back(std::move(v));
  return line(fmt::format("simulated {} ({} x {} cells{}) with {}{}", res.info.scene_path, cols,
                          rows, how, res.info.radar_path, mode_suffix),
              std::move(values));
}

RunSummary summary_of(const SlarRun& run, const RunResult& res) {
  RunSummary s;
  s.mode = slar_mode_name(run.sim.radar);
  s.lines.push_back(simulated_line(res, res.scene->cols, res.scene->rows, "",
                                   fmt::format(" ({})", s.mode), {{"mode", s.mode, ""}}));
  s.lines.push_back(slar_image_line(run.sim));
  s.lines.push_back(geometry_counts(run.sim.geometry));
  add_point_targets(s.lines, run.irfs, run.sim.hidden_targets);
  s.warnings = run.sim.reported_warnings();
  s.products = products_of(slar_product_stems(), res.info);
  return s;
}

// One line for the shared image, then one a channel: its band, polarisation
// and the suffix of its products.
RunSummary summary_of(const MultiChannelSlarRun& run, const RunResult& res) {
  const SlarSimulation& first = run.channels.front().run.sim;
  RunSummary s;
  s.mode = slar_mode_name(first.radar);
  const std::size_t n = run.channels.size();
  s.lines.push_back(simulated_line(res, res.scene->cols, res.scene->rows, "",
                                   fmt::format(" ({}, {} channels)", s.mode, n),
                                   {{"mode", s.mode, ""}, {"channels", n, ""}}));
  s.lines.push_back(slar_image_line(first));
  s.lines.push_back(geometry_counts(first.geometry));
  s.products = {"metadata"};
  for (std::string_view stem : slar_scene_wide_stems()) {
    if (res.info.products.wants(stem)) s.products.emplace_back(stem);
  }
  for (const ChannelRun& c : run.channels) {
    const RadarParams& radar = c.run.sim.radar;
    const std::string pol(to_string(radar.polarisation));
    s.lines.push_back(line(fmt::format("  channel {}: {:.3f} GHz {}, products *_{}", c.name,
                                       radar.frequency_hz / 1e9, pol, c.name),
                           {{"channel", c.name, ""},
                            {"frequency", radar.frequency_hz, "Hz"},
                            {"polarisation", pol, ""}}));
    for (const std::string& w : c.run.sim.reported_warnings())
      s.warnings.push_back(c.name + ": " + w);
    for (std::string_view stem : slar_product_stems()) {
      const auto& wide = slar_scene_wide_stems();
      if (res.info.products.wants(stem) &&
          std::find(wide.begin(), wide.end(), stem) == wide.end()) {
        s.products.push_back(std::string(stem) + "_" + c.name);
      }
    }
  }
  return s;
}

RunSummary summary_of(const PpiRun& run, const RunResult& res) {
  const PpiSimulation& ppi = run.sim;
  RunSummary s;
  s.mode = "PPI";
  s.lines.push_back(
      simulated_line(res, res.scene->cols, res.scene->rows, "", " (PPI)", {{"mode", "PPI", ""}}));
  s.lines.push_back(
      line(fmt::format("  B-scope: {} rays x {} range bins; scope {} x {} pixels of {:.2f} m",
                       ppi.bscope.lines, ppi.bscope.bins, ppi.scope_grid.size, ppi.scope_grid.size,
                       ppi.scope_grid.pixel_m),
           {{"rays", ppi.bscope.lines, ""},
            {"bins", ppi.bscope.bins, ""},
            {"scope_pixels", ppi.scope_grid.size, ""},
            {"scope_pixel", ppi.scope_grid.pixel_m, "m"}}));
  const double shadow = percent_of(ppi.geometry.rays.shadow_samples, ppi.geometry.rays);
  s.lines.push_back(line(fmt::format("  antenna at {:.1f} m (terrain {:.1f} m); shadow {:.2f}% "
                                     "of ray samples",
                                     ppi.geometry.altitude_m, ppi.geometry.site_ground_m, shadow),
                         {{"antenna_height", ppi.geometry.altitude_m, "m"},
                          {"site_terrain_height", ppi.geometry.site_ground_m, "m"},
                          {"shadow", shadow, "%"}}));
  if (res.has_targets) s.lines.push_back(ppi_targets_line(ppi));
  s.warnings = ppi.warnings;
  s.products = products_of(ppi_product_stems(), res.info);
  return s;
}

RunSummary summary_of(const AcquisitionRun& run, const RunResult& res) {
  RunSummary s;
  s.mode = acquisition_mode_name(run.image.sim.radar);
  add_acquisition_lines(s.lines, res, *run.grid, run.image.sim, run.acquisition_path,
                        s.mode.c_str());
  s.warnings = run.image.sim.warnings;
  s.products = products_of(acquisition_product_stems(), res.info);
  return s;
}

RunSummary summary_of(const StreamedSlarRun& run, const RunResult& res) {
  const SlarStreamSummary& st = run.summary;
  RunSummary s;
  s.mode = slar_mode_name(st.sim.radar);
  s.lines.push_back(
      simulated_line(res, st.grid.cols, st.grid.rows,
                     fmt::format(", streamed in {} blocks of {} lines", st.blocks, st.block_lines),
                     "", {{"blocks", st.blocks, ""}, {"block_lines", st.block_lines, ""}}));
  s.lines.push_back(slar_image_line(st.sim));
  s.lines.push_back(geometry_counts(st.sim.geometry));
  add_point_targets(s.lines, st.irfs, st.sim.hidden_targets);
  add_stage_times(s.lines, st.stage_seconds, &st.stage_cpu_seconds, st.cpu_parts);
  s.warnings = st.sim.reported_warnings();
  s.products = products_of(slar_product_stems(), res.info);
  return s;
}

RunSummary summary_of(const StreamedPpiRun& run, const RunResult& res) {
  const PpiStreamSummary& p = run.summary;
  RunSummary s;
  s.mode = "PPI";
  s.lines.push_back(simulated_line(
      res, p.grid.cols, p.grid.rows,
      fmt::format(", streamed in {} blocks of {} rays, {} scene windows", p.blocks, p.block_rays,
                  p.windows),
      "",
      {{"blocks", p.blocks, ""}, {"block_rays", p.block_rays, ""}, {"windows", p.windows, ""}}));
  s.lines.push_back(line(
      fmt::format("  B-scope: {} rays x {} range bins; scope {} x {} pixels", p.sim.bscope.lines,
                  p.sim.bscope.bins, p.sim.scope_grid.size, p.sim.scope_grid.size),
      {{"rays", p.sim.bscope.lines, ""},
       {"bins", p.sim.bscope.bins, ""},
       {"scope_pixels", p.sim.scope_grid.size, ""}}));
  s.lines.push_back(geometry_counts(p.sim.geometry.rays));
  if (res.has_targets) s.lines.push_back(ppi_targets_line(p.sim));
  add_stage_times(s.lines, p.stage_seconds, nullptr, {});
  s.warnings = p.sim.warnings;
  s.products = products_of(ppi_product_stems(), res.info);
  return s;
}

RunSummary summary_of(const StreamedAcquisitionRun& run, const RunResult& res) {
  const AcquisitionStreamSummary& st = run.summary;
  RunSummary s;
  // The radar's mode, as the in-memory run names it (before the result per
  // mode a streamed acquisition printed "SLAR" whatever the radar).
  s.mode = acquisition_mode_name(st.acquisition.sim.radar);
  add_acquisition_lines(s.lines, res, st.acquisition, st.acquisition.sim, run.acquisition_path,
                        s.mode.c_str());
  s.lines.push_back(
      line(fmt::format("  streamed in {} blocks of {} lines", st.blocks, st.block_lines),
           {{"blocks", st.blocks, ""}, {"block_lines", st.block_lines, ""}}));
  add_stage_times(s.lines, st.stage_seconds, &st.stage_cpu_seconds, st.cpu_parts);
  s.warnings = st.acquisition.sim.warnings;
  s.products = products_of(acquisition_product_stems(), res.info);
  return s;
}

}  // namespace

RunSummary run_summary(const RunResult& res) {
  RunSummary s = std::visit([&res](const auto& run) { return summary_of(run, res); }, res.run);
  s.strategy = res.strategy;
  s.ranks = res.ranks;
  return s;
}

std::string run_kind_name(const RunResult& res) {
  if (!res.in_memory()) return "streamed";
  if (std::holds_alternative<PpiRun>(res.run)) return "ppi";
  if (const auto* multi = std::get_if<MultiChannelSlarRun>(&res.run)) {
    return multi->channels.front().run.sim.radar.mode == RadarMode::sar ? "sar" : "slar";
  }
  const SlarRun& run = *slar_image_run(res);
  if (run.coherent) return "coherent_sar";
  return run.sim.radar.mode == RadarMode::sar ? "sar" : "slar";
}

nlohmann::json run_summary_json(const RunSummary& s) {
  nlohmann::json lines = nlohmann::json::array();
  for (const SummaryLine& l : s.lines) {
    nlohmann::json values = nlohmann::json::array();
    for (const SummaryValue& v : l.values) {
      values.push_back({{"key", v.key}, {"value", v.value}, {"unit", v.unit}});
    }
    lines.push_back({{"text", l.text}, {"values", values}});
  }
  return {{"mode", s.mode},
          {"strategy", s.strategy == RunStrategy::in_memory ? "in_memory" : "streamed"},
          {"ranks", s.ranks},
          {"lines", lines},
          {"warnings", s.warnings},
          {"products", s.products}};
}

}  // namespace ris
