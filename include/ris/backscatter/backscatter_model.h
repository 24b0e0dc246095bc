// One backscatter model with its parameters fixed: sigma0 against incidence
// for a band. Models form an open family (DESIGN.md principle 1): each lives
// in its own file under src/backscatter/models/ with its documentation
// (formula, source, validity range) at the top, and is registered by name in
// the one table of src/backscatter/model_registry.cpp.
//
// A model is built once per category from its TOML table (parse at the edge)
// and evaluated only while a Sigma0Lut is tabulated, never per sample.
//
// Example:
//   toml::table t = toml::parse(R"(name = "muhleman")");
//   ris::ConfigTable params(t, "lib.toml", "category[0].model");
//   ris::ModelContext ctx{"lib.toml", ".", false};
//   std::unique_ptr<ris::BackscatterModel> m = ris::make_backscatter_model(params, ctx);
//   double s0 = m->sigma0(ris::deg_to_rad(30.0), ris::RadarBand{8.6e9, ris::Polarisation::HH});
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ris/backscatter/polarisation.h"

namespace ris {

class ConfigTable;
class Sigma0Table;

// What a model factory needs besides its own keys.
struct ModelContext {
  std::string file;                  // the library or table path, for messages
  std::string base_dir;              // folder that relative file names resolve against
  bool allow_extrapolation = false;  // out-of-validity inputs warn instead of failing
  int category_id = -1;              // the library category being built, or -1
  // Tables already read, by resolved path (shared between the categories of
  // one library; shared ownership, so a model keeping a copy of its context
  // never holds a dangling pointer); may be null.
  std::shared_ptr<std::map<std::string, std::shared_ptr<const Sigma0Table>>> table_cache;
};

// Reports an input outside a model's validity range: an InputError naming the
// file and key, or (allow_extrapolation) a warning printed once per message.
void report_out_of_validity(const ModelContext& ctx, const std::string& key_path,
                            const std::string& what);

class BackscatterModel {
 public:
  virtual ~BackscatterModel() = default;

  // sigma0 (linear, >= 0) at incidence_rad in [0, pi/2] for this band.
  // check_band(band) has been called first.
  virtual double sigma0(double incidence_rad, const RadarBand& band) const = 0;
  // sigma0 at many angles, out[i] at incidence_rad[i] (a Sigma0Lut build):
  // the same values as sigma0(), but a model may compute what depends only
  // on the band (a soil's permittivity, a power law in frequency) once for
  // the whole curve. Default: sigma0() per angle. Added for the LUT build;
  // backward compatible.
  virtual void sigma0_curve(const double* incidence_rad, std::size_t n, const RadarBand& band,
                            double* out) const;

  // Refuses (or warns about) a band outside the model's validity range, via
  // report_out_of_validity. Band-independent parameters are checked when the
  // model is built. Default: valid at every band.
  virtual void check_band(const RadarBand& band) const;

  // One line: the model and its parameters, for metadata and `ris sigma0`.
  virtual std::string describe() const = 0;
};

// Builds the model named by the table's "name" key from the table's other
// keys. An unknown name, a missing or extra key, or a value outside the
// model's validity range is an InputError naming ctx.file and the key.
std::unique_ptr<BackscatterModel> make_backscatter_model(ConfigTable& params,
                                                         const ModelContext& ctx);

// Registered model names with a one-line summary each, in table order.
struct ModelInfo {
  std::string name;
  std::string summary;
};
std::vector<ModelInfo> backscatter_model_names();

}  // namespace ris
