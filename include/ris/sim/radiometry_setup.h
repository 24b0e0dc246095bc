// The radiometric set-up every mode shares before image formation, and the
// per-pixel switch corrections after it (MODEL.md section 3; the seed's
// equation 15 switches as ris/image/greytone_terms.h prescribes): the
// categories the scene uses and their names, the sigma0 LUT (with the
// reference category), the reference sigma0 resolved in the radar, the
// switched-off factors replaced by their reference values in the imaging
// parameters.
//
// Example:
//   ris::RadiometrySetup rs = ris::prepare_radiometry(scene, radar, derived, *sigma0, file);
//   ris::SlarImage img = ris::form_slar_image(geometry, rs.lut, rs.imaging, radar.source_file);
//   auto [range_fixed, area_fixed] = ris::apply_switch_corrections(img, rs.terms);
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/backscatter/sigma0_source.h"
#include "ris/image/greytone_terms.h"
#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_params.h"

namespace ris {

struct RadiometrySetup {
  Sigma0Lut lut;              // the scene's categories (constant when switched off)
  SlarImagingParams imaging;  // range bins, P_t, lambda, gain, beamwidth, pattern
  SwitchedRadarTerms terms;
  std::vector<std::uint16_t> categories;  // used by cells with data, sorted
  std::vector<std::string> category_names;
  std::string backscatter_description;
};

// radar: its reference sigma0 is resolved in place. backscatter_file names
// the sigma0 source in messages. Throws InputError for a scene without data
// or a category without backscatter.
RadiometrySetup prepare_radiometry(const Scene& scene, RadarParams& radar,
                                   const RadarDerived& derived, const Sigma0Source& sigma0,
                                   const std::string& backscatter_file);
// The same given the categories of the cells with data (sorted, unique; a
// streamed scene, ris/sim/slar_stream.h).
RadiometrySetup prepare_radiometry(const std::vector<std::uint16_t>& categories, RadarParams& radar,
                                   const RadarDerived& derived, const Sigma0Source& sigma0,
                                   const std::string& backscatter_file);

// SAR (mode sar): the constant azimuth window (L_a rho_a over the line
// spacing) and the range window (L_r rho_r over the bin) of the multilooked
// resolution cell (MODEL.md section 3); nothing for other modes.
void set_sar_windows(const RadarParams& radar, double line_spacing_m, SlarImagingParams& imaging);

// SAR thermal noise per range bin, NESZ over the multilooked resolution
// cell (ris/image/thermal_noise.h); empty without NESZ or for other modes.
std::vector<double> sar_noise_power_w(const RadarParams& radar, const SlarImagingParams& imaging,
                                      double altitude_m);

// The range and area switches, applied per pixel after image formation;
// returns whether each was applied.
std::pair<bool, bool> apply_switch_corrections(SlarImage& image, const SwitchedRadarTerms& terms);

}  // namespace ris
