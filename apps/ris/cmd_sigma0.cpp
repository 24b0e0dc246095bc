// ris sigma0: evaluate backscatter models and category libraries.
//
//   ris sigma0 --library data/backscatter/ku-geometric.toml --category 4,5
//              --frequency "8.6 GHz" --pol HH,VV --angles 0:90:10
//   ris sigma0 --model 'name = "oh1992", rms_height = "1 cm", permittivity = "15 - 4j"'
//              --frequency "5.405 GHz" --pol HH,VV,HV --angles 30 --format json
//   ris sigma0 --category all --pol HH,VV --plot sigma0.png
#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <iterator>
#include <optional>
#include <set>
#include <sstream>

#include "command_registry.h"
#include "number_list.h"
#include "ris/backscatter/backscatter_model.h"
#include "ris/backscatter/library.h"
#include "ris/image/line_chart.h"
#include "ris/io/atomic_file.h"
#include "ris/io/config_table.h"
#include "ris/io/toml_nesting.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace {

using ris::InputError;
using ris::app::parse_number_list;
using ris::app::split;

// Values below this are written as this (a table file needs finite numbers;
// sigma0 is exactly 0 at grazing incidence for most models).
constexpr double kFloorDb = -100.0;

struct Options {
  std::string library;
  std::string categories = "all";
  std::string model;
  std::string frequency = "8.6 GHz";
  std::string polarisations = "HH,VV";
  std::string angles = "0:90:5";
  std::string format = "table";
  std::string plot;
  std::string out;
  bool allow_extrapolation = false;
  bool list_models = false;
};

// "0:90:5" (inclusive) or "10,20,30", in degrees.
std::vector<double> parse_angles_deg(const std::string& text) {
  std::vector<double> out = parse_number_list(text, "--angles", "degrees");
  for (double d : out) {
    if (d < 0.0 || d > 90.0) {
      throw InputError("", "--angles", fmt::format("{:g} deg is outside [0, 90] deg", d));
    }
  }
  if (out.empty()) throw InputError("", "--angles", "no angles given");
  return out;
}

// One curve to evaluate: a category of a library (or the inline model) at one
// band.
struct Series {
  int category = 0;
  std::string name;
  std::string model;
  ris::RadarBand band;
  std::optional<std::array<std::uint8_t, 3>> colour;
  std::vector<double> sigma0_db;
};

double to_db(double linear) {
  return linear > 0.0 ? std::max(kFloorDb, 10.0 * std::log10(linear)) : kFloorDb;
}

void print_model_list() {
  for (const ris::ModelInfo& m : ris::backscatter_model_names()) {
    fmt::print("{:<16} {}\n", m.name, m.summary);
  }
  fmt::print(
      "dielectric models (a soil model's permittivity table): dobson1985, "
      "hallikainen1985, mironov2009\n");
}

double parse_frequency_hz(const std::string& text) {
  double frequency_hz = 0.0;
  try {
    frequency_hz = ris::parse_quantity(text, ris::Quantity::frequency);
  } catch (const std::invalid_argument& e) {
    throw InputError("", "--frequency", e.what());
  }
  if (!(frequency_hz > 0.0)) throw InputError("", "--frequency", "expected a frequency > 0");
  return frequency_hz;
}

std::vector<ris::Polarisation> parse_polarisations(const std::string& text) {
  std::vector<ris::Polarisation> pols;
  for (const auto& p : split(text, ',')) {
    try {
      pols.push_back(ris::parse_polarisation(p));
    } catch (const std::invalid_argument& e) {
      throw InputError("", "--pol", e.what());
    }
  }
  if (pols.empty()) throw InputError("", "--pol", "no polarisation given");
  return pols;
}

// The inline model's curves: the option's text is the body of a TOML inline
// table.
std::vector<Series> model_series(const Options& o, double frequency_hz,
                                 const std::vector<ris::Polarisation>& pols,
                                 const std::vector<double>& angles) {
  toml::table doc;
  ris::require_toml_nesting_within(o.model, ris::kMaxTomlNesting - 1, "--model");
  try {
    doc = toml::parse("model = { " + o.model + " }");
  } catch (const toml::parse_error& e) {
    throw InputError("", "--model",
                     fmt::format("expected TOML key = value pairs such as 'name = \"oh1992\", "
                                 "rms_height = \"1 cm\"': {}",
                                 e.description()));
  }
  ris::ConfigTable root(doc, "--model", "");
  std::optional<ris::ConfigTable> t = root.subtable("model");
  ris::ModelContext ctx{"--model", ".", o.allow_extrapolation, -1, nullptr};
  std::unique_ptr<ris::BackscatterModel> model = ris::make_backscatter_model(*t, ctx);
  std::vector<Series> series;
  for (ris::Polarisation p : pols) {
    Series s{0, "model", model->describe(), {frequency_hz, p}, std::nullopt, {}};
    model->check_band(s.band);
    for (double a : angles) s.sigma0_db.push_back(to_db(model->sigma0(ris::deg_to_rad(a), s.band)));
    series.push_back(std::move(s));
  }
  return series;
}

