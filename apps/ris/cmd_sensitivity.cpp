// `ris sensitivity`: how the simulated image changes as one parameter moves,
// or as the ground truth holds less detail (ris/analysis/sensitivity.h,
// docs/quality.md "ris sensitivity"): a CSV row per run, a chart per
// parameter, and the least detail that keeps the image within a tolerance of
// the full-detail one (the seed's "minimum level of information").
//
//   ris sensitivity [--scene S] [--radar R] [--backscatter B]
//                   --vary KEY=V1,V2,... [--vary ...] [--tolerance-db T]
//                   [--seed N] [--out DIR]
#include <fmt/format.h>

#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "command_registry.h"
#include "ris/analysis/sensitivity.h"
#include "ris/backscatter/library.h"
#include "ris/image/line_chart.h"
#include "ris/io/atomic_file.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/one_channel_radar.h"
#include "ris/sensor/polarisation.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "seed_option.h"

namespace ris::app {
namespace {

struct SensitivityArgs {
  std::string scene, radar, backscatter, out;
  std::vector<std::string> vary;
  double tolerance_db = 1.0;
  std::uint64_t seed = 1;
};

// "key=v1,v2,...": values in the key's unit (frequency and elevation_step
// take units, polarisation names).
SensitivityAxis parse_axis(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos) {
    throw InputError("", "--vary", fmt::format("expected KEY=V1,V2,..., got '{}'", text));
  }
  SensitivityAxis a;
  a.key = text.substr(0, eq);
  if (!is_sensitivity_key(a.key)) {
    throw InputError("", "--vary",
                     fmt::format("unknown key '{}'; expected one of {}", a.key,
                                 fmt::join(sensitivity_keys(), ", ")));
  }
  std::stringstream ss(text.substr(eq + 1));
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      if (a.key == "frequency") {
        a.values.push_back(parse_quantity(item, Quantity::frequency));
      } else if (a.key == "elevation_step") {
        a.values.push_back(parse_quantity(item, Quantity::length));
      } else if (a.key == "polarisation") {
        a.values.push_back(static_cast<double>(static_cast<int>(parse_polarisation(item))));
      } else {
        std::size_t used = 0;
        a.values.push_back(std::stod(item, &used));
        if (used != item.size()) throw std::invalid_argument(item);
      }
    } catch (const InputError&) {
      throw;
    } catch (const std::exception& e) {
      throw InputError("", "--vary", fmt::format("{}: bad value '{}' ({})", a.key, item, e.what()));
    }
  }
  if (a.values.empty()) throw InputError("", "--vary", fmt::format("{}: no values", a.key));
  return a;
}

std::string value_text(const SensitivityRow& r) {
  if (r.key == "polarisation") {
    return std::string(to_string(static_cast<Polarisation>(static_cast<int>(r.value))));
  }
  return fmt::format("{:g}", r.value);
}

