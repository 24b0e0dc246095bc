#include "ris/sensors_eo/eo_band.h"

#include <array>

#include "ris/util/error.h"

namespace ris {
namespace {

// Sentinel-2A: B2 492.4 nm / 66 nm, B3 559.8 / 36, B4 664.6 / 31, B8 832.8 / 106.
const std::array<EoBandInfo, 6> kBands{{
    {EoBand::blue, "blue", {459.4e-9, 525.4e-9}, false, 1959.72},
    {EoBand::green, "green", {541.8e-9, 577.8e-9}, false, 1823.24},
    {EoBand::red, "red", {649.1e-9, 680.1e-9}, false, 1512.06},
    {EoBand::nir, "nir", {779.8e-9, 885.8e-9}, false, 1036.39},
    {EoBand::mwir, "mwir", {3e-6, 5e-6}, true, 0.0},
    {EoBand::lwir, "lwir", {8e-6, 12e-6}, true, 0.0},
}};

}  // namespace

const EoBandInfo& eo_band_info(EoBand b) {
  return kBands[static_cast<std::size_t>(b)];
}

EoBand parse_eo_band(std::string_view name, const std::string& file, const std::string& key) {
  std::string known;
  for (const EoBandInfo& i : kBands) {
    if (i.name == name) return i.band;
    known += (known.empty() ? "" : ", ") + std::string(i.name);
  }
  throw InputError(file, key, "unknown band '" + std::string(name) + "'; expected one of " + known);
}

std::vector<EoBand> all_eo_bands() {
  std::vector<EoBand> out;
  for (const EoBandInfo& i : kBands) out.push_back(i.band);
  return out;
}

}  // namespace ris
