// `ris simulate --acquisition P --dem D --stream` (ris/sim/acquisition_stream.h):
// the in-memory run's files, byte for byte, on the shipped NISAR-format
// products (winnipeg.h5 with its DEM; SanAnd_138.h5 over its window of a
// DEM), for SLAR and the incoherent SAR, on the ellipsoid and the flat
// Earth, with land cover, in blocks of 7, 16 and all lines and from the memory budget, on 1
// and 2 threads; a failing block leaves no output.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "acquisition_paths.h"
#include "folder_compare.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/scene/geo_frame.h"
#include "ris/scene/scene_io.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// The acquisition run `args` in memory and streamed (each block length, 1
// and 2 threads): the same 8 files (two pictures, five rasters, metadata).
void expect_streams_as_in_memory(const std::string& args, const std::string& tag) {
  test::TempDir dir;
  for (int threads : {1, 2}) {
    const std::string run = "simulate --quiet --threads " + std::to_string(threads) + " " + args;
    const fs::path mem = dir / ("mem" + std::to_string(threads));
    const auto m = test::run_ris(run + " --out " + mem.string());
    ASSERT_EQ(m.exit_code, 0) << tag << "\n" << m.output;
    for (const std::string blocks :
         {" --block-lines 7", " --block-lines 16", " --block-lines 100000", " --stream"}) {
      const std::string t = tag + ", " + std::to_string(threads) + " threads," + blocks;
      const fs::path out = dir / "streamed";
      fs::remove_all(out);
      const auto s = test::run_ris(run + blocks + " --out " + out.string());
      ASSERT_EQ(s.exit_code, 0) << t << "\n" << s.output;
      EXPECT_NE(s.output.find("streamed in"), std::string::npos) << t << "\n" << s.output;
      test::expect_same_files(mem, out, t, 8);
    }
  }
}

std::string winnipeg() {
  return "-a " + test::winnipeg_h5() + " --dem " + test::test_dem("winnipeg_dem.tif");
}

TEST(StreamAcquisitionCli, WinnipegSlarStreamsAsInMemory) {
  expect_streams_as_in_memory(winnipeg(), "Winnipeg SLAR, ellipsoid");
}

TEST(StreamAcquisitionCli, WinnipegIncoherentSarOnTheFlatEarthStreamsAsInMemory) {
  test::TempDir dir;
  const std::string sar = test::radar_with(dir, "sar.toml", "sar-x-band-stripmap.toml",
                                           "coherent = true", "coherent = false");
  expect_streams_as_in_memory(winnipeg() + " --earth flat --radar " + sar,
                              "Winnipeg incoherent SAR, flat Earth");
}

TEST(StreamAcquisitionCli, SanAndreasStreamsAsInMemory) {
  expect_streams_as_in_memory(
      "-a " + test::sanand_h5() + " --dem " + test::test_dem("SanAnd_dem.tif"), "San Andreas SLAR");
}

// Land cover (--land-cover): a scene in UTM over the Winnipeg DEM, category
// 1 west of the DEM's centre and 2 east of it. Each streamed block reads its
// window of the DEM and the categories on it; the categories over the whole
// DEM (the radiometry's table) come from a pass in bands of rows.
TEST(StreamAcquisitionCli, LandCoverStreamsAsInMemory) {
  test::TempDir dir;
  const EllipsoidalDem dem = read_ellipsoidal_dem(test::test_dem("winnipeg_dem.tif"));
  const double lat_c = rad_to_deg(dem.lat0_rad + 0.5 * (dem.rows - 1) * dem.dlat_rad);
  const double lon_c = rad_to_deg(dem.lon0_rad + 0.5 * (dem.cols - 1) * dem.dlon_rad);
  Scene cover = Scene::flat(1000, 1000, 25.0, 0.0f, 1);
  cover.crs_wkt = utm_wkt_for(lon_c, lat_c);
  const auto [xc, yc] = GeoFrame(cover.crs_wkt, "test").scene_from_lonlat(lon_c, lat_c);
  cover.origin_x_m = xc - 12500.0;
  cover.origin_y_m = yc + 12500.0;
  for (int r = 0; r < cover.rows; ++r)
    for (int c = 500; c < cover.cols; ++c) cover.category[cover.index(r, c)] = 2;
  const fs::path cover_tif = dir / "cover.tif";
  write_scene_geotiff(cover, cover_tif);
  expect_streams_as_in_memory(winnipeg() + " --land-cover " + cover_tif.string(),
                              "Winnipeg SLAR, land cover");
  // The cover changes the image (category 2 east of the centre).
  for (const std::string& extra : {std::string(), " --land-cover " + cover_tif.string()}) {
    const auto r = test::run_ris("simulate --quiet --products mean_power_slant " + winnipeg() +
                                 extra + " --out " + (dir / (extra.empty() ? "a" : "b")).string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  EXPECT_NE(test::read_file(dir / "a" / "mean_power_slant.tif"),
            test::read_file(dir / "b" / "mean_power_slant.tif"));
}

// A block that fails (RIS_FAIL_BLOCK) fails the run naming it; nothing is
// left in or beside the output folder.
TEST(StreamAcquisitionCli, FailingBlockLeavesNoOutput) {
  test::TempDir dir;
  const fs::path out = dir / "out";
  const auto r =
      test::run_ris_env("RIS_FAIL_BLOCK=3", "simulate --quiet " + winnipeg() +
                                                " --block-lines 16 --out " + out.string());
  EXPECT_NE(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("block 3"), std::string::npos) << r.output;
  int left = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++left;
  EXPECT_EQ(left, 0) << "left in " << dir.path();
}

}  // namespace
}  // namespace ris
