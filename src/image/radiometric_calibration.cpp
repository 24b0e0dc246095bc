#include "ris/image/radiometric_calibration.h"

#include <cmath>
#include <cstddef>
#include <limits>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

std::string_view backscatter_name(Backscatter b) {
  switch (b) {
    case Backscatter::sigma0:
      return "sigma0";
    case Backscatter::beta0:
      return "beta0";
    case Backscatter::gamma0:
      return "gamma0";
  }
  return "sigma0";
}

SlantCalibration calibration_from_angles(const SlarImagingParams& p, double reference_height_m,
                                         std::span<const double> look_rad,
                                         std::span<const double> incidence_rad,
                                         std::span<const double> azimuth_cell_m) {
  const auto n = static_cast<std::size_t>(p.range.count);
  RIS_CHECK(n > 0 && look_rad.size() == n && incidence_rad.size() == n &&
            azimuth_cell_m.size() == n);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  SlantCalibration cal;
  cal.reference_height_m = reference_height_m;
  cal.unit_power_w.assign(n, nan);
  cal.sin_incidence.assign(n, nan);
  cal.cos_incidence.assign(n, nan);
  // P_t lambda^2 / (4 pi)^3, as the image's elements take it.
  const double k_radar =
      p.transmit_power_w * p.wavelength_m * p.wavelength_m / std::pow(4.0 * kPi, 3.0);
  // The range cell as the image integrates it: a range window of
  // range_window_bins bins, else one bin.
  const double range_cell_m =
      p.range_window_bins > 0.0 ? p.range_window_bins * p.range.bin_m : p.range.bin_m;
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(look_rad[i]) || !std::isfinite(incidence_rad[i])) continue;
    const double r = p.range.centre_m(static_cast<int>(i));
    const double sin_t = std::sin(incidence_rad[i]), cos_t = std::cos(incidence_rad[i]);
    if (!(sin_t > 0.0)) continue;  // straight down: no ground area to refer to
    const double g = (p.elevation_gain ? p.elevation_gain(look_rad[i]) : 1.0) * p.peak_gain;
    const double area_m2 = azimuth_cell_m[i] * range_cell_m / sin_t;
    const double r2 = r * r;
    const double unit = k_radar * g * g * area_m2 / (r2 * r2);
    cal.sin_incidence[i] = sin_t;
    cal.cos_incidence[i] = cos_t;
    if (unit > 0.0) cal.unit_power_w[i] = unit;  // a null of the pattern: no reference
  }
  return cal;
}

SlantCalibration slant_calibration(const SlarImagingParams& p, double line_spacing_m,
                                   double altitude_m, double reference_height_m) {
  RIS_CHECK(p.range.count > 0 && line_spacing_m > 0.0);
  const auto n = static_cast<std::size_t>(p.range.count);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> look(n, nan), azimuth_cell(n, nan);
  const double height_m = altitude_m - reference_height_m;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = p.range.centre_m(static_cast<int>(i));
    // The azimuth cell as the image integrates it: a window of
    // azimuth_window_lines lines, else R phi at the bin centre.
    azimuth_cell[i] = p.azimuth_window_lines > 0.0 ? p.azimuth_window_lines * line_spacing_m
                                                   : slar_footprint_m(r, p.azimuth_beamwidth_rad);
    // The flat Earth: the look angle from nadir is the incidence.
    if (height_m > 0.0 && r > height_m) look[i] = std::acos(height_m / r);
  }
  return calibration_from_angles(p, reference_height_m, look, look, azimuth_cell);
}

double calibration_factor(const SlantCalibration& cal, Backscatter b, int bin) {
  const auto i = static_cast<std::size_t>(bin);
  RIS_CHECK(i < cal.unit_power_w.size());
  const double to_sigma0 = 1.0 / cal.unit_power_w[i];
  switch (b) {
    case Backscatter::sigma0:
      return to_sigma0;
    case Backscatter::beta0:
      return to_sigma0 / cal.sin_incidence[i];
    case Backscatter::gamma0:
      return to_sigma0 / cal.cos_incidence[i];
  }
  return to_sigma0;
}

void calibrate_slant_image(std::span<const float> power_w, int bins, const SlantCalibration& cal,
                           Backscatter b, bool decibels, std::span<float> out) {
  RIS_CHECK(bins > 0 && static_cast<std::size_t>(bins) == cal.unit_power_w.size());
  RIS_CHECK(power_w.size() == out.size() && power_w.size() % static_cast<std::size_t>(bins) == 0);
  const auto nb = static_cast<std::size_t>(bins);
  std::vector<double> factor(nb);
  for (int k = 0; k < bins; ++k)
    factor[static_cast<std::size_t>(k)] = calibration_factor(cal, b, k);
  const std::ptrdiff_t lines = static_cast<std::ptrdiff_t>(power_w.size() / nb);
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t line = 0; line < lines; ++line) {
    const std::size_t row = static_cast<std::size_t>(line) * nb;
    for (std::size_t k = 0; k < nb; ++k) {
      const double v = double(power_w[row + k]) * factor[k];  // NaN stays NaN
      if (!decibels) {
        out[row + k] = static_cast<float>(v);
      } else {
        out[row + k] = v > 0.0 ? static_cast<float>(10.0 * std::log10(v)) : kNaN;
      }
    }
  }
}

}  // namespace ris
