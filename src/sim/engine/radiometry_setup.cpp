#include "ris/sim/radiometry_setup.h"

#include "ris/image/thermal_noise.h"
#include "ris/sensor/elevation_gain.h"
#include "ris/util/thread_ranges.h"

namespace ris {

namespace {

// Marks mark[c] for the category c of each cell in [i0, i1) with data, and
// mark[65536] for cells without (a select, not a branch).
void mark_categories(const std::uint8_t* valid, const std::uint16_t* category, std::size_t i0,
                     std::size_t i1, std::uint8_t* mark) {
  for (std::size_t i = i0; i < i1; ++i) mark[valid[i] ? std::size_t{category[i]} : 65536u] = 1;
}

// Categories of the cells with data, sorted. Each thread marks a range of
// cells in its own table (ris/util/thread_ranges.h; the scan was a serial
// step of every run), the tables merged after.
std::vector<std::uint16_t> used_categories(const Scene& scene) {
  std::vector<std::uint8_t> seen(65537, 0);
  for_thread_ranges(scene.size(), [&](std::size_t i0, std::size_t i1) {
    std::vector<std::uint8_t> local(65537, 0);
    mark_categories(scene.valid.data(), scene.category.data(), i0, i1, local.data());
#pragma omp critical(ris_used_categories)
    for (std::size_t c = 0; c < 65536; ++c) seen[c] |= local[c];
  });
  std::vector<std::uint16_t> out;
  for (std::size_t c = 0; c < 65536; ++c)
    if (seen[c]) out.push_back(static_cast<std::uint16_t>(c));
  return out;
}

}  // namespace

RadiometrySetup prepare_radiometry(const Scene& scene, RadarParams& radar,
                                   const RadarDerived& derived, const Sigma0Source& sigma0,
                                   const std::string& backscatter_file) {
  return prepare_radiometry(used_categories(scene), radar, derived, sigma0, backscatter_file);
}

RadiometrySetup prepare_radiometry(const std::vector<std::uint16_t>& categories, RadarParams& radar,
                                   const RadarDerived& derived, const Sigma0Source& sigma0,
                                   const std::string& backscatter_file) {
  RadiometrySetup rs;
  // sigma0 for every category the scene uses (and the reference's).
  rs.categories = categories;
  for (std::uint16_t c : rs.categories) rs.category_names.push_back(sigma0.category_name(c));
  std::vector<std::uint16_t> lut_categories = rs.categories;
  if (radar.reference.sigma0_category) lut_categories.push_back(*radar.reference.sigma0_category);
  const RadarBand band{radar.frequency_hz, radar.polarisation};
  rs.lut = Sigma0Lut::build(sigma0, band, lut_categories, backscatter_file);
  resolve_reference_sigma0(radar, rs.lut);
  rs.backscatter_description = sigma0.description();

  // The switched-off factors at their reference values.
  rs.terms = switched_terms(radar);
  if (rs.terms.constant_sigma0) {
    rs.lut = Sigma0Lut::build(ConstantSigma0(*rs.terms.constant_sigma0), band, rs.categories,
                              backscatter_file);
  }
  SlarImagingParams& imaging = rs.imaging;
  imaging.range.near_m = derived.near_slant_range_m;
  imaging.range.bin_m = derived.range_bin_m;
  imaging.range.count = derived.range_bins;
  imaging.transmit_power_w = rs.terms.transmit_power_w;
  imaging.wavelength_m = rs.terms.wavelength_m;
  imaging.peak_gain = rs.terms.peak_gain;
  imaging.azimuth_beamwidth_rad = radar.azimuth_beamwidth_rad;
  if (!rs.terms.uniform_elevation) {
    const ElevationGain gain(radar.elevation_pattern);
    imaging.elevation_gain = [gain](double beta) { return gain(beta); };
  }
  return rs;
}

std::pair<bool, bool> apply_switch_corrections(SlarImage& img, const SwitchedRadarTerms& terms) {
  const bool range = terms.reference_range_m.has_value();
  const bool area = terms.reference_area_m2.has_value();
  if (range || area) {
#pragma omp parallel for schedule(static)
    for (int line = 0; line < img.lines; ++line) {
      for (int b = 0; b < img.bins; ++b) {
        const std::size_t i = img.index(line, b);
        const double f =
            range_correction(terms, img.range.centre_m(b)) * area_correction(terms, img.area_m2[i]);
        img.mean_power_w[i] = static_cast<float>(img.mean_power_w[i] * f);
      }
    }
  }
  return {range, area};
}

void set_sar_windows(const RadarParams& radar, double line_spacing_m, SlarImagingParams& imaging) {
  if (radar.mode != RadarMode::sar) return;
  imaging.azimuth_window_lines = radar.sar.azimuth_resolution_looks_m() / line_spacing_m;
  imaging.range_window_bins = radar.sar.range_resolution_looks_m() / imaging.range.bin_m;
}

std::vector<double> sar_noise_power_w(const RadarParams& radar, const SlarImagingParams& imaging,
                                      double altitude_m) {
  if (radar.mode != RadarMode::sar || !radar.sar.nesz) return {};
  return thermal_noise_power_w(imaging, *radar.sar.nesz, altitude_m,
                               radar.sar.azimuth_resolution_looks_m(),
                               radar.sar.range_resolution_looks_m());
}

}  // namespace ris
