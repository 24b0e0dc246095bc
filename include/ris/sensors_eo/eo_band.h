// The optical and thermal bands a sensor may image, by name. Optical bands
// are Sentinel-2 MSI's B2, B3, B4, B8 (ESA, Sentinel-2 User Handbook, 2015,
// table 2: centre/width), with their top-of-atmosphere mean solar irradiance
// from the Sentinel-2A L1C metadata (SOLAR_IRRADIANCE, from the Thuillier et
// al. 2003 solar spectrum). Thermal bands are the atmospheric windows
// 3-5 um (MWIR) and 8-12 um (LWIR). docs/sensors.md, "Bands".
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "ris/sensors_eo/planck_band.h"

namespace ris {

enum class EoBand { blue, green, red, nir, mwir, lwir };

struct EoBandInfo {
  EoBand band;
  std::string_view name;  // as written in a sensor file
  SpectralBand range;
  bool thermal;
  double solar_irradiance_w_m2_um;  // TOA at 1 au; 0 for thermal bands
};

const EoBandInfo& eo_band_info(EoBand b);

// Parses a band name; throws InputError(file, key, ...) listing the known
// names for an unknown one.
EoBand parse_eo_band(std::string_view name, const std::string& file, const std::string& key);

std::vector<EoBand> all_eo_bands();

}  // namespace ris
