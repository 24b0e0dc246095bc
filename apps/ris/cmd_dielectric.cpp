// ris dielectric: soil permittivity tables from the dielectric models (the
// permittivity a bare-soil backscatter model can take), as `ris sigma0` does
// for backscatter.
//
//   ris dielectric --model dobson1985,mironov2009 --moisture 0:0.4:0.05
//                  --frequency "1.25 GHz,5.3 GHz" --clay 0.2 --sand 0.4
//   ris dielectric --model all --moisture 0.2 --frequency "5.405 GHz" --format json
//   ris dielectric --model hallikainen1985 --moisture 0.05:0.45:0.01 --plot eps.png
//
// Output: eps' and eps'' (eps = eps' - j eps'', eps'' >= 0) for every model,
// frequency and moisture. Inputs outside a model's validity range are refused
// naming the range (see include/ris/backscatter/dielectric.h and each model's
// file); --allow-extrapolation warns instead.
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <iterator>
#include <optional>
#include <sstream>

#include "command_registry.h"
#include "number_list.h"
#include "ris/backscatter/dielectric.h"
#include "ris/image/line_chart.h"
#include "ris/io/atomic_file.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace {

using ris::InputError;
using ris::app::parse_double;
using ris::app::parse_number_list;
using ris::app::split;

struct Options {
  std::string models = "all";
  std::string moisture = "0.05:0.45:0.05";
  std::string frequency = "5.3 GHz";
  double clay = 0.2;
  double sand = 0.4;
  double bulk_density = 1.5;
  double temperature = 20.0;
  std::string conductivity = "dobson1985";
  std::string format = "table";
  std::string out;
  std::string plot;
  bool allow_extrapolation = false;
};

// "0.05:0.45:0.05" (inclusive) or "0.1,0.2", volumetric water content m3/m3.
std::vector<double> parse_moisture(const std::string& text) {
  std::vector<double> out = parse_number_list(text, "--moisture", "m3/m3");
  if (out.empty()) throw InputError("", "--moisture", "no moisture given");
  for (double mv : out) {
    if (mv < 0.0 || mv > 1.0) {
      throw InputError("", "--moisture", fmt::format("{:g} m3/m3 is outside [0, 1]", mv));
    }
  }
  return out;
}

struct Series {
  ris::DielectricModel model;
  double frequency_hz;
  std::vector<double> eps_re;
  std::vector<double> eps_im;  // eps'' >= 0
};

