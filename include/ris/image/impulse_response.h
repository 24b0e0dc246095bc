// Impulse-response (IRF) quality of a point target in a simulated image: the
// 3 dB resolution in range and azimuth, the peak sidelobe ratio (PSLR) and
// the integrated sidelobe ratio (ISLR), as SAR calibration measures them
// (e.g. Curlander and McDonough 1991, section 3.2; CEOS SAR calibration).
//
// Around the brightest pixel within `search_px` of the given position, one
// cut in range (along the peak's row) and one in azimuth (along its column),
// each +- half_length_px pixels, are oversampled 32 times:
//   sinc   Whittaker-Shannon interpolation of the intensity, exact for a
//          coherent image sampled at least twice per resolution (the
//          intensity of a band-limited complex image has twice its
//          bandwidth); use it for coherent SAR;
//   linear for box-shaped (incoherent) responses.
// On the oversampled cut: the 3 dB width is the distance between the
// half-peak crossings either side of the peak; the main lobe extends to the
// first minimum on each side; PSLR = the highest point outside the main lobe
// over the peak; ISLR = the energy outside the main lobe over the energy
// inside it (within the cut), both in dB. The worse of the two cuts gives
// the summary PSLR and ISLR.
//
// Example:
//   ris::IrfMeasurement m = ris::measure_irf(power, lines, bins, ds, dr, line, bin, 3, 32,
//                                            ris::IrfInterpolation::sinc);
//   fmt::print("{:.2f} m x {:.2f} m, PSLR {:.1f} dB\n", m.range_width_m, m.azimuth_width_m,
//              m.pslr_db);
#pragma once

#include <span>
#include <string>

#include <nlohmann/json.hpp>

namespace ris {

enum class IrfInterpolation { sinc, linear };

struct IrfCut {
  double width_m = 0.0;  // 3 dB width
  double pslr_db = 0.0;
  double islr_db = 0.0;
};

struct IrfMeasurement {
  int peak_line = 0, peak_bin = 0;
  double peak_power_w = 0.0;
  IrfCut range, azimuth;
  double pslr_db = 0.0;  // the higher (worse) of the two cuts
  double islr_db = 0.0;
  double range_width_m() const { return range.width_m; }
  double azimuth_width_m() const { return azimuth.width_m; }
};

// power: lines x bins (row = azimuth line); line_spacing_m and bin_m the
// pixel sizes. Cuts are clipped at the image edge.
IrfMeasurement measure_irf(std::span<const float> power, int lines, int bins, double line_spacing_m,
                           double bin_m, int line, int bin, int search_px, int half_length_px,
                           IrfInterpolation interpolation);

// One cut (samples at unit spacing, peak near the middle); widths in samples.
IrfCut measure_irf_cut(std::span<const double> cut, double spacing_m,
                       IrfInterpolation interpolation);

nlohmann::json irf_to_json(const IrfMeasurement& m);

}  // namespace ris
