// Morchin's land clutter model: sigma0 of four terrain types against grazing
// angle and frequency, as used for airborne early-warning radar.
//
//   sigma0 = A sigma_c sin(psi) / lambda
//            + mu cot^2(beta0) exp(-tan^2(B - psi) / tan^2(beta0))   (linear)
//   psi    = pi/2 - t, the grazing angle (rad) on the local surface
//   lambda = c / f (m), mu = sqrt(f / 1 GHz) / 4.7
//   sigma_c = 1, except desert: sigma_c = psi / psi_c below the critical
//   angle psi_c = asin(lambda / (4 pi h_e)), h_e = 9.3 beta0^2.2 (m)
//
// The first term is the diffuse return, the second the quasi-specular one
// near vertical incidence (peaking at psi = B).
//
//   terrain        A        B (rad)  beta0 (rad)
//   desert         0.00126  pi/2     0.14
//   farmland       0.004    pi/2     0.2
//   wooded_hills   0.0126   pi/2     0.4
//   mountains      0.04     1.24     0.5
//
// Source: W. C. Morchin, Airborne Early Warning Radar, Artech House, 1990,
// land clutter model and its terrain parameter table; the numbers as read
// from four independent public codes that agree wherever they overlap
// (../shared/data/backscatter/SOURCES.md, morchin_land_clutter.csv: the
// desert row and its critical-angle rule are in two of them). MathWorks'
// Radar Toolbox documentation places the model at 300 MHz to 8 GHz.
// Validity: 0.3-8 GHz, enforced (refused outside unless allow_extrapolation).
// The model has no polarisation: its value is used for HH and VV; HV and VH
// are refused (no published cross-polarised value).
// The "wooded_hills" row is labelled hills in two codes and woods in
// MATLAB's list of Morchin's land types.
//
// TOML:  [category.model]
//        name = "morchin"
//        terrain = "farmland"
#include <algorithm>
#include <array>
#include <string_view>

#include "backscatter/models/models.h"
#include "ris/util/error.h"

namespace ris::detail {

namespace {

struct MorchinTerrain {
  const char* name;
  double a;
  double b_rad;
  double beta0_rad;
  bool desert;  // sigma_c = psi / psi_c below the critical angle
};

constexpr std::array<MorchinTerrain, 4> kTerrains = {{
    {"desert", 0.00126, kPi / 2.0, 0.14, true},
    {"farmland", 0.004, kPi / 2.0, 0.2, false},
    {"wooded_hills", 0.0126, kPi / 2.0, 0.4, false},
    {"mountains", 0.04, 1.24, 0.5, false},
}};

constexpr double kMinFrequencyHz = 0.3e9;
constexpr double kMaxFrequencyHz = 8e9;

const MorchinTerrain* find_terrain(std::string_view name) {
  for (const MorchinTerrain& t : kTerrains) {
    if (name == t.name) return &t;
  }
  return nullptr;
}

class Morchin final : public BackscatterModel {
 public:
  Morchin(const MorchinTerrain& t, ModelContext ctx, std::string key)
      : t_(t), ctx_(std::move(ctx)), key_(std::move(key)) {}

  void check_band(const RadarBand& band) const override {
    if (band.polarisation == Polarisation::HV || band.polarisation == Polarisation::VH) {
      throw InputError(ctx_.file, key_,
                       fmt::format("Morchin's land clutter model ({}) has no {} value: it gives "
                                   "one co-polarised sigma0 (use HH or VV)",
                                   t_.name, to_string(band.polarisation)));
    }
    if (band.frequency_hz < kMinFrequencyHz || band.frequency_hz > kMaxFrequencyHz) {
      report_out_of_validity(ctx_, key_,
                             fmt::format("Morchin's land clutter model ({}) is valid at 0.3-8 GHz, "
                                         "not {:g} GHz",
                                         t_.name, band.frequency_hz / 1e9));
    }
  }

  double sigma0(double incidence_rad, const RadarBand& band) const override {
    return morchin_sigma0(t_.a, t_.b_rad, t_.beta0_rad, t_.desert, band.frequency_hz,
                          kPi / 2.0 - incidence_rad);
  }

  std::string describe() const override { return fmt::format("morchin terrain = {}", t_.name); }

 private:
  MorchinTerrain t_;
  ModelContext ctx_;
  std::string key_;
};

}  // namespace

double morchin_sigma0(double a, double b_rad, double beta0_rad, bool desert, double frequency_hz,
                      double grazing_rad) {
  const double psi = std::clamp(grazing_rad, 0.0, kPi / 2.0);
  const double lambda = kSpeedOfLight_m_per_s / frequency_hz;
  double sigma_c = 1.0;
  if (desert) {
    const double h_e = 9.3 * std::pow(beta0_rad, 2.2);
    const double psi_c = std::asin(std::min(1.0, lambda / (4.0 * kPi * h_e)));
    if (psi < psi_c) sigma_c = psi / psi_c;
  }
  const double mu = std::sqrt(frequency_hz / 1e9) / 4.7;
  const double tb = std::tan(beta0_rad);
  const double tg = std::tan(b_rad - psi);
  return a * sigma_c * std::sin(psi) / lambda + mu / (tb * tb) * std::exp(-(tg * tg) / (tb * tb));
}

std::unique_ptr<BackscatterModel> make_morchin(ConfigTable& params, const ModelContext& ctx) {
  const std::string name = params.get_string("terrain");
  const MorchinTerrain* t = find_terrain(name);
  if (t == nullptr) {
    params.fail("terrain", fmt::format("unknown Morchin terrain \"{}\" (known: desert, farmland, "
                                       "wooded_hills, mountains)",
                                       name));
  }
  const std::string key = params.key_path("terrain");
  params.finish();
  return std::make_unique<Morchin>(*t, ctx, key);
}

}  // namespace ris::detail