void run(const Options& o) {
  std::vector<ris::DielectricModel> models;
  if (o.models == "all") {  // the registry's, in its order
    for (const auto& [name, model] : ris::dielectric_model_registry()) models.push_back(model);
  }
  for (const auto& n : o.models == "all" ? std::vector<std::string>{} : split(o.models, ',')) {
    const auto m = ris::parse_dielectric_model(n);
    if (!m) {
      throw InputError("", "--model",
                       "unknown dielectric model \"" + n + "\" (known: " +
                           ris::joined_names(ris::dielectric_model_names()) + ", or all)");
    }
    models.push_back(*m);
  }
  if (models.empty()) throw InputError("", "--model", "no model given");
  std::vector<double> freqs;
  for (const auto& f : split(o.frequency, ',')) {
    double hz = 0.0;
    try {
      hz = ris::parse_quantity(f, ris::Quantity::frequency);
    } catch (const std::invalid_argument& e) {
      throw InputError("", "--frequency", e.what());
    }
    if (!(hz > 0.0)) throw InputError("", "--frequency", "expected a frequency > 0");
    freqs.push_back(hz);
  }
  if (freqs.empty()) throw InputError("", "--frequency", "no frequency given");
  const std::vector<double> moisture = parse_moisture(o.moisture);
  if (o.clay < 0.0 || o.clay > 1.0) throw InputError("", "--clay", "expected a fraction in [0, 1]");
  if (o.sand < 0.0 || o.sand > 1.0) throw InputError("", "--sand", "expected a fraction in [0, 1]");
  if (o.clay + o.sand > 1.0 + 1e-9) {
    throw InputError("", "--sand", "clay + sand exceeds 1 (mass fractions of the same soil)");
  }
  if (!(o.bulk_density > 0.0 && o.bulk_density < 2.66)) {
    throw InputError("", "--bulk-density", "expected a dry bulk density in (0, 2.66) g/cm3");
  }

  const std::optional<ris::DobsonConductivity> conductivity =
      ris::parse_dobson_conductivity(o.conductivity);
  if (!conductivity) {
    throw InputError("", "--conductivity",
                     "expected one of " + ris::joined_names(ris::dobson_conductivity_names()) +
                         ", got \"" + o.conductivity + "\"");
  }

  std::vector<Series> series;
  for (ris::DielectricModel m : models) {
    for (double f : freqs) {
      Series s{m, f, {}, {}};
      for (double mv : moisture) {
        const ris::SoilComposition soil{mv,           o.clay, o.sand, o.bulk_density, o.temperature,
                                        *conductivity};
        for (const std::string& problem : ris::dielectric_validity(m, soil, f)) {
          const std::string msg = fmt::format("{}: {}", ris::to_string(m), problem);
          if (!o.allow_extrapolation) {
            throw InputError("", "--model", msg + " (--allow-extrapolation to go on)");
          }
          spdlog::warn("{}", msg);
        }
        const std::complex<double> eps = ris::soil_permittivity(m, soil, f);
        s.eps_re.push_back(eps.real());
        s.eps_im.push_back(-eps.imag());
      }
      series.push_back(std::move(s));
    }
  }

  std::string text;
  const std::string soil_line =
      fmt::format("clay {:g}, sand {:g}, bulk density {:g} g/cm3, {:g} C{}", o.clay, o.sand,
                  o.bulk_density, o.temperature,
                  *conductivity == ris::DobsonConductivity::dobson1985
                      ? ""
                      : ", dobson1985 with the peplinski1995 conductivity");
  if (o.format == "csv") {
    fmt::format_to(std::back_inserter(text),
                   "# soil permittivity written by ris {} (ris "
                   "dielectric); eps = eps' - j eps''\n# {}\n",
                   RIS_VERSION, soil_line);
    fmt::format_to(std::back_inserter(text),
                   "model,frequency_ghz,moisture_m3_m3,eps_real,eps_imag\n");
    for (const Series& s : series) {
      for (size_t i = 0; i < moisture.size(); ++i) {
        fmt::format_to(std::back_inserter(text), "{},{:g},{:g},{:.4f},{:.4f}\n",
                       ris::to_string(s.model), s.frequency_hz / 1e9, moisture[i], s.eps_re[i],
                       s.eps_im[i]);
      }
    }
  } else if (o.format == "json") {
    nlohmann::json j = nlohmann::json::array();
    for (const Series& s : series) {
      j.push_back({{"model", std::string(ris::to_string(s.model))},
                   {"frequency_ghz", s.frequency_hz / 1e9},
                   {"clay", o.clay},
                   {"sand", o.sand},
                   {"bulk_density_g_cm3", o.bulk_density},
                   {"temperature_c", o.temperature},
                   {"dobson_conductivity", o.conductivity},
                   {"moisture_m3_m3", moisture},
                   {"eps_real", s.eps_re},
                   {"eps_imag", s.eps_im}});
    }
    fmt::format_to(std::back_inserter(text), "{}\n", j.dump(2));
  } else if (o.format == "table") {
    fmt::format_to(std::back_inserter(text), "soil permittivity eps' - j eps'' ({})\n", soil_line);
    fmt::format_to(std::back_inserter(text), "{:>8}", "mv");
    for (const Series& s : series) {
      const std::string head =
          fmt::format("{} {:g} GHz", ris::to_string(s.model), s.frequency_hz / 1e9);
      fmt::format_to(std::back_inserter(text), " {:>24}", head);
    }
    fmt::format_to(std::back_inserter(text), "\n");
    for (size_t i = 0; i < moisture.size(); ++i) {
      fmt::format_to(std::back_inserter(text), "{:>8.3f}", moisture[i]);
      for (const Series& s : series) {
        fmt::format_to(std::back_inserter(text), " {:>24}",
                       fmt::format("{:.2f} - {:.2f}j", s.eps_re[i], s.eps_im[i]));
      }
      fmt::format_to(std::back_inserter(text), "\n");
    }
  } else {
    throw InputError("", "--format", "expected table, csv or json, got \"" + o.format + "\"");
  }
  if (o.out.empty()) {
    fmt::print("{}", text);
  } else {
    ris::write_text_file_atomic(o.out, text);
  }

  if (!o.plot.empty()) {
    // One colour per model and frequency; eps' solid, eps'' dashed.
    std::vector<ris::ChartSeries> curves;
    for (size_t k = 0; k < series.size(); ++k) {
      const Series& s = series[k];
      const ris::Rgb8 colour = ris::category_colour(static_cast<std::uint16_t>(k + 1));
      const std::string name =
          fmt::format("{} {:g} GHz", ris::to_string(s.model), s.frequency_hz / 1e9);
      curves.push_back(ris::ChartSeries{name + " eps'", moisture, s.eps_re, colour, 0});
      curves.push_back(ris::ChartSeries{name + " eps''", moisture, s.eps_im, colour, 1});
    }
    ris::ChartSpec spec;
    spec.title = "Soil permittivity (" + soil_line + ")";
    spec.x_label = "volumetric moisture (m3/m3)";
    spec.y_label = "relative permittivity eps', eps''";
    spec.x_min = moisture.front();
    spec.x_max = moisture.back();
    ris::write_line_chart_png(o.plot, spec, curves);
    spdlog::info("wrote {}", o.plot);
  }
}