// The categories --category names: "all", or ids or names ("5,tall milo").
std::vector<std::uint16_t> chosen_categories(const ris::Sigma0Source& src,
                                             const std::string& categories,
                                             const std::string& path) {
  if (categories == "all") return src.category_ids();
  std::vector<std::uint16_t> ids;
  for (const auto& c : split(categories, ',')) {
    std::optional<std::uint16_t> id;
    for (std::uint16_t known : src.category_ids()) {
      if (src.category_name(known) == c) id = known;
    }
    if (!id) {
      char* end = nullptr;
      const long v = std::strtol(c.c_str(), &end, 10);
      if (end != c.c_str() && *end == '\0' && v >= 1 && v <= 65535 &&
          src.has_category(static_cast<std::uint16_t>(v))) {
        id = static_cast<std::uint16_t>(v);
      }
    }
    if (!id) {
      throw InputError(path, "--category",
                       fmt::format("no category \"{}\" in the file (give ids or names)", c));
    }
    ids.push_back(*id);
  }
  return ids;
}

// The library's curves, one per category and polarisation.
std::vector<Series> library_series(const Options& o, double frequency_hz,
                                   const std::vector<ris::Polarisation>& pols,
                                   const std::vector<double>& angles) {
  const std::string path = o.library.empty() ? ris::default_sigma0_library_path() : o.library;
  std::unique_ptr<ris::Sigma0Source> src = ris::load_sigma0_source(path);
  const std::vector<std::uint16_t> ids = chosen_categories(*src, o.categories, path);
  std::vector<Series> series;
  for (std::uint16_t id : ids) {
    for (ris::Polarisation p : pols) {
      Series s{id, src->category_name(id), "", {frequency_hz, p}, src->category_colour(id), {}};
      s.model = src->category_model(id, s.band);
      for (double a : angles) {
        s.sigma0_db.push_back(to_db(src->sigma0(id, ris::deg_to_rad(a), s.band)));
      }
      series.push_back(std::move(s));
    }
  }
  return series;
}

// The sigma0 table format (include/ris/backscatter/sigma0_table.h), so the
// output can be shipped as a table file.
std::string csv_text(const std::vector<Series>& series, const std::vector<double>& angles) {
  std::string text;
  fmt::format_to(std::back_inserter(text), "# sigma0 table written by ris {} (ris sigma0)\n",
                 RIS_VERSION);
  fmt::format_to(std::back_inserter(text), "# values below {:g} dB are written as {:g} dB\n",
                 kFloorDb, kFloorDb);
  std::set<int> named;
  for (const Series& s : series) {
    if (named.insert(s.category).second) {
      fmt::format_to(std::back_inserter(text), "# category {}: {}\n", s.category, s.name);
    }
  }
  for (const Series& s : series)
    fmt::format_to(std::back_inserter(text), "#   model of category {} at {:g} GHz {}: {}\n",
                   s.category, s.band.frequency_hz / 1e9, ris::to_string(s.band.polarisation),
                   s.model);
  fmt::format_to(std::back_inserter(text),
                 "category,frequency_ghz,polarisation,angle_deg,sigma0_db\n");
  for (const Series& s : series) {
    for (size_t i = 0; i < angles.size(); ++i) {
      fmt::format_to(std::back_inserter(text), "{},{:g},{},{:g},{:.3f}\n", s.category,
                     s.band.frequency_hz / 1e9, ris::to_string(s.band.polarisation), angles[i],
                     s.sigma0_db[i]);
    }
  }
  return text;
}

std::string json_text(const std::vector<Series>& series, const std::vector<double>& angles) {
  nlohmann::json j = nlohmann::json::array();
  for (const Series& s : series) {
    j.push_back({{"category", s.category},
                 {"name", s.name},
                 {"model", s.model},
                 {"frequency_ghz", s.band.frequency_hz / 1e9},
                 {"polarisation", std::string(ris::to_string(s.band.polarisation))},
                 {"angle_deg", angles},
                 {"sigma0_db", s.sigma0_db}});
  }
  return fmt::format("{}\n", j.dump(2));
}

std::string table_text(const std::vector<Series>& series, const std::vector<double>& angles,
                       double frequency_hz) {
  std::string text;
  fmt::format_to(std::back_inserter(text), "sigma0 (dB) at {:g} GHz\n", frequency_hz / 1e9);
  for (const Series& s : series) {
    fmt::format_to(std::back_inserter(text), "  {:>3} {}: {} {}\n", s.category,
                   ris::to_string(s.band.polarisation), s.name, s.model);
  }
  fmt::format_to(std::back_inserter(text), "{:>9}", "angle_deg");
  for (const Series& s : series) {
    fmt::format_to(std::back_inserter(text), " {:>9}",
                   fmt::format("{}{}", s.category, ris::to_string(s.band.polarisation)));
  }
  fmt::format_to(std::back_inserter(text), "\n");
  for (size_t i = 0; i < angles.size(); ++i) {
    fmt::format_to(std::back_inserter(text), "{:>9g}", angles[i]);
    for (const Series& s : series)
      fmt::format_to(std::back_inserter(text), " {:>9.2f}", s.sigma0_db[i]);
    fmt::format_to(std::back_inserter(text), "\n");
  }
  return text;
}

