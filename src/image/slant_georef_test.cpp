// The slant-range products' GCPs against the geocoding they must agree
// with, and bilinear geocoding against an analytic ramp.
#include "ris/image/slant_georef.h"

#include <gdal.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ris/image/geocode.h"
#include "ris/io/gdal_util.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/error.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

RadarParams test_radar(const std::string& heading) {
  toml::table doc = toml::parse(R"(name = "t"
mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
near_range = "12000 m"
far_range = "20000 m"
azimuth_beamwidth = "0.05 deg"
[track]
altitude = "6000 m"
heading = ")" + heading + R"("
near_edge_distance = "12000 m"
)");
  return radar_from_toml(doc, "radar.toml");
}

// 20 m cells at 50 m, with a smooth hill 60 m high (sigma 600 m): the tie
// points must follow the terrain, not a flat reference.
Scene hill_scene() {
  Scene s = Scene::flat(150, 200, 20.0, 50.0f, 0);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const double d2 = (r - 75.0) * (r - 75.0) + (c - 100.0) * (c - 100.0);
      s.elevation_m[s.index(r, c)] +=
          static_cast<float>(60.0 * std::exp(-d2 / (2.0 * 30.0 * 30.0)));
    }
  return s;
}

struct Offsets {
  double max_pixel = 0.0, max_line = 0.0;
  int cells = 0;
};

// Warps an image of each pixel's own (pixel, line) centre coordinates,
// carrying `g`'s GCPs, onto the scene grid with GDALWarp (bilinear, which
// reproduces the linear coordinates exactly between centres) and compares
// every cell's warped coordinates with its exact position (geocode_position):
// the offset, in pixels and lines, of a gdalwarp of a slant product.
Offsets warp_offsets(const Scene& s, const SlarSimulation& sim, const Georef& g,
                     const std::vector<std::string>& extra) {
  ensure_gdal_writers_registered();
  const SlarImage& img = sim.image;
  GDALDatasetH src =
      GDALCreate(GDALGetDriverByName("MEM"), "", img.bins, img.lines, 2, GDT_Float64, nullptr);
  std::vector<double> p(img.mean_power_w.size()), l(p.size());
  for (int k = 0; k < img.lines; ++k)
    for (int b = 0; b < img.bins; ++b) {
      p[img.index(k, b)] = b + 0.5;
      l[img.index(k, b)] = k + 0.5;
    }
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(src, 1), GF_Write, 0, 0, img.bins, img.lines, p.data(),
                         img.bins, img.lines, GDT_Float64, 0, 0),
            CE_None);
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(src, 2), GF_Write, 0, 0, img.bins, img.lines, l.data(),
                         img.bins, img.lines, GDT_Float64, 0, 0),
            CE_None);
  std::vector<GDAL_GCP> gcps(g.gcps.size());
  std::vector<std::string> ids(gcps.size());
  for (std::size_t i = 0; i < gcps.size(); ++i) {
    ids[i] = std::to_string(i);
    gcps[i] = {ids[i].data(), ids[i].data(), g.gcps[i].pixel, g.gcps[i].line,
               g.gcps[i].x,   g.gcps[i].y,   g.gcps[i].z};
  }
  GDALSetGCPs(src, static_cast<int>(gcps.size()), gcps.data(), "");
  const auto [x0, y1] = s.world_from_grid(0, 0);
  const auto [x1, y0] = s.world_from_grid(s.cols, s.rows);
  std::vector<std::string> args = {"-of",
                                   "MEM",
                                   "-r",
                                   "bilinear",
                                   "-et",
                                   "0",
                                   "-dstnodata",
                                   "nan",
                                   "-te",
                                   std::to_string(x0),
                                   std::to_string(y0),
                                   std::to_string(x1),
                                   std::to_string(y1),
                                   "-ts",
                                   std::to_string(s.cols),
                                   std::to_string(s.rows)};
  args.insert(args.end(), extra.begin(), extra.end());
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALWarpAppOptions* opt = GDALWarpAppOptionsNew(argv.data(), nullptr);
  int usage_error = 0;
  GDALDatasetH dst = GDALWarp("", nullptr, 1, &src, opt, &usage_error);
  GDALWarpAppOptionsFree(opt);
  Offsets o;
  EXPECT_NE(dst, nullptr) << last_gdal_error();
  if (dst == nullptr) {
    GDALClose(src);
    return o;
  }
  std::vector<double> wp(s.size()), wl(s.size());
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(dst, 1), GF_Read, 0, 0, s.cols, s.rows, wp.data(),
                         s.cols, s.rows, GDT_Float64, 0, 0),
            CE_None);
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(dst, 2), GF_Read, 0, 0, s.cols, s.rows, wl.data(),
                         s.cols, s.rows, GDT_Float64, 0, 0),
            CE_None);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      double line = 0, bin = 0;
      const std::size_t i = s.index(r, c);
      if (!geocode_position(s, sim.track, img, r, c, s.elevation_m[i], line, bin)) continue;
      // Inside the image's pixel centres (bilinear is exact there).
      if (!(line > 1.0 && line < img.lines - 1.0 && bin > 1.0 && bin < img.bins - 1.0)) continue;
      if (std::isnan(wp[i]) || std::isnan(wl[i])) continue;
      o.max_pixel = std::max(o.max_pixel, std::abs(wp[i] - bin));
      o.max_line = std::max(o.max_line, std::abs(wl[i] - line));
      ++o.cells;
    }
  GDALClose(dst);
  GDALClose(src);
  return o;
}

