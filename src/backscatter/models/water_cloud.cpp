// Water cloud: a vegetation canopy as a uniform cloud of water droplets over
// a ground whose backscatter comes from any other registered model.
//
//   sigma0 = A V1 cos(theta) (1 - tau^2) + tau^2 sigma0_ground(theta)
//   tau^2  = exp(-2 B V2 / cos(theta))          (two-way canopy transmissivity)
// Source: Attema, E. P. W. & Ulaby, F. T. (1978), "Vegetation modeled as a
// water cloud", Radio Science 13(2), 357-364, in the two-descriptor form of
// Ulaby, Allen, Eger & Kanemasu (1984), "Relating the microwave backscattering
// coefficient to leaf area index", Remote Sens. Environ. 14, 113-133; and
// MODEL.md section 4.
// Parameters:
//   A, B     fitted constants (>= 0); their units are the inverse of V1's and
//            V2's (with V = vegetation water content in kg/m^2, B in m^2/kg).
//            Either a number, or a power law in frequency (a ris extension,
//            for one parameter set valid across bands):
//              A = { value = 0.228, frequency = "8.6 GHz", exponent = 0.75 }
//            meaning A(f) = value (f / frequency)^exponent.
//   V1, V2   canopy descriptors (>= 0), e.g. vegetation water content or LAI
//   ground   a table naming the ground model and its parameters
// Validity: A and B are fitted per crop, band and polarisation; state the
// band range they hold for with valid_frequency = ["1 GHz", "18 GHz"] (or give
// per-band entries). Limits: V -> 0 gives the ground model; an opaque canopy
// (B V2 -> infinity) gives A V1 cos(theta).
//
// TOML:  [category.model]
//        name = "water_cloud"
//        A = 0.0012
//        B = 0.091
//        V1 = 1.0
//        V2 = 1.0
//        [category.model.ground]
//        name = "oh1992"
//        rms_height = "1 cm"
//        permittivity = "15 - 4j"
#include "backscatter/models/models.h"

namespace ris::detail {
namespace {

// A constant or value * (f / f0)^exponent.
struct PowerLaw {
  double value = 0.0;
  double f0_hz = 1.0;
  double exponent = 0.0;
  double at(double f_hz) const { return value * std::pow(f_hz / f0_hz, exponent); }
  std::string describe() const {
    if (exponent == 0.0) return fmt::format("{:g}", value);
    return fmt::format("{:g} (f / {:g} GHz)^{:g}", value, f0_hz / 1e9, exponent);
  }
};

PowerLaw get_power_law(ConfigTable& params, const std::string& key) {
  if (!params.has(key)) params.fail(key, "missing required key");
  if (params.raw(key)->is_table()) {
    std::optional<ConfigTable> t = params.subtable(key);
    PowerLaw p;
    p.value = get_nonnegative(*t, "value");
    p.f0_hz = t->get_quantity("frequency", Quantity::frequency);
    if (!(p.f0_hz > 0.0)) t->fail("frequency", "expected a reference frequency > 0");
    p.exponent = t->get_double("exponent");
    t->finish();
    return p;
  }
  return PowerLaw{get_nonnegative(params, key), 1.0, 0.0};
}

class WaterCloud final : public BackscatterModel {
 public:
  WaterCloud(PowerLaw a, PowerLaw b, double v1, double v2, std::unique_ptr<BackscatterModel> ground)
      : a_(a), b_(b), v1_(v1), v2_(v2), ground_(std::move(ground)) {}

  void check_band(const RadarBand& band) const override { ground_->check_band(band); }

  double sigma0(double incidence_rad, const RadarBand& band) const override {
    const double c = std::cos(incidence_rad);
    // At grazing incidence the path through the canopy is infinite: tau^2 = 0
    // and the canopy term A V1 cos(theta) vanishes too.
    if (c <= 1e-12) return 0.0;
    const double f = band.frequency_hz;
    const double tau2 = std::exp(-2.0 * b_.at(f) * v2_ / c);
    return a_.at(f) * v1_ * c * (1.0 - tau2) + tau2 * ground_->sigma0(incidence_rad, band);
  }

  // A(f) and B(f) once per curve and the ground's own curve: the same values
  // as sigma0() at each angle (the ground is also evaluated at grazing
  // incidence, where its value is not used).
  void sigma0_curve(const double* incidence_rad, std::size_t n, const RadarBand& band,
                    double* out) const override {
    ground_->sigma0_curve(incidence_rad, n, band, out);
    const double f = band.frequency_hz;
    const double a = a_.at(f), b = b_.at(f);
    for (std::size_t i = 0; i < n; ++i) {
      const double c = std::cos(incidence_rad[i]);
      if (c <= 1e-12) {
        out[i] = 0.0;
        continue;
      }
      const double tau2 = std::exp(-2.0 * b * v2_ / c);
      out[i] = a * v1_ * c * (1.0 - tau2) + tau2 * out[i];
    }
  }

  std::string describe() const override {
    return fmt::format("water_cloud A = {}, B = {}, V1 = {:g}, V2 = {:g} over {}", a_.describe(),
                       b_.describe(), v1_, v2_, ground_->describe());
  }

 private:
  PowerLaw a_;
  PowerLaw b_;
  double v1_;
  double v2_;
  std::unique_ptr<BackscatterModel> ground_;
};

}  // namespace

std::unique_ptr<BackscatterModel> make_water_cloud(ConfigTable& params, const ModelContext& ctx) {
  const PowerLaw a = get_power_law(params, "A");
  const PowerLaw b = get_power_law(params, "B");
  const double v1 = get_nonnegative(params, "V1");
  const double v2 = get_nonnegative(params, "V2");
  std::optional<ConfigTable> ground = params.subtable("ground");
  if (!ground) params.fail("ground", "missing required table (the ground model under the canopy)");
  ModelContext ground_ctx = ctx;
  std::unique_ptr<BackscatterModel> ground_model = make_backscatter_model(*ground, ground_ctx);
  params.finish();
  return std::make_unique<WaterCloud>(a, b, v1, v2, std::move(ground_model));
}

}  // namespace ris::detail