// The curves as a chart: one colour per category (the library's display
// colour), one dash pattern per polarisation.
void plot_series(const std::string& plot, const std::vector<Series>& series,
                 const std::vector<double>& angles, const std::vector<ris::Polarisation>& pols,
                 double frequency_hz) {
  std::vector<ris::ChartSeries> curves;
  for (const Series& s : series) {
    ris::ChartSeries c;
    c.label = s.category == 0 ? fmt::format("model {}", ris::to_string(s.band.polarisation))
                              : fmt::format("{} {} {}", s.category, s.name,
                                            ris::to_string(s.band.polarisation));
    c.x = angles;
    c.y = s.sigma0_db;
    if (s.colour) {
      c.colour = ris::Rgb8{(*s.colour)[0], (*s.colour)[1], (*s.colour)[2]};
    } else {
      c.colour = ris::category_colour(static_cast<std::uint16_t>(s.category));
    }
    c.dash =
        static_cast<int>(std::find(pols.begin(), pols.end(), s.band.polarisation) - pols.begin());
    curves.push_back(std::move(c));
  }
  ris::ChartSpec spec;
  spec.title = fmt::format("Backscatter at {:g} GHz", frequency_hz / 1e9);
  spec.x_label = "incidence angle (deg)";
  spec.y_label = "sigma0 (dB)";
  spec.y_floor = kFloorDb;
  spec.x_min = angles.front();
  spec.x_max = angles.back();
  ris::write_line_chart_png(plot, spec, curves);
  spdlog::info("wrote {}", plot);
}

void run(const Options& o) {
  if (o.list_models) {
    print_model_list();
    return;
  }
  const std::vector<double> angles = parse_angles_deg(o.angles);
  const double frequency_hz = parse_frequency_hz(o.frequency);
  const std::vector<ris::Polarisation> pols = parse_polarisations(o.polarisations);
  const std::vector<Series> series = o.model.empty() ? library_series(o, frequency_hz, pols, angles)
                                                     : model_series(o, frequency_hz, pols, angles);

  // Output: built as text, then printed or written atomically to --out.
  std::string text;
  if (o.format == "csv") {
    text = csv_text(series, angles);
  } else if (o.format == "json") {
    text = json_text(series, angles);
  } else if (o.format == "table") {
    text = table_text(series, angles, frequency_hz);
  } else {
    throw InputError("", "--format", "expected table, csv or json, got \"" + o.format + "\"");
  }
  if (o.out.empty()) {
    fmt::print("{}", text);
  } else {
    ris::write_text_file_atomic(o.out, text);
  }
  if (!o.plot.empty()) plot_series(o.plot, series, angles, pols, frequency_hz);
}

void add_sigma0(CLI::App& app) {
  auto opts = std::make_shared<Options>();
  auto* cmd = app.add_subcommand(
      "sigma0",
      "Evaluate backscatter (sigma0 against incidence) for library categories or a model");
  cmd->add_option("--library", opts->library,
                  "Category library (.toml) or sigma0 table (.csv); default "
                  "data/backscatter/ku-geometric.toml");
  cmd->add_option("--category", opts->categories,
                  "Category ids or names, comma separated, or \"all\"")
      ->capture_default_str();
  cmd->add_option("--model", opts->model,
                  "A model with inline parameters instead of a library, as TOML key = value "
                  "pairs: 'name = \"oh1992\", rms_height = \"1 cm\", permittivity = \"15 - 4j\"'");
  cmd->add_option("--frequency,-f", opts->frequency, "Radar frequency, e.g. \"8.6 GHz\"")
      ->capture_default_str();
  cmd->add_option("--pol,-p", opts->polarisations, "Polarisations, comma separated (HH,VV,HV,VH)")
      ->capture_default_str();
  cmd->add_option("--angles,-a", opts->angles,
                  "Incidence angles in degrees: start:stop:step or a comma list")
      ->capture_default_str();
  cmd->add_option("--format", opts->format, "Output: table, csv (the table file format) or json")
      ->capture_default_str();
  cmd->add_option("--out,-o", opts->out, "Write the table/CSV/JSON to this file instead of stdout");
  cmd->add_option("--plot", opts->plot,
                  "Also draw sigma0 (dB) against incidence for every series into this PNG");
  cmd->add_flag("--models", opts->list_models, "List the registered backscatter models and exit");
  cmd->add_flag("--allow-extrapolation", opts->allow_extrapolation,
                "For --model: warn instead of failing outside the model's validity range");
  cmd->callback([opts] { run(*opts); });
}

const ris::app::Registration reg{"sigma0", add_sigma0};

}  // namespace
