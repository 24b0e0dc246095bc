// Ulaby-Dobson fit: an empirical curve of mean sigma0 against angle for a
// terrain class, band and polarisation.
//
//   sigma0 (dB) = P1 + P2 exp(-P3 t) + P4 cos(P5 t + P6),   t in radians
// Source: Ulaby, F. T. & Dobson, M. C. (1989), Handbook of Radar Scattering
// Statistics for Terrain, Artech House; MODEL.md section 4.
// Parameters, either
//   terrain   a terrain class of the coefficient file ("soil")
//   file      optional coefficient CSV (default <data>/backscatter/
//             ulaby-dobson-1989.csv; its header says where each row is from)
// or inline coefficients for a band you state with valid_frequency:
//   HH, VV, HV   arrays [P1, P2, P3, P4, P5, P6] (VH uses HV); give the
//                polarisations you need
// Validity: the band of each row (its frequency range) and the handbook's
// angular range (about 0-80 deg, documented, not enforced). A band with no
// row is refused naming the bands that exist; allow_extrapolation = true
// uses the row of the nearest band instead.
//
// TOML:  [category.model]
//        name = "ulaby_dobson"
//        terrain = "soil"
#include <array>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "backscatter/models/models.h"
#include "ris/io/safe_paths.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"

namespace ris::detail {
namespace {

struct Row {
  std::string band;
  double fmin_hz = 0.0;
  double fmax_hz = 0.0;
  Polarisation pol = Polarisation::HH;
  std::array<double, 6> p{};
};

std::vector<Row> load_rows(const std::string& path, const std::string& terrain,
                           const ConfigTable& t) {
  require_regular_input(path, t.key_path("file"));
  std::ifstream in(path);
  if (!in) t.fail("file", "cannot open the Ulaby-Dobson coefficient file " + path);
  std::vector<Row> rows;
  std::string line;
  int line_no = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++line_no;
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string item;
    while (std::getline(ss, item, ',')) f.push_back(item);
    if (!header) {
      header = true;
      continue;
    }
    if (f.size() != 11) {
      throw InputError(path, fmt::format("line {}", line_no),
                       "expected 11 fields: terrain,band,frequency_min_ghz,frequency_max_ghz,"
                       "polarisation,p1..p6");
    }
    if (f[0] != terrain) continue;
    Row r;
    r.band = f[1];
    try {
      r.fmin_hz = std::stod(f[2]) * 1e9;
      r.fmax_hz = std::stod(f[3]) * 1e9;
      r.pol = parse_polarisation(f[4]);
      for (size_t i = 0; i < 6; ++i) r.p[i] = std::stod(f[5 + i]);
    } catch (const std::exception& e) {
      throw InputError(path, fmt::format("line {}", line_no), e.what());
    }
    rows.push_back(r);
  }
  return rows;
}

class UlabyDobson final : public BackscatterModel {
 public:
  UlabyDobson(std::vector<Row> rows, std::string source, ModelContext ctx, std::string key)
      : rows_(std::move(rows)),
        source_(std::move(source)),
        ctx_(std::move(ctx)),
        key_(std::move(key)) {}

  void check_band(const RadarBand& band) const override { find(band, true); }

  double sigma0(double incidence_rad, const RadarBand& band) const override {
    const Row& r = find(band, false);
    const double db = r.p[0] + r.p[1] * std::exp(-r.p[2] * incidence_rad) +
                      r.p[3] * std::cos(r.p[4] * incidence_rad + r.p[5]);
    return db_to_linear(db);
  }

  std::string describe() const override { return "ulaby_dobson " + source_; }

 private:
  const Row& find(const RadarBand& band, bool report) const {
    const Polarisation pol =
        band.polarisation == Polarisation::VH ? Polarisation::HV : band.polarisation;
    const Row* nearest = nullptr;
    double best = 1e300;
    std::string bands;
    for (const Row& r : rows_) {
      if (r.pol != pol) continue;
      if (band.frequency_hz >= r.fmin_hz && band.frequency_hz <= r.fmax_hz) return r;
      bands += fmt::format("{}{} ({:g}-{:g} GHz)", bands.empty() ? "" : ", ", r.band,
                           r.fmin_hz / 1e9, r.fmax_hz / 1e9);
      const double centre = 0.5 * (r.fmin_hz + r.fmax_hz);
      if (std::abs(std::log(band.frequency_hz / centre)) < best) {
        best = std::abs(std::log(band.frequency_hz / centre));
        nearest = &r;
      }
    }
    if (nearest == nullptr) {
      throw InputError(
          ctx_.file, key_,
          fmt::format("{} has no {} coefficients", source_, to_string(band.polarisation)));
    }
    if (report) {
      report_out_of_validity(
          ctx_, key_,
          fmt::format("{} has no {} coefficients for {:g} GHz (it has: {})", source_,
                      to_string(band.polarisation), band.frequency_hz / 1e9, bands));
    }
    return *nearest;
  }

  std::vector<Row> rows_;
  std::string source_;
  ModelContext ctx_;
  std::string key_;
};

std::string default_coefficient_file() {
  return (data_dir() / "backscatter" / "ulaby-dobson-1989.csv").string();
}

}  // namespace

std::unique_ptr<BackscatterModel> make_ulaby_dobson(ConfigTable& params, const ModelContext& ctx) {
  std::vector<Row> rows;
  std::string source;
  std::string key;
  if (params.has("terrain")) {
    const std::string terrain = params.get_string("terrain");
    std::string file = default_coefficient_file();
    if (params.has("file")) {
      std::filesystem::path p(params.get_string("file"));
      if (p.is_relative() && !ctx.base_dir.empty()) p = std::filesystem::path(ctx.base_dir) / p;
      file = p.lexically_normal().string();
    }
    rows = load_rows(file, terrain, params);
    if (rows.empty()) {
      params.fail("terrain", fmt::format("no rows for terrain \"{}\" in {}", terrain, file));
    }
    source = fmt::format("terrain \"{}\" from {}", terrain, file);
    key = params.key_path("terrain");
  } else {
    for (const char* pol : {"HH", "VV", "HV"}) {
      if (!params.has(pol)) continue;
      const std::vector<double> p = params.get_double_array(pol);
      if (p.size() != 6) params.fail(pol, "expected six coefficients [P1, P2, P3, P4, P5, P6]");
      Row r;
      r.band = "inline";
      r.fmin_hz = 0.0;
      r.fmax_hz = 1e300;
      r.pol = parse_polarisation(pol);
      std::copy(p.begin(), p.end(), r.p.begin());
      rows.push_back(r);
    }
    if (rows.empty()) {
      params.fail("terrain", "give a terrain class, or inline coefficients HH/VV/HV = [P1..P6]");
    }
    source = "inline coefficients";
    key = params.key_path(rows.front().band == "inline" ? "HH" : "terrain");
  }
  params.finish();
  return std::make_unique<UlabyDobson>(std::move(rows), source, ctx, key);
}

}  // namespace ris::detail
