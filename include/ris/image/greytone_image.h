// The image chain after the mean power, in one call: N per range bin, fading
// (when its switch is on), the greytone map (explicit or auto reference) and
// the greytones (MODEL.md section 3; the seed's program SLAR Greytone).
//
// Because it starts from the mean power, it can be re-run with another seed,
// film or reference without recomputing geometry, as the seed re-ran its
// fourth program on one geometry tape (`ris greytone`).
//
// Example:
//   ris::GreytoneImage g = ris::make_greytone_image(radar, img.mean_power_w, img.lines,
//                                                   img.bins, img.range.near_m,
//                                                   img.range.bin_m, seed, no_data);
//   ris::write_png_gray(out / "slant.png", g.greytone.data(), img.bins, img.lines);
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ris/image/greytone.h"
#include "ris/sensor/radar_params.h"

namespace ris {

struct GreytoneImage {
  std::vector<double> looks_per_bin;    // N at each bin's centre range
  std::vector<float> speckled_power_w;  // mean power x fading factor (= mean if fading off)
  std::vector<std::uint8_t> greytone;   // lines x bins, equation 15, rounded and clamped
  GreytoneMap map;                      // P_ref, G_ref and the film terms used
};

// N at each range bin's centre, near_range_m + (k + 0.5) bin_m
// (independent_samples, ris/sensor/radar_derived.h).
std::vector<double> looks_per_bin(const RadarParams& radar, int bins, double near_range_m,
                                  double bin_m);

// mean_power_w: lines x bins (row = azimuth line, column = range bin, near
// first), NaN or no_data non-zero for no data; bin k is centred at slant range
// near_range_m + (k + 0.5) bin_m. No-data pixels get greytone 0.
GreytoneImage make_greytone_image(const RadarParams& radar, std::span<const float> mean_power_w,
                                  int lines, int bins, double near_range_m, double bin_m,
                                  std::uint64_t seed, std::span<const std::uint8_t> no_data = {});

// The same with N given per range bin (looks_per_bin.size() == bins, each
// finite and > 0) instead of from the radar's geometry: a mean-power array
// whose ranges are not known (the Python API's ris.greytone(looks=...)).
GreytoneImage make_greytone_image(const RadarParams& radar, std::span<const float> mean_power_w,
                                  int lines, int bins, std::vector<double> looks_per_bin,
                                  std::uint64_t seed, std::span<const std::uint8_t> no_data = {});

}  // namespace ris