TEST(SlantGeoref, TiePointsLieOnTheTerrainAtTheirSlantRange) {
  const Scene s = hill_scene();
  const SlarSimulation sim = simulate_slar(s, test_radar("0 deg"), test::CosineSigma0Source());
  const Georef g = slant_georef(s, sim.track, sim.image);
  ASSERT_EQ(g.gcps.size(), 400u);  // 20 x 20
  for (const GroundControlPoint& p : g.gcps) {
    const auto [s_m, u_m] = sim.track.along_cross(p.x, p.y);
    const double R = std::hypot(u_m, sim.track.altitude_m - p.z);
    // Linear between samples half a cell (10 m) apart: the chord of R(u)
    // is within 1 mm of it.
    EXPECT_NEAR(R, sim.image.range.near_m + p.pixel * sim.image.range.bin_m, 1e-3);
    EXPECT_NEAR(s_m, p.line * sim.image.line_spacing_m, 1e-6);
    // The height is the terrain's there (cells' heights; linear between
    // half-cell samples: within the hill's change over a cell, < 2.5 m).
    const auto [fc, fr] = s.grid_from_world(p.x, p.y);
    const int c = std::clamp(int(fc), 0, s.cols - 1), r = std::clamp(int(fr), 0, s.rows - 1);
    if (s.contains(int(std::floor(fr)), int(std::floor(fc)))) {
      EXPECT_NEAR(p.z, s.elevation_m[s.index(r, c)], 2.5) << p.pixel << " " << p.line;
    }
  }
}

TEST(SlantGeoref, GdalwarpWithTheGcpsLandsOnTheGeocodingWithinACell) {
  // Tracks along and off the grid axes. GDAL fits the 20 x 20 points (a
  // thin-plate spline with -tps, exact at every point; its default, a
  // polynomial of order 2, is what QGIS's automatic warp uses); what no fit
  // through the points follows is the terrain and the range curvature
  // between them (here ~27 bins, 8 lines apart, over a hill 60 m high).
  // Measured max |offset| on this scene (2026-12-02): -tps 0.66 / 0.86
  // bins (heading 0 / 30 deg), 0.04 lines; polynomial 1.30 / 1.13 bins.
  // So: within a cell with -tps, within 1.5 cells with the polynomial.
  const Scene s = hill_scene();
  for (const std::string heading : {"0 deg", "30 deg"}) {
    const SlarSimulation sim = simulate_slar(s, test_radar(heading), test::CosineSigma0Source());
    const Georef g = slant_georef(s, sim.track, sim.image);
    const Offsets tps = warp_offsets(s, sim, g, {"-tps"});
    const Offsets poly = warp_offsets(s, sim, g, {});
    std::printf(
        "heading %s: %d cells; -tps max offset %.3f bins, %.3f lines; polynomial %.3f "
        "bins, %.3f lines\n",
        heading.c_str(), tps.cells, tps.max_pixel, tps.max_line, poly.max_pixel, poly.max_line);
    EXPECT_GT(tps.cells, 10000) << heading;
    EXPECT_LT(tps.max_pixel, 1.0) << heading;
    EXPECT_LT(tps.max_line, 1.0) << heading;
    EXPECT_LT(poly.max_pixel, 1.5) << heading;
    EXPECT_LT(poly.max_line, 1.5) << heading;
  }
}

