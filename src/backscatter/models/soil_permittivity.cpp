#include "backscatter/models/soil_permittivity.h"

#include "backscatter/models/model_util.h"

namespace ris::detail {

std::string SoilPermittivity::describe() const {
  return fmt::format("{:g} - {:g}j", fixed_.real(), -fixed_.imag());
}

SoilPermittivity read_soil_permittivity(ConfigTable& params, const std::string& key,
                                        const ModelContext&) {
  return SoilPermittivity(parse_permittivity(params, key, params.get_string(key)));
}

}  // namespace ris::detail