void run(const SensitivityArgs& a) {
  if (a.vary.empty()) throw InputError("", "--vary", "give at least one KEY=V1,V2,...");
  if (!(a.tolerance_db > 0.0)) {
    throw InputError("", "--tolerance-db", fmt::format("expected > 0, got {}", a.tolerance_db));
  }
  std::vector<SensitivityAxis> axes;
  for (const std::string& v : a.vary) axes.push_back(parse_axis(v));
  SensitivityStudy st;
  st.scene = std::make_shared<Scene>(load_scene_source(a.scene).scene);
  st.radar = load_one_channel_radar(a.radar, "ris sensitivity");
  st.backscatter_path = a.backscatter.empty() ? default_sigma0_library_path() : a.backscatter;
  st.sigma0 = load_sigma0_source(st.backscatter_path);
  st.seed = a.seed;

  fmt::print("{:<20} {:>10} {:>10} {:>9} {:>9} {:>8} {:>7}\n", "key", "value", "pixels", "RMS dB",
             "bias dB", "Pearson", "ENL");
  const std::vector<SensitivityRow> rows = run_sensitivity(st, axes, [](const SensitivityRow& r) {
    fmt::print("{:<20} {:>10} {:>10} {:>9.3f} {:>9.3f} {:>8.4f} {:>7.3f}\n", r.key, value_text(r),
               r.pixels, r.rms_db, r.bias_db, r.pearson, r.enl);
    std::fflush(stdout);
  });

  // The least detail within the tolerance, per detail key.
  nlohmann::json summary = {{"tolerance_db", a.tolerance_db},
                            {"minimum_detail", nlohmann::json::object()}};
  for (const char* key : {"cell_factor", "elevation_step", "mislabel"}) {
    std::optional<double> coarsest;
    for (const SensitivityRow& r : rows)
      if (r.key == key && r.rms_db <= a.tolerance_db && (!coarsest || r.value > *coarsest))
        coarsest = r.value;
    if (coarsest) {
      summary["minimum_detail"][key] = *coarsest;
      fmt::print("least detail within {:.2f} dB RMS: {} = {:g}\n", a.tolerance_db, key, *coarsest);
    }
  }
  if (a.out.empty()) return;
  StagedDirectory dir(a.out);
  std::string csv = "key,value,pixels,rms_db,bias_db,pearson,enl\n";
  nlohmann::json rj = nlohmann::json::array();
  for (const SensitivityRow& r : rows) {
    csv += fmt::format("{},{},{},{:.6f},{:.6f},{:.6f},{:.6f}\n", r.key, value_text(r), r.pixels,
                       r.rms_db, r.bias_db, r.pearson, r.enl);
    rj.push_back({{"key", r.key},
                  {"value", r.value},
                  {"pixels", r.pixels},
                  {"rms_db", r.rms_db},
                  {"bias_db", r.bias_db},
                  {"pearson", r.pearson},
                  {"enl", r.enl}});
  }
  summary["rows"] = rj;
  write_text_file_atomic(dir.path("sensitivity.csv"), csv);
  write_text_file_atomic(dir.path("sensitivity.json"), summary.dump(1) + "\n");
  for (const SensitivityAxis& ax : axes) {
    if (ax.key == "polarisation" || ax.values.size() < 2) continue;
    ChartSeries s{"RMS dB", {}, {}, {30, 30, 200}};
    for (const SensitivityRow& r : rows)
      if (r.key == ax.key) s.x.push_back(r.value), s.y.push_back(r.rms_db);
    ChartSpec spec;
    spec.title = "Sensitivity of the mean-power image to " + ax.key;
    spec.x_label = ax.key + (ax.key == "frequency"        ? " (Hz)"
                             : ax.key == "elevation_step" ? " (m)"
                                                          : "");
    spec.y_label = "RMS dB difference";
    spec.y_min = 0.0;
    write_line_chart_png(dir.path(ax.key + ".png"), spec, {s});
  }
  dir.commit();
  fmt::print("sensitivity.csv, sensitivity.json and a chart per parameter in {}\n", a.out);
}

void add_sensitivity(CLI::App& app) {
  auto a = std::make_shared<SensitivityArgs>();
  a->scene = default_scene_path();
  a->radar = default_radar_path();
  auto* cmd = app.add_subcommand(
      "sensitivity", "How the image changes with a parameter or with less ground-truth detail");
  cmd->add_option("--scene", a->scene, "Scene: a .toml description or a raster")
      ->capture_default_str();
  cmd->add_option("--radar", a->radar, "Radar description (TOML)")->capture_default_str();
  cmd->add_option("--backscatter", a->backscatter, "Backscatter library or table");
  cmd->add_option("--vary", a->vary,
                  "KEY=V1,V2,... (repeatable): cell_factor, elevation_step, mislabel, frequency, "
                  "polarisation, film_gamma, film_density_range, seed")
      ->required();
  cmd->add_option("--tolerance-db", a->tolerance_db,
                  "RMS dB difference from the full-detail image still acceptable")
      ->capture_default_str();
  add_seed_option(cmd, a->seed, "Fading seed");
  cmd->add_option("--out", a->out, "Folder for sensitivity.csv, .json and the charts");
  cmd->callback([a] { run(*a); });
}

const Registration reg{"sensitivity", add_sensitivity};

}  // namespace
}  // namespace ris::app
