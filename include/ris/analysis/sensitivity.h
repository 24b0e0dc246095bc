// Sensitivity analysis (docs/quality.md, "ris sensitivity"; the seed's
// recommendation 3.2.2): how much does the image change when a radar or film
// parameter moves, or when the ground-truth database holds less detail? The
// least detail that keeps the image within a tolerance of the full-detail one
// is the seed's "minimum level of information" an application needs.
//
// Ground-truth detail is reduced on the scene's own grid, so every image
// shares the reference's pixels:
//   cell_factor k      the scene averaged over k x k blocks (elevation: mean of
//                      the cells with data; category: the most common) and put
//                      back on the original cells: what a database k times
//                      coarser knows
//   elevation_step s   elevations rounded to multiples of s metres
//   mislabel f         a fraction f of the cells with data given another of the
//                      scene's categories (a seeded hash per cell, so the same f
//                      mislabels the same cells, and a larger f a superset)
// Radar and film: frequency (Hz) and polarisation (radar_at_band), film
// gamma and density range, the fading seed.
//
// Each run is compared with the reference (every parameter at its given
// value, full detail) on the mean power before fading, over pixels holding
// power in both: the RMS and mean of the dB difference, and the Pearson
// correlation of dB values; and on the speckled image: its ENL.
//
// Example:
//   ris::SensitivityStudy s{scene, radar, sigma0};
//   std::vector<ris::SensitivityRow> rows = ris::run_sensitivity(s, {{"cell_factor", {1, 2, 4}}});
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"

namespace ris {

// One parameter and the values it takes (units: Hz, metres, fractions;
// polarisation as the value of the Polarisation enum).
struct SensitivityAxis {
  std::string key;
  std::vector<double> values;
};

// Keys: cell_factor, elevation_step, mislabel, frequency, polarisation,
// film_gamma, film_density_range, seed.
bool is_sensitivity_key(const std::string& key);
const std::vector<std::string>& sensitivity_keys();

struct SensitivityStudy {
  std::shared_ptr<const Scene> scene;
  RadarParams radar;
  std::shared_ptr<const Sigma0Source> sigma0;
  std::string backscatter_path;
  std::uint64_t seed = 1;
  std::uint64_t mislabel_seed = 1;
};

struct SensitivityRow {
  std::string key;
  double value = 0.0;
  std::int64_t pixels = 0;  // compared with the reference
  double rms_db = 0.0;      // RMS of (run - reference) dB, mean power
  double bias_db = 0.0;     // mean of it
  double pearson = 0.0;     // of the dB values
  double enl = 0.0;         // of the speckled image (automatic regions)
};

// Every axis varied on its own about the reference; `row` is called as each
// run finishes (for streaming the results). InputError for a bad key or value.
std::vector<SensitivityRow> run_sensitivity(
    const SensitivityStudy& study, const std::vector<SensitivityAxis>& axes,
    const std::function<void(const SensitivityRow&)>& row = {});

// The detail reductions, exposed for tests.
Scene coarsened_scene(const Scene& s, int factor);
Scene quantised_scene(const Scene& s, double step_m);
Scene mislabelled_scene(const Scene& s, double fraction, std::uint64_t seed);

}  // namespace ris
