// Real terrain end to end: a geographic DEM simulated directly and through a
// different UTM reprojection, with a track in latitude/longitude.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "build_paths.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/scene_io.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_simulation.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

// Right-looking, flying north about 10 km west of the San Andreas DEM.
RadarParams west_of_sanand() {
  toml::table doc = toml::parse(R"(name = "t"
mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.2 us"
near_range = "10000 m"
far_range = "14000 m"
azimuth_beamwidth = "0.2 deg"
azimuth_line_spacing = "60 m"
[track]
altitude = "3000 m"
look_side = "right"
start_latlon = [34.13, -118.55]
end_latlon = [34.22, -118.55]
)");
  return radar_from_toml(doc, "radar.toml");
}

TEST(TerrainSimulate, GeographicDemAndAFinerUtmReprojectionGiveTheSameImage) {
  const std::string dem = std::string(ris::test::test_data_dir()) + "/dem/SanAnd_dem.tif";
  // Directly: read_scene imports the geographic DEM on the fly (30 m cells).
  const Scene direct = read_scene(dem);
  // Through a reprojection on another grid: 15 m cells.
  DemImportOptions opt;
  opt.cell_size_m = 15.0;
  const Scene fine = import_dem(dem, opt).scene;
  ASSERT_DOUBLE_EQ(direct.dx_m, 30.0);

  const RadarParams radar = west_of_sanand();
  // A bare DEM's cells are all kDefaultCategory (ris/scene/scene.h).
  const test::CosineSigma0Source sigma0({kDefaultCategory});
  const SlarSimulation a = simulate_slar(direct, radar, sigma0);
  const SlarSimulation b = simulate_slar(fine, radar, sigma0);
  // The same track (latitude/longitude into the same UTM zone) and image grid.
  EXPECT_NEAR(a.track.start_x_m, b.track.start_x_m, 1e-6);
  ASSERT_EQ(a.image.lines, b.image.lines);
  ASSERT_EQ(a.image.bins, b.image.bins);

  // Pixels imaged in both, away from the DEM's edges (first and last lines
  // and bins with data): power agrees within the resampling error of the
  // terrain (heights bilinear at 30 or 15 m, slopes from them).
  std::vector<double> rel;
  double sum_a = 0, sum_b = 0;
  for (int l = 10; l < a.image.lines - 10; ++l) {
    for (int k = 0; k < a.image.bins; ++k) {
      const std::size_t i = a.image.index(l, k);
      if (a.image.mask[i] || b.image.mask[i]) continue;
      const double pa = a.image.mean_power_w[i], pb = b.image.mean_power_w[i];
      if (!(pa > 0.0 && pb > 0.0)) continue;
      rel.push_back(std::abs(pa - pb) / pa);
      sum_a += pa, sum_b += pb;
    }
  }
  ASSERT_GT(rel.size(), 1000u);
  std::sort(rel.begin(), rel.end());
  EXPECT_LT(rel[rel.size() / 2], 0.05) << "median relative difference " << rel[rel.size() / 2];
  EXPECT_NEAR(sum_b / sum_a, 1.0, 0.02) << "total power";
}

}  // namespace
}  // namespace ris
