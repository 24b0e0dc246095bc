// The factories of every registered backscatter model (private to src/).
// Each is defined in its own file, src/backscatter/models/<name>.cpp, with the
// model's documentation at the top; model_registry.cpp lists them by name.
#pragma once

#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "backscatter/models/model_util.h"
#include "ris/backscatter/backscatter_model.h"
#include "ris/io/config_table.h"

namespace ris::detail {

using ModelFactory = std::unique_ptr<BackscatterModel> (*)(ConfigTable&, const ModelContext&);

std::unique_ptr<BackscatterModel> make_table_model(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_muhleman(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_constant_gamma(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_lambert(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_oh1992(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_water_cloud(ConfigTable&, const ModelContext&);

}  // namespace ris::detail
