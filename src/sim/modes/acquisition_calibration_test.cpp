// An acquisition run's calibrated image (sim/modes/acquisition_calibration.h):
// level ground on the ellipsoid (and on the flat Earth) reads sigma0(theta)
// of its category within 0.01 dB, with theta the incidence the run itself
// reports per pixel (its local-incidence layer: on level ground the
// incidence to the ellipsoid's normal), gamma0 the cosine source's constant.
//
// Error budget: the pixel sums elements of a 3-points-a-bin profile (range
// and angle across the bin against the centre's, < 1e-3 dB as on a scene);
// one line (the window's middle) stands for the window's calibration: on
// the 6-second airborne line the sensor's height and the ground spacing
// change by parts in 10^5, 4e-4 dB at most; the local-incidence layer is the
// incidence of the ground nearest the bin centre (float32 degrees).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "acquisition_paths.h"
#include "acquisition_test_dems.h"
#include "ris/image/radiometric_calibration.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/acquisition_simulation.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

double worst_db_error(const AcquisitionSimulation& a, Backscatter b, int& checked) {
  const SlarImage& img = a.sim.image;
  std::vector<float> v(img.mean_power_w.size());
  calibrate_slant_image(img.mean_power_w, img.bins, a.sim.calibration, b, true, v);
  const double gamma = test::CosineSigma0Source::gamma(0);
  double worst = 0.0;
  checked = 0;
  // Away from the window's first and last lines (the footprint leaves the
  // grid) and from the swath's edges.
  for (int line = img.lines / 4; line < img.lines - img.lines / 4; ++line) {
    for (int bin = 10; bin < img.bins - 10; ++bin) {
      const std::size_t i = img.index(line, bin);
      const double theta = deg_to_rad(a.local_incidence_deg[i]);
      if (img.mask[i] != 0 || !std::isfinite(theta)) continue;
      const double s0 = gamma * std::cos(theta);
      const double expected = b == Backscatter::sigma0  ? s0
                              : b == Backscatter::beta0 ? s0 / std::sin(theta)
                                                        : gamma;
      worst = std::max(worst, std::abs(v[i] - 10.0 * std::log10(expected)));
      ++checked;
    }
  }
  return worst;
}

TEST(AcquisitionCalibration, LevelGroundReadsItsSigma0OnTheEllipsoidAndTheFlatEarth) {
  const Acquisition acq = test::small_airborne();
  const EllipsoidalDem dem = test::dem_for(acq, 0.0, 1.0);  // level at 230 m
  const RadarParams radar = load_radar(std::string(test::data_dir()) + "/radars/seed-fig4-5.toml");
  for (const EarthModel earth : {EarthModel::ellipsoid, EarthModel::flat}) {
    AcquisitionSimOptions o;
    o.earth = earth;
    o.category = 0;
    const AcquisitionSimulation a =
        simulate_acquisition(acq, dem, radar, test::CosineSigma0Source(), o);
    ASSERT_FALSE(a.sim.calibration.empty());
    EXPECT_NEAR(a.sim.calibration.reference_height_m, 230.0, 1e-3);
    for (const Backscatter b : {Backscatter::sigma0, Backscatter::beta0, Backscatter::gamma0}) {
      int checked = 0;
      const double worst = worst_db_error(a, b, checked);
      std::printf("%s %s: worst %.5f dB over %d pixels\n",
                  earth == EarthModel::flat ? "flat" : "ellipsoid",
                  std::string(backscatter_name(b)).c_str(), worst, checked);
      EXPECT_GT(checked, 1000);
      EXPECT_LT(worst, 0.01) << backscatter_name(b);
    }
  }
}

}  // namespace
}  // namespace ris
