#include "ris/scene/landcover.h"
#include "build_paths.h"

#include <cpl_string.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <set>

#include "ris/io/raster_io.h"
#include "ris/scene/geo_frame.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

std::string wkt_of_epsg(int code) {
  OGRSpatialReference srs;
  srs.importFromEPSG(code);
  char* text = nullptr;
  srs.exportToWkt(&text);
  std::string out = text;
  CPLFree(text);
  return out;
}

constexpr const char* kLibrary = R"([library]
name = "test"
[[category]]
id = 1
name = "bare soil"
[[category]]
id = 2
name = "grass"
[[category]]
id = 3
name = "forest"
[[category]]
id = 4
name = "water"
[[category]]
id = 5
name = "urban"
[[category]]
id = 6
name = "road"
[[category]]
id = 7
name = "rock"
[[category]]
id = 8
name = "snow"
)";

// A 60 x 40 scene of 10 m cells in UTM 33N near Rome.
Scene utm_scene() {
  Scene s = Scene::flat(40, 60, 10.0, 50.0f, 0);
  s.origin_x_m = 290000.0;
  s.origin_y_m = 4652000.0;
  s.crs_wkt = wkt_of_epsg(32633);
  return s;
}

// Land cover in latitude/longitude (EPSG:4326) around the scene: 0.0001 deg
// pixels, code from a function of (col, row).
template <typename F>
void write_landcover(const std::filesystem::path& path, double lon0, double lat0, int cols,
                     int rows, F code_of, std::optional<double> nodata = std::nullopt) {
  std::vector<std::uint16_t> codes(static_cast<std::size_t>(cols) * rows);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c)
      codes[static_cast<std::size_t>(r) * cols + c] = static_cast<std::uint16_t>(code_of(c, r));
  Georef g{{lon0, 1e-4, 0, lat0, 0, -1e-4}, wkt_of_epsg(4326)};
  write_geotiff<std::uint16_t>(path, codes.data(), cols, rows, &g, nodata);
}

struct Fixture : ::testing::Test {
  test::TempDir dir;
  Scene scene = utm_scene();
  double lon0 = 0, lat0 = 0;  // north-west corner of a land cover covering the scene
  void SetUp() override {
    test::write_file(dir / "lib.toml", kLibrary);
    GeoFrame frame(scene.crs_wkt, "scene");
    auto [lon_a, lat_a] = frame.lonlat_from_scene(scene.origin_x_m - 100, scene.origin_y_m + 100);
    lon0 = std::floor(lon_a * 1e4) / 1e4;
    lat0 = std::ceil(lat_a * 1e4) / 1e4;
  }
  std::filesystem::path mapping(const std::string& extra_head, const std::string& classes) {
    test::write_file(dir / "map.toml", "[mapping]\nname = \"test\"\nlibrary = \"lib.toml\"\n" +
                                           extra_head + "\n[classes]\n" + classes);
    return dir / "map.toml";
  }
};

using LandCover = Fixture;

TEST_F(LandCover, NearestCodeOfEachCellCentreIsMapped) {
  // Codes vary with every pixel so that any shift would show.
  auto code_of = [](int c, int r) { return std::uint16_t(10 + (c / 3 + r / 2) % 4 * 10); };
  write_landcover(dir / "lc.tif", lon0, lat0, 120, 80, code_of);
  LandCoverMapping m = read_landcover_mapping(
      mapping("", "10 = \"forest\"\n20 = \"grass\"\n30 = \"water\"\n40 = 5\n"));
  EXPECT_EQ(m.classes.at(10), 3);
  EXPECT_EQ(m.classes.at(40), 5);
  LandCoverStats st = apply_landcover(scene, dir / "lc.tif", m);
  EXPECT_EQ(st.mapped_cells, scene.size());
  const std::map<int, std::uint16_t> expect_cat{{10, 3}, {20, 2}, {30, 4}, {40, 5}};
  GeoFrame frame(scene.crs_wkt, "scene");
  int mismatches = 0;
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      auto [x, y] = scene.cell_centre(r, c);
      auto [lon, lat] = frame.lonlat_from_scene(x, y);
      const int pc = static_cast<int>(std::floor((lon - lon0) / 1e-4));
      const int pr = static_cast<int>(std::floor((lat0 - lat) / 1e-4));
      mismatches += scene.category[scene.index(r, c)] != expect_cat.at(code_of(pc, pr));
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_EQ(st.metadata.at("RIS_LANDCOVER"), "lc.tif");
}

TEST_F(LandCover, UnmappedCodesAreListedUnlessADefaultIsSet) {
  write_landcover(dir / "lc.tif", lon0, lat0, 120, 80, [](int c, int) {
    return std::uint16_t(c < 40 ? 10 : c < 80 ? 12 : 99);
  });
  LandCoverMapping m = read_landcover_mapping(mapping("", "10 = \"forest\"\n"));
  try {
    Scene s = scene;
    apply_landcover(s, dir / "lc.tif", m);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("map.toml"), std::string::npos) << what;
    EXPECT_NE(what.find("12 ("), std::string::npos) << what;
    EXPECT_NE(what.find("99 ("), std::string::npos) << what;
    EXPECT_EQ(what.find("10 ("), std::string::npos) << what;
  }
  LandCoverMapping with_default =
      read_landcover_mapping(mapping("default = \"rock\"", "10 = \"forest\"\n"));
  LandCoverStats st = apply_landcover(scene, dir / "lc.tif", with_default);
  EXPECT_GT(st.default_cells, 0u);
  EXPECT_EQ(st.default_cells + st.mapped_cells, scene.size());
  EXPECT_EQ(st.cells_per_category.at(7), st.default_cells);
}