void add_dielectric(CLI::App& app) {
  auto opts = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "dielectric", "Soil permittivity against moisture from the dielectric models (tables, plot)");
  cmd->add_option("--model,-m", opts->models,
                  ris::joined_names(ris::dielectric_model_names()) + " (comma separated) or all")
      ->capture_default_str();
  cmd->add_option("--moisture", opts->moisture,
                  "Volumetric moisture in m3/m3: start:stop:step or a comma list")
      ->capture_default_str();
  cmd->add_option("--frequency,-f", opts->frequency, "Frequencies, comma separated (\"5.3 GHz\")")
      ->capture_default_str();
  cmd->add_option("--clay", opts->clay, "Clay mass fraction (0..1)")->capture_default_str();
  cmd->add_option("--sand", opts->sand, "Sand mass fraction (0..1; mironov2009 does not use it)")
      ->capture_default_str();
  cmd->add_option("--bulk-density", opts->bulk_density, "Dry bulk density, g/cm3 (dobson1985)")
      ->capture_default_str();
  cmd->add_option("--temperature", opts->temperature, "Soil temperature, deg C (dobson1985)")
      ->capture_default_str();
  cmd->add_option("--conductivity", opts->conductivity,
                  "dobson1985's effective-conductivity fit: dobson1985 (1.4-18 GHz) or "
                  "peplinski1995 (0.3-1.3 GHz; docs/backscatter.md)")
      ->capture_default_str();
  cmd->add_option("--format", opts->format, "Output: table, csv or json")->capture_default_str();
  cmd->add_option("--out,-o", opts->out, "Write the table/CSV/JSON to this file instead of stdout");
  cmd->add_option("--plot", opts->plot, "Also draw eps' and eps'' against moisture into this PNG");
  cmd->add_flag("--allow-extrapolation", opts->allow_extrapolation,
                "Warn instead of failing outside a model's validity range");
  cmd->callback([opts] { run(*opts); });
}

const ris::app::Registration reg{"dielectric", add_dielectric};

}  // namespace
