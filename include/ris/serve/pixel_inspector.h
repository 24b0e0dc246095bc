// The page's pixel inspector: what one pixel of a view holds.
//
// On the slant image (x: range bin, y: azimuth line): slant range, the
// incidence over a flat datum, N, mean and speckled power, greytone and the
// pixel's flags, and "calibrated": the pixel's sigma0, beta0 and gamma0 (dB,
// of the mean and of the speckled power) as `ris simulate --calibrated`
// writes them (ris/image/radiometric_calibration.h), or {"not_calibrated":
// "not calibrated: <why>"} (a PPI run; film.terms.range or .area false). On
// the ground-range image (x: ground pixel): its ground
// range, greytone and flags, and the slant pixel at its range. On the scene or geocoded grid (x:
// column, y: row): the cell's elevation, category, flags, local incidence and sigma0 there, its
// slant range and incidence from the track, and the slant pixel it maps to (geocode_pixel) with
// that pixel's values.
//
// Example:
//   nlohmann::json j = ris::inspect_pixel(result, *sigma0, "scene", 120, 350);
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "ris/backscatter/sigma0_source.h"
#include "ris/sim/run.h"

namespace ris {

// Throws InputError (source "request") for an unknown view or a pixel
// outside it. SLAR and SAR runs; a PPI run reports its scope pixel only.
nlohmann::json inspect_pixel(const RunResult& run, const Sigma0Source& sigma0,
                             const std::string& view, int x, int y);

}  // namespace ris