TEST_F(LandCover, NonOverlappingLandCoverIsRefused) {
  write_landcover(dir / "far.tif", lon0 + 1.0, lat0, 50, 50, [](int, int) { return 10; });
  LandCoverMapping m = read_landcover_mapping(mapping("", "10 = \"forest\"\n"));
  try {
    apply_landcover(scene, dir / "far.tif", m);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("far.tif"), std::string::npos) << what;
    EXPECT_NE(what.find("does not overlap"), std::string::npos) << what;
  }
}

TEST_F(LandCover, CellsWithoutLandCoverAreMaskedOrFilled) {
  // The land cover covers only the western part of the scene, with a no-data
  // code block inside.
  const double lon_mid = lon0 + 0.0030;  // ~250 m east of the corner
  const int cols = static_cast<int>(std::round((lon_mid - lon0) / 1e-4));
  write_landcover(
      dir / "west.tif", lon0, lat0, cols, 80,
      [](int c, int r) { return std::uint16_t(c > 5 && c < 10 && r > 5 && r < 10 ? 0 : 20); }, 0.0);
  LandCoverMapping m = read_landcover_mapping(mapping("", "20 = \"grass\"\n"));
  Scene masked = scene;
  LandCoverStats st = apply_landcover(masked, dir / "west.tif", m);
  EXPECT_GT(st.unfilled_cells, 0u);
  EXPECT_EQ(st.unfilled_cells + st.mapped_cells, scene.size());
  std::size_t nodata = 0;
  for (auto v : masked.valid) nodata += v == 0;
  EXPECT_EQ(nodata, st.unfilled_cells);

  LandCoverMapping filled =
      read_landcover_mapping(mapping("fill = \"bare soil\"", "20 = \"grass\"\n"));
  Scene f = scene;
  LandCoverStats st2 = apply_landcover(f, dir / "west.tif", filled);
  EXPECT_EQ(st2.fill_cells, st.unfilled_cells);
  EXPECT_EQ(st2.cells_per_category.at(1), st2.fill_cells);
  // DEM no-data cells stay no-data whatever the land cover says.
  Scene holed = scene;
  holed.valid[0] = 0;
  holed.category[0] = kNoDataCategory;
  apply_landcover(holed, dir / "west.tif", filled);
  EXPECT_EQ(holed.valid[0], 0);
  EXPECT_EQ(holed.category[0], kNoDataCategory);
}

TEST_F(LandCover, MappingFileErrorsNameFileAndKey) {
  auto expect_error = [&](const std::string& head, const std::string& classes,
                          const std::string& needle) {
    try {
      read_landcover_mapping(mapping(head, classes));
      FAIL() << "expected an InputError for " << needle;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  expect_error("", "10 = \"meadow\"\n", "unknown category \"meadow\"");
  expect_error("", "ten = \"grass\"\n", "classes.ten");
  expect_error("colour = 3", "10 = \"grass\"\n", "mapping.colour");
  expect_error("", "10 = 70000\n", "classes.10");
  expect_error("default = \"lava\"", "10 = \"grass\"\n", "mapping.default");
  EXPECT_THROW(read_landcover_mapping(dir / "missing.toml"), InputError);
}

TEST_F(LandCover, ShippedMappingsResolveAgainstTheGenericTerrainLibrary) {
  const std::string data = ris::test::data_dir();
  const auto names = read_category_names(data + "/backscatter/generic-terrain.toml");
  LandCoverMapping wc = read_landcover_mapping(data + "/landcover/esa-worldcover.toml");
  EXPECT_EQ(wc.classes.size(), 11u);
  EXPECT_EQ(wc.classes.at(10), names.at("forest"));
  EXPECT_EQ(wc.classes.at(50), names.at("urban"));
  EXPECT_EQ(wc.classes.at(70), names.at("snow"));
  EXPECT_EQ(wc.classes.at(80), names.at("water"));
  EXPECT_EQ(wc.nodata_codes, (std::set<std::int64_t>{0}));
  LandCoverMapping clc = read_landcover_mapping(data + "/landcover/corine.toml");
  EXPECT_EQ(clc.classes.size(), 88u);
  // Raster grid codes 1..44 and three-digit codes agree class by class.
  const int three_digit[44] = {111, 112, 121, 122, 123, 124, 131, 132, 133, 141, 142,
                               211, 212, 213, 221, 222, 223, 231, 241, 242, 243, 244,
                               311, 312, 313, 321, 322, 323, 324, 331, 332, 333, 334,
                               335, 411, 412, 421, 422, 423, 511, 512, 521, 522, 523};
  for (int g = 1; g <= 44; ++g) {
    EXPECT_EQ(clc.classes.at(g), clc.classes.at(three_digit[g - 1])) << g;
  }
  EXPECT_EQ(clc.classes.at(332), names.at("rock"));
  EXPECT_EQ(clc.classes.at(122), names.at("road"));
  EXPECT_EQ(clc.classes.at(523), names.at("water"));
}

}  // namespace
}  // namespace ris
