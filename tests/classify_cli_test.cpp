// `ris scene classify` end to end (docs/classify.md): a georeferenced image
// of four known regions with 4-look speckle and a no-data stripe, written as
// a GeoTIFF (power, and the same in dB), classified by the binary without
// and with training polygons (in the image's CRS and in WGS 84); the class
// raster keeps the image's grid, georeferencing and no-data, the regions
// come back with IoU > 0.95, and bad input leaves no output.
#include <gdal.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <ogr_spatialref.h>
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "ris/io/raster_io.h"
#include "ris/scene/scene_io.h"
#include "test_util.h"

namespace ris {
namespace {

constexpr int kSize = 128;
constexpr double kX0 = 500000.0, kY0 = 4000000.0, kCell = 10.0;  // UTM 33N, 10 m pixels
const float kMean[4] = {0.05f, 0.2f, 0.8f, 3.2f};                // -13, -7, -1, +5 dB

int region_of(int r, int c) {
  return (r >= kSize / 2 ? 2 : 0) + (c >= kSize / 2 ? 1 : 0);
}
bool no_data(int /*r*/, int c) {
  return c >= 100 && c < 108;
}  // a stripe of fill

std::string utm_wkt() {
  OGRSpatialReference s;
  s.importFromEPSG(32633);
  char* w = nullptr;
  s.exportToWkt(&w);
  std::string out = w;
  CPLFree(w);
  return out;
}

// The image: power (db = false) or 10 log10 of it, NaN no-data in the
// stripe; placed by its geotransform or (gcps) by a 5 x 5 grid of ground
// control points on the same affine map, as ris's slant-range products are.
void write_image(const std::filesystem::path& p, bool db, bool gcps = false) {
  std::mt19937_64 rng(42);
  std::gamma_distribution<float> speckle(4.0f, 0.25f);
  std::vector<float> v(kSize * kSize);
  for (int r = 0; r < kSize; ++r)
    for (int c = 0; c < kSize; ++c) {
      const float x = kMean[region_of(r, c)] * speckle(rng);
      v[static_cast<std::size_t>(r * kSize + c)] =
          no_data(r, c) ? NAN : (db ? 10.0f * std::log10(x) : x);
    }
  Georef g{{kX0, kCell, 0.0, kY0, 0.0, -kCell}, utm_wkt()};
  for (int i = 0; gcps && i <= 4; ++i)
    for (int k = 0; k <= 4; ++k) {
      const double px = k * kSize / 4.0, ln = i * kSize / 4.0;
      g.gcps.push_back({px, ln, kX0 + px * kCell, kY0 - ln * kCell, 0.0});
    }
  write_geotiff<float>(p, v.data(), kSize, kSize, &g, NAN);
}

// Per region: IoU with the class code that holds most of it (pixels with data).
std::vector<double> region_iou(const RasterF64& lab, std::vector<int>* best_code = nullptr) {
  std::vector<double> out;
  for (int q = 0; q < 4; ++q) {
    std::map<int, int> votes;
    for (int r = 0; r < kSize; ++r)
      for (int c = 0; c < kSize; ++c)
        if (!no_data(r, c) && region_of(r, c) == q)
          ++votes[static_cast<int>(lab.data[static_cast<std::size_t>(r * kSize + c)])];
    const int best = std::max_element(votes.begin(), votes.end(), [](auto& a, auto& b) {
                       return a.second < b.second;
                     })->first;
    if (best_code != nullptr) best_code->push_back(best);
    double inter = 0, uni = 0;
    for (int r = 0; r < kSize; ++r)
      for (int c = 0; c < kSize; ++c) {
        if (no_data(r, c)) continue;
        const bool a = region_of(r, c) == q;
        const bool b = lab.data[static_cast<std::size_t>(r * kSize + c)] == best;
        inter += a && b;
        uni += a || b;
      }
    out.push_back(inter / uni);
  }
  return out;
}

TEST(SceneClassifyCli, RecoversSpeckledRegionsWithTheImagesGridAndNoData) {
  test::TempDir dir;
  write_image(dir / "power.tif", false);
  write_image(dir / "db.tif", true);
  const auto r = test::run_ris("scene classify " + test::q(dir / "power.tif") +
                               " --classes 4 --out " + test::q(dir / "classes.tif"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RasterF64 lab = read_raster_f64(dir / "classes.tif");
  ASSERT_EQ(lab.cols, kSize);
  ASSERT_EQ(lab.rows, kSize);
  ASSERT_TRUE(lab.nodata.has_value());
  EXPECT_EQ(*lab.nodata, 0.0);
  EXPECT_TRUE(lab.has_geotransform);
  EXPECT_EQ(lab.georef.geotransform, (std::array<double, 6>{kX0, kCell, 0.0, kY0, 0.0, -kCell}));
  OGRSpatialReference crs;
  crs.importFromWkt(lab.georef.crs_wkt.c_str());
  EXPECT_STREQ(crs.GetAuthorityCode(nullptr), "32633");
  std::size_t zeros = 0;
  for (int row = 0; row < kSize; ++row)
    for (int c = 0; c < kSize; ++c) {
      const double v = lab.data[static_cast<std::size_t>(row * kSize + c)];
      zeros += v == 0.0;
      if (no_data(row, c)) {
        EXPECT_EQ(v, 0.0) << row << "," << c;
      }
    }
  EXPECT_EQ(zeros, 8U * kSize);  // exactly the stripe
  std::vector<int> code;
  const std::vector<double> iou = region_iou(lab, &code);
  for (int q = 0; q < 4; ++q) {
    std::printf("CLI k-means: region %d -> class %d, IoU %.4f\n", q, code[q], iou[q]);
    EXPECT_GT(iou[q], 0.95) << "region " << q;
    EXPECT_EQ(code[q], q + 1);  // classes numbered by increasing mean
  }
  // The summary: counts add up to the pixels with data; per class the mean
  // within 0.3 dB of its region's (the classes lose and gain a few percent
  // of edge pixels). The ENL is the speckle's 4 looks for the two outer
  // classes (within 0.5: 3.4 standard errors of an ENL from 3500 pixels) and
  // lower for the middle ones, which hold a few percent of pixels of regions
  // 6 dB either side (a mixture: measured 2.7-2.8; asked 2.3-4.3).
  const auto j = nlohmann::json::parse(test::read_file(dir / "classes.json"));
  EXPECT_EQ(j["pixels_with_data"].get<std::size_t>(), static_cast<std::size_t>(120 * kSize));
  EXPECT_EQ(j["no_data_pixels"].get<std::size_t>(), static_cast<std::size_t>(8 * kSize));
  EXPECT_EQ(j["image"]["read_as"].get<std::string>(), "power");
  ASSERT_EQ(j["classes"].size(), 4U);
  EXPECT_FALSE(j["classes"][0].contains("k_shape_nu"));  // only with --looks
  std::size_t total = 0;
  for (int q = 0; q < 4; ++q) {
    const auto& c = j["classes"][static_cast<std::size_t>(q)];
    total += c["pixels"].get<std::size_t>();
    const double db = c["mean_sigma0_db"][0].get<double>(), enl = c["enl"][0].get<double>();
    std::printf("CLI class %d: %.3f dB (truth %.3f), ENL %.3f\n", q + 1, db,
                10 * std::log10(kMean[q]), enl);
    EXPECT_NEAR(db, 10 * std::log10(kMean[q]), 0.3) << q;
    if (q == 0 || q == 3) {
      EXPECT_NEAR(enl, 4.0, 0.5) << q;
    } else {
      EXPECT_NEAR(enl, 3.3, 1.0) << q;
    }
  }
  EXPECT_EQ(total, static_cast<std::size_t>(120 * kSize));

  // The same image in dB, read with --scale db: the same classes.
  const auto d =
      test::run_ris("scene classify " + test::q(dir / "db.tif") +
                    " --scale db --classes 4 --quiet --out " + test::q(dir / "db_classes.tif"));
  ASSERT_EQ(d.exit_code, 0) << d.output;
  EXPECT_TRUE(d.output.empty()) << d.output;
  const RasterF64 lab_db = read_raster_f64(dir / "db_classes.tif");
  std::size_t same = 0;
  for (std::size_t i = 0; i < lab.data.size(); ++i) same += lab.data[i] == lab_db.data[i];
  EXPECT_GE(same, lab.data.size() - 5) << "of " << lab.data.size();
  EXPECT_EQ(nlohmann::json::parse(test::read_file(dir / "db_classes.json"))["image"]["read_as"]
                .get<std::string>(),
            "10^(dB/10)");
}

// --looks: single-look speckle (nu infinite) in the west half, 10 dB below
// a K-distributed east half of shape nu = 2 (a Gamma(2, 1/2) texture per
// pixel times the speckle: Jakeman & Pusey 1976). The classes' method-of-
// moments nu: 1/nu within 0.1 of 0 in the west (null in the JSON when the
// estimate is at or below speckle alone); within 1.5..2.7 in the east (8192
// pixels: the standard error of 1/nu is about 0.04 on 0.5, and the few
// pixels the classifier swaps between the halves).
TEST(SceneClassifyCli, LooksGiveEachClassItsKDistributionShape) {
  test::TempDir dir;
  std::mt19937_64 rng(5);
  std::exponential_distribution<float> speckle(1.0f);
  std::gamma_distribution<float> texture(2.0f, 0.5f);
  std::vector<float> v(kSize * kSize);
  for (int r = 0; r < kSize; ++r)
    for (int c = 0; c < kSize; ++c)
      v[static_cast<std::size_t>(r * kSize + c)] =
          c < kSize / 2 ? speckle(rng) : 10.0f * texture(rng) * speckle(rng);
  const Georef g{{kX0, kCell, 0.0, kY0, 0.0, -kCell}, utm_wkt()};
  write_geotiff<float>(dir / "k.tif", v.data(), kSize, kSize, &g);
  const auto r = test::run_ris("scene classify " + test::q(dir / "k.tif") +
                               " --classes 2 --looks 1 --smooth 2 --quiet --out " +
                               test::q(dir / "k_classes.tif"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(test::read_file(dir / "k_classes.json"));
  ASSERT_EQ(j["classes"].size(), 2U);
  EXPECT_EQ(j["looks"].get<double>(), 1.0);
  const auto& west = j["classes"][0]["k_shape_nu"][0];
  const double inv_west = west.is_null() ? 0.0 : 1.0 / west.get<double>();
  const double nu_east = j["classes"][1]["k_shape_nu"][0].get<double>();
  std::printf("K shape: west 1/nu %.4f, east nu %.3f (pixels %zu, %zu)\n", inv_west, nu_east,
              j["classes"][0]["pixels"].get<std::size_t>(),
              j["classes"][1]["pixels"].get<std::size_t>());
  EXPECT_LT(std::abs(inv_west), 0.1);
  EXPECT_GT(nu_east, 1.5);
  EXPECT_LT(nu_east, 2.7);
}

// One 20 x 20-pixel box inside each region: its corners in the image's CRS.
struct Box {
  double x0, y0, x1, y1;
};
std::vector<Box> training_boxes() {
  std::vector<Box> out;
  for (int q = 0; q < 4; ++q) {
    const int c0 = (q % 2 ? 64 : 0) + 20, r0 = (q >= 2 ? 64 : 0) + 20;
    out.push_back(
        {kX0 + c0 * kCell, kY0 - (r0 + 20) * kCell, kX0 + (c0 + 20) * kCell, kY0 - r0 * kCell});
  }
  return out;
}

// A GeoJSON of the boxes with the given categories; in WGS 84 (lon, lat,
// GeoJSON's default) when wgs84, else with a "crs" member naming UTM 33N.
std::string training_geojson(const std::vector<int>& category, bool wgs84, double shift_m = 0.0) {
  OGRSpatialReference utm, geo;
  utm.importFromEPSG(32633);
  geo.importFromEPSG(4326);
  geo.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&utm, &geo));
  std::string f;
  const std::vector<Box> boxes = training_boxes();
  for (std::size_t q = 0; q < boxes.size(); ++q) {
    const Box& b = boxes[q];
    std::string ring;
    const double xs[5] = {b.x0, b.x1, b.x1, b.x0, b.x0}, ys[5] = {b.y0, b.y0, b.y1, b.y1, b.y0};
    for (int k = 0; k < 5; ++k) {
      double x = xs[k] + shift_m, y = ys[k];
      if (wgs84) ct->Transform(1, &x, &y);
      ring += (k ? "," : "") + std::string("[") + std::to_string(x) + "," + std::to_string(y) + "]";
    }
    f += (q ? ",\n" : "") + std::string("{\"type\":\"Feature\",\"properties\":{\"category\":") +
         std::to_string(category[q]) + "},\"geometry\":{\"type\":\"Polygon\",\"coordinates\":[[" +
         ring + "]]}}";
  }
  const std::string crs = wgs84 ? ""
                                : "\"crs\":{\"type\":\"name\",\"properties\":{\"name\":\"urn:ogc:"
                                  "def:crs:EPSG::32633\"}},";
  return "{\"type\":\"FeatureCollection\"," + crs + "\"features\":[\n" + f + "]}\n";
}

// A vector file converted to a GeoPackage (GDALVectorTranslate, the library
// behind ogr2ogr).
bool to_geopackage(const std::filesystem::path& from, const std::filesystem::path& to) {
  GDALAllRegister();
  GDALDatasetH src = GDALOpenEx(from.c_str(), GDAL_OF_VECTOR, nullptr, nullptr, nullptr);
  if (src == nullptr) {
    std::printf("GDALOpenEx: %s\n", CPLGetLastErrorMsg());
    return false;
  }
  char* argv[] = {const_cast<char*>("-f"), const_cast<char*>("GPKG"), nullptr};
  GDALVectorTranslateOptions* opt = GDALVectorTranslateOptionsNew(argv, nullptr);
  GDALDatasetH out = GDALVectorTranslate(to.c_str(), nullptr, 1, &src, opt, nullptr);
  GDALVectorTranslateOptionsFree(opt);
  GDALClose(src);
  if (out == nullptr) {
    std::printf("GDALVectorTranslate: %s\n", CPLGetLastErrorMsg());
    return false;
  }
  GDALClose(out);
  return true;
}

// The polygons in UTM (GeoJSON and GeoPackage), in WGS 84, and in UTM over
// the image placed by GCPs (whose class raster keeps the GCPs).
TEST(SceneClassifyCli, TrainingPolygonsInAnyCrsGiveTheirCategories) {
  test::TempDir dir;
  write_image(dir / "power.tif", false);
  write_image(dir / "power_gcps.tif", false, true);
  const std::vector<int> category = {7, 3, 12, 5};  // region -> ris category id
  for (const std::string name : {"utm", "wgs84", "gcps", "gpkg"}) {
    const bool wgs84 = name == "wgs84";
    test::write_file(dir / (name + ".geojson"), training_geojson(category, wgs84));
    std::string polygons = name + ".geojson";
    if (name == "gpkg") {  // the UTM GeoJSON as a GeoPackage, by GDAL's ogr2ogr
      polygons = "training.gpkg";
      // (from utm.geojson: a layer named "gpkg", from gpkg.geojson, failed to translate)
      ASSERT_TRUE(to_geopackage(dir / "utm.geojson", dir / polygons));
    }
    const std::string image = name == "gcps" ? "power_gcps.tif" : "power.tif";
    const auto r =
        test::run_ris("scene classify " + test::q(dir / image) + " --training " +
                      test::q(dir / polygons) + " --out " + test::q(dir / (name + ".tif")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::vector<int> code;
    const std::vector<double> iou = region_iou(read_raster_f64(dir / (name + ".tif")), &code);
    for (int q = 0; q < 4; ++q) {
      std::printf("CLI training (%s): region %d -> category %d, IoU %.4f\n", name.c_str(), q,
                  code[q], iou[q]);
      EXPECT_EQ(code[q], category[q]) << name << " region " << q;
      EXPECT_GT(iou[q], 0.95) << name << " region " << q;
    }
    const auto j = nlohmann::json::parse(test::read_file(dir / (name + ".json")));
    EXPECT_EQ(j["method"].get<std::string>(), "nearest mean");
    if (name == "gcps") {
      GDALDatasetH ds = GDALOpen((dir / "gcps.tif").c_str(), GA_ReadOnly);
      ASSERT_NE(ds, nullptr);
      EXPECT_EQ(GDALGetGCPCount(ds), 25);
      GDALClose(ds);
      EXPECT_EQ(j["image"]["georeferenced"].get<std::string>(), "ground control points");
    }
    EXPECT_EQ(j["training"]["features"].get<int>(), 4);
    // Each 20 x 20 box burns the 400 pixels whose centres it holds (the
    // WGS 84 copy, its edges slightly curved in UTM, within 2 %).
    for (const auto& [code_text, n] : j["training"]["pixels"].items())
      EXPECT_NEAR(n.get<double>(), 400.0, wgs84 ? 8.0 : 0.0) << name << " category " << code_text;
  }
}

// The class raster is a land cover `ris scene import` reads: a flat DEM on
// the image's grid with the classes mapped to generic-terrain categories
// gives a scene whose every cell with data has its class's category, and
// the no-data stripe is no-data (the mapping has no fill).
TEST(SceneClassifyCli, TheClassRasterIsALandCoverSceneImportReads) {
  test::TempDir dir;
  write_image(dir / "power.tif", false);
  ASSERT_EQ(test::run_ris("scene classify " + test::q(dir / "power.tif") +
                          " --classes 4 --quiet --out " + test::q(dir / "classes.tif"))
                .exit_code,
            0);
  std::vector<float> flat(kSize * kSize, 100.0f);
  const Georef g{{kX0, kCell, 0.0, kY0, 0.0, -kCell}, utm_wkt()};
  write_geotiff<float>(dir / "dem.tif", flat.data(), kSize, kSize, &g);
  test::write_file(dir / "classes.toml",
                   "[mapping]\nname = \"ris scene classify\"\n"
                   "library = \"backscatter/generic-terrain.toml\"\n"
                   "[classes]\n1 = \"water\"\n2 = \"grass\"\n3 = \"forest\"\n4 = \"urban\"\n");
  const auto r = test::run_ris("scene import " + test::q(dir / "dem.tif") + " --landcover " +
                               test::q(dir / "classes.tif") + " --mapping " +
                               test::q(dir / "classes.toml") + " -o " + test::q(dir / "scene.tif"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Scene scene = read_scene(dir / "scene.tif");
  ASSERT_EQ(scene.cols, kSize);
  ASSERT_EQ(scene.rows, kSize);
  const RasterF64 lab = read_raster_f64(dir / "classes.tif");
  const std::uint16_t category_of_class[5] = {0, 23, 21, 22, 24};
  std::size_t differ = 0, invalid = 0;
  for (int row = 0; row < kSize; ++row)
    for (int c = 0; c < kSize; ++c) {
      const std::size_t i = static_cast<std::size_t>(row * kSize + c);
      const int cls = static_cast<int>(lab.data[i]);
      invalid += scene.valid[i] == 0;
      if (cls == 0) {
        differ += scene.valid[i] != 0;
      } else {
        differ += scene.valid[i] == 0 || scene.category[i] != category_of_class[cls];
      }
    }
  EXPECT_EQ(differ, 0U);
  EXPECT_EQ(invalid, 8U * kSize);  // the stripe
}

// Each refusal: a non-zero exit, a message naming the file or option, and
// no class raster or summary left in the folder.
void expect_refused(const test::TempDir& dir, const std::string& args, const std::string& says) {
  const auto r = test::run_ris("scene classify " + args + " --out " + test::q(dir / "out.tif"));
  EXPECT_NE(r.exit_code, 0) << args;
  EXPECT_NE(r.output.find(says), std::string::npos) << args << "\n" << r.output;
  for (const auto& e : std::filesystem::directory_iterator(dir.path())) {
    const std::string f = e.path().filename().string();
    EXPECT_TRUE(f == "power.tif" || f == "db.tif" || f.ends_with(".geojson"))
        << args << ": left " << f;
  }
}

TEST(SceneClassifyCli, BadInputGivesAClearErrorAndNoOutput) {
  test::TempDir dir;
  write_image(dir / "power.tif", false);
  const std::string img = test::q(dir / "power.tif");
  expect_refused(dir, test::q(dir / "missing.tif") + " --classes 4", "missing.tif");
  expect_refused(dir, img + " --classes 1", "--classes");
  expect_refused(dir, img + " --classes 256", "expected 2..255 classes, got 256");
  expect_refused(dir, img, "--classes");  // neither --classes nor --training
  expect_refused(dir, img + " --classes 4 --band 2", "band 2 asked for, the raster has 1");
  expect_refused(dir, img + " --classes 4 --scale linear", "--scale");
  expect_refused(dir, img + " --classes 4 --looks -1", "--looks");
  // An image in dB read as power (its -13 and -7 dB halves <= 0): the hint.
  write_image(dir / "db.tif", true);
  expect_refused(dir, test::q(dir / "db.tif") + " --classes 4",
                 "values at or below 0: for an image in dB give --scale db");
  std::filesystem::remove(dir / "db.tif");
  // Polygons 100 km east of the image: no overlap, the two extents given.
  test::write_file(dir / "far.geojson", training_geojson({1, 2, 3, 4}, false, 1e5));
  expect_refused(dir, img + " --training " + test::q(dir / "far.geojson"),
                 "none of its 4 polygons covers a pixel of the image");
  // A category that is not an integer 1..255, and a missing attribute.
  test::write_file(dir / "zero.geojson", training_geojson({1, 2, 0, 4}, false));
  expect_refused(dir, img + " --training " + test::q(dir / "zero.geojson"),
                 "expected an integer category 1..255, got '0'");
  test::write_file(dir / "attr.geojson", training_geojson({1, 2, 3, 4}, false));
  expect_refused(dir, img + " --training " + test::q(dir / "attr.geojson") + " --attribute class",
                 "has no attribute 'class'");
  // One category only: nothing to choose between.
  test::write_file(dir / "one.geojson", training_geojson({2, 2, 2, 2}, false));
  expect_refused(dir, img + " --training " + test::q(dir / "one.geojson"), "2 or more categories");
  // Training on an image placed neither by a geotransform nor by GCPs.
  {
    std::vector<float> plain(64 * 64, 1.0f);
    write_geotiff<float>(dir / "plain.tif", plain.data(), 64, 64, nullptr);
    const auto r =
        test::run_ris("scene classify " + test::q(dir / "plain.tif") + " --training " +
                      test::q(dir / "attr.geojson") + " --out " + test::q(dir / "out.tif"));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("neither a geotransform nor ground control points"), std::string::npos)
        << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.tif"));
    std::filesystem::remove(dir / "plain.tif");
  }
  test::write_file(dir / "notvec.geojson", "not a vector file");
  expect_refused(dir, img + " --training " + test::q(dir / "notvec.geojson"), "notvec.geojson");
  // Memory: a 512 x 512 image reads in 3 MiB (12 bytes a pixel) but needs
  // 10 MiB to classify (40 bytes a pixel on one band): refused at 6 MiB.
  {
    std::vector<float> big(512 * 512, 1.0f);
    const Georef g{{kX0, kCell, 0.0, kY0, 0.0, -kCell}, utm_wkt()};
    write_geotiff<float>(dir / "big.tif", big.data(), 512, 512, &g);
    const auto r = test::run_ris_env("RIS_MAX_MEMORY_MB=6",
                                     "scene classify " + test::q(dir / "big.tif") +
                                         " --classes 3 --out " + test::q(dir / "out.tif"));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("classifying the 512 x 512 image"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.tif"));
    std::filesystem::remove(dir / "big.tif");
  }
  // The output must be a GeoTIFF.
  const auto png =
      test::run_ris("scene classify " + img + " --classes 4 --out " + test::q(dir / "out.png"));
  EXPECT_NE(png.exit_code, 0);
  EXPECT_NE(png.output.find("expected a GeoTIFF"), std::string::npos) << png.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
}

}  // namespace
}  // namespace ris
