// The one table of backscatter models by name (DESIGN.md principle 1). To add
// a model: write src/backscatter/models/<name>.cpp with its documentation at
// the top and a factory, declare the factory in models/models.h, and add a
// row here (docs/backscatter.md, "Adding a model").
#include <spdlog/spdlog.h>

#include <array>
#include <mutex>
#include <set>

#include "backscatter/models/models.h"
#include "ris/util/error.h"

namespace ris {

namespace {

struct Entry {
  const char* name;
  detail::ModelFactory make;
  const char* summary;
};

constexpr std::array kModels = {
    Entry{"table", detail::make_table_model, "measured sigma0 (dB) against angle from a CSV table"},
    Entry{"muhleman", detail::make_muhleman, "0.0118 cos t / (sin t + 0.111 cos t)^3"},
    Entry{"constant_gamma", detail::make_constant_gamma, "gamma cos t (Clapp)"},
    Entry{"lambert", detail::make_lambert, "gamma cos^2 t"},
    Entry{"oh1992", detail::make_oh1992, "bare soil, Oh, Sarabandi & Ulaby 1992"},
    Entry{"oh2004", detail::make_oh2004, "bare soil from moisture and ks, Oh 2004"},
    Entry{"ulaby_dobson", detail::make_ulaby_dobson,
          "P1 + P2 exp(-P3 t) + P4 cos(P5 t + P6) dB, Ulaby & Dobson 1989"},
    Entry{"dubois1995", detail::make_dubois1995, "bare soil HH/VV, Dubois, van Zyl & Engman 1995"},
    Entry{"spm", detail::make_spm, "first-order small perturbation, Gaussian/exponential"},
    Entry{"i2em", detail::make_i2em, "improved integral equation model, Fung et al. 2002"},
    Entry{"morchin", detail::make_morchin,
          "land clutter: A sin(psi)/lambda + specular term, Morchin 1990 (0.3-8 GHz)"},
    Entry{"water_cloud", detail::make_water_cloud,
          "vegetation over a ground model, Attema & Ulaby 1978"},
};

// Decorates a model with a frequency validity range given in the library
// ("valid_frequency = [\"1 GHz\", \"18 GHz\"]"), for fitted parameters.
class FrequencyLimited final : public BackscatterModel {
 public:
  FrequencyLimited(std::unique_ptr<BackscatterModel> inner, double lo_hz, double hi_hz,
                   ModelContext ctx, std::string key_path)
      : inner_(std::move(inner)),
        lo_hz_(lo_hz),
        hi_hz_(hi_hz),
        ctx_(std::move(ctx)),
        key_path_(std::move(key_path)) {}
  double sigma0(double incidence_rad, const RadarBand& band) const override {
    return inner_->sigma0(incidence_rad, band);
  }
  void sigma0_curve(const double* incidence_rad, std::size_t n, const RadarBand& band,
                    double* out) const override {
    inner_->sigma0_curve(incidence_rad, n, band, out);
  }
  void check_band(const RadarBand& band) const override {
    if (band.frequency_hz < lo_hz_ || band.frequency_hz > hi_hz_) {
      report_out_of_validity(
          ctx_, key_path_,
          fmt::format("{:g} GHz is outside the stated validity range {:g}..{:g} GHz",
                      band.frequency_hz / 1e9, lo_hz_ / 1e9, hi_hz_ / 1e9));
    }
    inner_->check_band(band);
  }
  std::string describe() const override { return inner_->describe(); }

 private:
  std::unique_ptr<BackscatterModel> inner_;
  double lo_hz_;
  double hi_hz_;
  ModelContext ctx_;
  std::string key_path_;
};

}  // namespace

void BackscatterModel::check_band(const RadarBand&) const {}

void BackscatterModel::sigma0_curve(const double* incidence_rad, std::size_t n,
                                    const RadarBand& band, double* out) const {
  for (std::size_t i = 0; i < n; ++i) out[i] = sigma0(incidence_rad[i], band);
}

void report_out_of_validity(const ModelContext& ctx, const std::string& key_path,
                            const std::string& what) {
  if (!ctx.allow_extrapolation) {
    throw InputError(ctx.file, key_path,
                     what + " (set allow_extrapolation = true to use it anyway)");
  }
  // Warn once per message: a LUT build evaluates a model thousands of times.
  static std::mutex mutex;
  static std::set<std::string> said;
  const std::string message = (ctx.file.empty() ? "" : ctx.file + ": ") + "'" + key_path +
                              "': " + what + " (extrapolating: allow_extrapolation = true)";
  std::lock_guard<std::mutex> lock(mutex);
  if (said.insert(message).second) spdlog::warn("{}", message);
}

std::unique_ptr<BackscatterModel> make_backscatter_model(ConfigTable& params,
                                                         const ModelContext& ctx) {
  const std::string name = params.get_string("name");
  const Entry* entry = nullptr;
  for (const Entry& e : kModels) {
    if (name == e.name) entry = &e;
  }
  if (entry == nullptr) {
    std::string known;
    for (const Entry& e : kModels) known += (known.empty() ? "" : ", ") + std::string(e.name);
    params.fail("name", fmt::format("unknown backscatter model \"{}\" (known: {})", name, known));
  }
  std::optional<std::vector<double>> range;
  if (params.has("valid_frequency")) {
    range = params.get_quantity_array("valid_frequency", Quantity::frequency);
    if (range->size() != 2 || !((*range)[0] > 0.0) || !((*range)[1] > (*range)[0])) {
      params.fail("valid_frequency",
                  "expected [low, high] with 0 < low < high, e.g. [\"1 GHz\", \"18 GHz\"]");
    }
  }
  std::unique_ptr<BackscatterModel> model = entry->make(params, ctx);
  if (range) {
    model = std::make_unique<FrequencyLimited>(std::move(model), (*range)[0], (*range)[1], ctx,
                                               params.key_path("valid_frequency"));
  }
  return model;
}

std::vector<ModelInfo> backscatter_model_names() {
  std::vector<ModelInfo> out;
  for (const Entry& e : kModels) out.push_back({e.name, e.summary});
  return out;
}

}  // namespace ris