TEST(GeocodeBilinear, ReproducesAnAnalyticRampAndNearestDoesNot) {
  // Slant values linear in the image coordinates, v = 2 P + 3 L at pixel
  // centres: bilinear geocoding gives each cell 2 P + 3 L at its own exact
  // position (geocode_position); nearest is off by up to 1 (half a bin
  // times 2; the cells sit at line centres along this track).
  const Scene s = hill_scene();
  const SlarSimulation sim = simulate_slar(s, test_radar("0 deg"), test::CosineSigma0Source());
  const SlarImage& img = sim.image;
  std::vector<float> ramp(img.mean_power_w.size());
  for (int k = 0; k < img.lines; ++k)
    for (int b = 0; b < img.bins; ++b)
      ramp[img.index(k, b)] = static_cast<float>(2.0 * (b + 0.5) + 3.0 * (k + 0.5));
  const std::vector<float> bil =
      geocode_slant_image(s, sim.track, img, ramp, GeocodeResampling::bilinear);
  const std::vector<float> near = geocode_slant_image(s, sim.track, img, ramp);
  double max_bil = 0.0, max_near = 0.0;
  int n = 0;
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      double line = 0, bin = 0;
      const std::size_t i = s.index(r, c);
      if (!geocode_position(s, sim.track, img, r, c, s.elevation_m[i], line, bin)) continue;
      if (!(line >= 0.5 && line <= img.lines - 0.5 && bin >= 0.5 && bin <= img.bins - 0.5))
        continue;
      const double want = 2.0 * bin + 3.0 * line;
      max_bil = std::max(max_bil, std::abs(bil[i] - want));
      max_near = std::max(max_near, std::abs(near[i] - want));
      ++n;
    }
  ASSERT_GT(n, 10000);
  EXPECT_LT(max_bil, 2e-3);  // float rounding of values up to ~1500
  EXPECT_GT(max_near, 0.9);
}

TEST(GeocodeBilinear, SkipsNeighboursWithoutData) {
  // One pixel value NaN: cells around it take their other neighbours
  // (renormalised weights), never NaN, and a constant image stays constant.
  const Scene s = hill_scene();
  const SlarSimulation sim = simulate_slar(s, test_radar("0 deg"), test::CosineSigma0Source());
  const SlarImage& img = sim.image;
  std::vector<float> flat(img.mean_power_w.size(), 7.0f);
  flat[img.index(img.lines / 2, img.bins / 2)] = std::nanf("");
  const std::vector<float> bil =
      geocode_slant_image(s, sim.track, img, flat, GeocodeResampling::bilinear);
  const std::vector<float> near = geocode_slant_image(s, sim.track, img, flat);
  int filled = 0;  // the NaN pixel's own cells, filled from its neighbours
  for (std::size_t i = 0; i < bil.size(); ++i) {
    if (std::isnan(bil[i])) continue;
    EXPECT_FLOAT_EQ(bil[i], 7.0f) << i;
    if (std::isnan(near[i])) ++filled;
  }
  EXPECT_GT(filled, 0);
  EXPECT_THROW(parse_geocode_resampling("cubic", "", "--geocode-resampling"), InputError);
  EXPECT_EQ(parse_geocode_resampling("bilinear", "", "k"), GeocodeResampling::bilinear);
}

}  // namespace
}  // namespace ris
