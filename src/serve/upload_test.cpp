// Uploads (POST /api/upload) through a real server: a DEM is imported and
// simulated with the library it names; the body cap, the content-type rule
// and the Origin check hold on the upload route; names that are not plain
// file names are refused; hostile rasters (a VRT whose pixels are
// /etc/passwd) read nothing; the working folder holds every upload and goes
// with the session. Also: `--scene` on an imported DEM uses the library the
// scene names, as `ris simulate` does.
#include <gdal.h>
#include <gtest/gtest.h>
#include <httplib.h>

#include <fstream>
#include <sstream>
#include <thread>

#include "ris/backscatter/library.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/serve/server.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

constexpr std::size_t kMaxUpload = 256 * 1024;

std::string read_bytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string dem_bytes() {
  return read_bytes(std::filesystem::path(test::data_dir()).parent_path() / "tests" / "data" /
                    "dem" / "SanAnd_dem.tif");
}

// The session's working folders under `parent` (ris-serve-XXXXXX).
std::vector<std::filesystem::path> work_folders(const std::filesystem::path& parent) {
  std::vector<std::filesystem::path> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(parent, ec)) {
    if (e.path().filename().string().rfind("ris-serve-", 0) == 0) out.push_back(e.path());
  }
  return out;
}

ServeInputs standard_inputs(const test::TempDir& tmp) {
  ServeInputs in;
  in.scene_path = std::string(test::data_dir()) + "/scenes/ku-geometric.toml";
  in.radar_path = std::string(test::data_dir()) + "/radars/seed-fig4-5.toml";
  in.data_dir = test::data_dir();
  in.out_dir = tmp / "out";
  in.work_parent = tmp / "work";
  std::filesystem::create_directories(in.work_parent);
  return in;
}

class ServeUpload : public ::testing::Test {
 protected:
  void SetUp() override {
    session_ = std::make_unique<Session>(standard_inputs(tmp_));
    ServerOptions o;
    o.port = 0;
    o.max_upload_bytes = kMaxUpload;
    o.web_dir = tmp_ / "web";
    std::filesystem::create_directories(o.web_dir);
    test::write_file(o.web_dir / "index.html", "<html>page</html>");
    server_ = std::make_unique<HttpServer>(*session_, o);
    port_ = server_->bind();
    thread_ = std::thread([this] { server_->run(); });
  }
  void TearDown() override {
    server_->stop();
    thread_.join();
  }

  httplib::Result upload(const std::string& query, const std::string& bytes,
                         const char* type = "application/octet-stream",
                         const httplib::Headers& headers = {}) {
    httplib::Client c("127.0.0.1", port_);
    c.set_url_encode(false);
    return c.Post(("/api/upload?" + query).c_str(), headers, bytes, type);
  }
  nlohmann::json state() {
    httplib::Client c("127.0.0.1", port_);
    return nlohmann::json::parse(c.Get("/api/state")->body);
  }
  std::filesystem::path work() {
    const auto folders = work_folders(tmp_ / "work");
    return folders.size() == 1 ? folders[0] : std::filesystem::path();
  }
  // Every file under the working folder.
  std::vector<std::string> stored() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::recursive_directory_iterator(work())) {
      if (e.is_regular_file()) out.push_back(e.path().filename().string());
    }
    return out;
  }

  test::TempDir tmp_;
  std::unique_ptr<Session> session_;
  std::unique_ptr<HttpServer> server_;
  std::thread thread_;
  int port_ = 0;
};

TEST_F(ServeUpload, DemIsImportedAndSimulatedWithTheLibraryItNames) {
  const auto r = upload("kind=dem&name=SanAnd_dem.tif", dem_bytes());
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const nlohmann::json j = nlohmann::json::parse(r->body);
  EXPECT_EQ(j["uploaded"], "SanAnd_dem.tif");
  // Every cell is the default category, whose library the scene names.
  EXPECT_EQ(j["backscatter"], std::filesystem::path(kDefaultCategoryLibrary).filename().string());
  EXPECT_EQ(j["run"]["map"]["legend"][0]["id"], kDefaultCategory);
  EXPECT_TRUE(j["run"]["map"]["georeferenced"].get<bool>());
  const nlohmann::json s = state();
  EXPECT_FALSE(s["scene"]["editable"].get<bool>());
  EXPECT_EQ(s["scene"]["file"], "scene.tif");  // a name, never the working folder
  // A cell's latitude and longitude lie inside the DEM (gdalinfo:
  // 34.140..34.210 N, 118.440..118.410 W).
  httplib::Client c("127.0.0.1", port_);
  const auto cell = c.Get("/api/inspect?view=scene&x=10&y=10");
  ASSERT_EQ(cell->status, 200) << cell->body;
  const nlohmann::json at = nlohmann::json::parse(cell->body);
  EXPECT_GT(at["lat_deg"].get<double>(), 34.140);
  EXPECT_LT(at["lat_deg"].get<double>(), 34.2102);
  EXPECT_GT(at["lon_deg"].get<double>(), -118.4402);
  EXPECT_LT(at["lon_deg"].get<double>(), -118.410);
  // Only the working folder holds it.
  const std::vector<std::string> files = stored();
  EXPECT_NE(std::find(files.begin(), files.end(), "SanAnd_dem.tif"), files.end());
  EXPECT_FALSE(std::filesystem::exists(tmp_ / "out" / "SanAnd_dem.tif"));
  // Undo returns to the standard scene and its library.
  const auto undo = c.Post("/api/scene/undo", "{}", "application/json");
  ASSERT_EQ(undo->status, 200) << undo->body;
  EXPECT_TRUE(state()["scene"]["editable"].get<bool>());
  EXPECT_EQ(state()["backscatter"], "ku-geometric.toml");
}

TEST_F(ServeUpload, OverTheCapIs413AndStoresNothing) {
  const auto r = upload("kind=dem&name=big.tif", std::string(kMaxUpload + 1, 'x'));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
  EXPECT_NE(r->body.find("--max-upload-mib"), std::string::npos) << r->body;
  EXPECT_TRUE(stored().empty());
  // At the cap, the size is no reason to refuse (the bytes are no raster).
  const auto at_cap = upload("kind=dem&name=big.tif", std::string(kMaxUpload, 'x'));
  ASSERT_TRUE(at_cap);
  EXPECT_EQ(at_cap->status, 400) << at_cap->body;
}

TEST_F(ServeUpload, ContentTypeAndOriginRules) {
  // JSON on the upload route, bytes on a JSON route: 415.
  auto r = upload("kind=dem&name=a.tif", dem_bytes(), "application/json");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 415);
  EXPECT_NE(r->body.find("application/octet-stream"), std::string::npos) << r->body;
  for (const char* type :
       {"text/plain", "multipart/form-data; boundary=x", "application/x-www-form-urlencoded"}) {
    r = upload("kind=dem&name=a.tif", dem_bytes(), type);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 415) << type;
  }
  httplib::Client c("127.0.0.1", port_);
  const auto sim = c.Post("/api/simulate", "{}", "application/octet-stream");
  ASSERT_TRUE(sim);
  EXPECT_EQ(sim->status, 415);
  // Another page's upload: 403.
  r = upload("kind=dem&name=a.tif", dem_bytes(), "application/octet-stream",
             {{"Origin", "http://evil.example"}});
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 403);
  EXPECT_TRUE(stored().empty());
  EXPECT_TRUE(state()["scene"]["editable"].get<bool>());  // still the description
}

TEST_F(ServeUpload, NamesThatAreNotPlainFileNamesAreRefused) {
  for (const char* name : {"..%2Fescaped.tif", "%2Ftmp%2Fescaped.tif", "a%2Fb.tif", ".hidden.tif",
                           "x..tif", "escaped.so", "escaped", "", "..", "a%20b.tif"}) {
    const auto r = upload(std::string("kind=dem&name=") + name, dem_bytes());
    ASSERT_TRUE(r) << name;
    EXPECT_EQ(r->status, 400) << name << ": " << r->body;
  }
  EXPECT_TRUE(stored().empty());
  EXPECT_FALSE(std::filesystem::exists(tmp_ / "escaped.tif"));
  EXPECT_FALSE(std::filesystem::exists(tmp_ / "work" / "escaped.tif"));
  const auto kind = upload("kind=exe&name=a.tif", dem_bytes());
  ASSERT_TRUE(kind);
  EXPECT_EQ(kind->status, 400);
  EXPECT_NE(kind->body.find("dem, landcover or scene"), std::string::npos);
}

TEST_F(ServeUpload, HostileRastersReadNothing) {
  const std::string raw = R"(<VRTDataset rasterXSize="8" rasterYSize="8">
  <SRS>EPSG:32611</SRS><GeoTransform>368000, 30, 0, 3785000, 0, -30</GeoTransform>
  <VRTRasterBand dataType="Byte" band="1" subClass="VRTRawRasterBand">
    <SourceFilename relativeToVRT="0">/etc/passwd</SourceFilename>
  </VRTRasterBand></VRTDataset>)";
  const std::string simple = R"(<VRTDataset rasterXSize="8" rasterYSize="8">
  <SRS>EPSG:32611</SRS><GeoTransform>368000, 30, 0, 3785000, 0, -30</GeoTransform>
  <VRTRasterBand dataType="Byte" band="1"><SimpleSource>
    <SourceFilename relativeToVRT="0">/etc/passwd</SourceFilename><SourceBand>1</SourceBand>
  </SimpleSource></VRTRasterBand></VRTDataset>)";
  const std::string dotdot = R"(<VRTDataset rasterXSize="8" rasterYSize="8">
  <VRTRasterBand dataType="Float32" band="1"><SimpleSource>
    <SourceFilename relativeToVRT="1">../../../etc/passwd</SourceFilename>
  </SimpleSource></VRTRasterBand></VRTDataset>)";
  const nlohmann::json before = state();
  for (const auto& [name, text] : std::vector<std::pair<std::string, std::string>>{
           {"raw.vrt", raw}, {"raw.tif", raw}, {"simple.vrt", simple}, {"dotdot.tif", dotdot}}) {
    for (const char* kind : {"dem", "scene"}) {
      if (std::string(kind) == "scene" && name.ends_with(".vrt")) continue;
      const auto r = upload(std::string("kind=") + kind + "&name=" + name, text);
      ASSERT_TRUE(r) << name;
      EXPECT_EQ(r->status, 400) << kind << " " << name << ": " << r->body;
      EXPECT_EQ(r->body.find("root:"), std::string::npos) << name;
      EXPECT_EQ(r->body.find(work().string()), std::string::npos) << "a server path: " << r->body;
    }
  }
  // The raw band is refused by name of the rule, not by chance.
  const auto r = upload("kind=dem&name=raw2.vrt", raw);
  EXPECT_NE(r->body.find("raw"), std::string::npos) << r->body;
  const nlohmann::json after = state();
  EXPECT_EQ(after["scene"], before["scene"]);
  EXPECT_EQ(after["backscatter"], before["backscatter"]);
  EXPECT_EQ(after["run"]["id"], before["run"]["id"]);
}

// A land-cover raster of one code (ESA WorldCover 10, tree cover) over the
// DEM, in its own CRS (geographic): mapped through the shipped mapping.
std::string landcover_bytes(const test::TempDir& tmp) {
  const std::filesystem::path path = tmp / "landcover.tif";
  GDALAllRegister();  // this test may run alone (ctest runs each on its own)
  GDALDriverH drv = GDALGetDriverByName("GTiff");
  if (drv == nullptr) ADD_FAILURE() << "no GTiff driver";
  GDALDatasetH ds = GDALCreate(drv, path.c_str(), 60, 60, 1, GDT_Byte, nullptr);
  const double gt[6] = {-118.45, 0.05 / 60, 0.0, 34.22, 0.0, -0.09 / 60};
  GDALSetGeoTransform(ds, const_cast<double*>(gt));
  GDALSetProjection(
      ds,
      R"(GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433],AXIS["Latitude",NORTH],AXIS["Longitude",EAST],AUTHORITY["EPSG","4326"]])");
  std::vector<std::uint8_t> codes(60 * 60, 10);
  if (GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 60, 60, codes.data(), 60, 60, GDT_Byte,
                   0, 0) != CE_None) {
    ADD_FAILURE() << "cannot write the land cover";
  }
  GDALClose(ds);
  return read_bytes(path);
}

TEST_F(ServeUpload, LandCoverOnTheUploadedDem) {
  // Without a DEM first: refused, naming what to do.
  auto r = upload("kind=landcover&name=lc.tif", landcover_bytes(tmp_));
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(r->body.find("upload a DEM first"), std::string::npos) << r->body;
  ASSERT_EQ(upload("kind=dem&name=SanAnd_dem.tif", dem_bytes())->status, 200);
  r = upload("kind=landcover&name=lc.tif&mapping=nope.toml", landcover_bytes(tmp_));
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(r->body.find("mapping"), std::string::npos) << r->body;
  r = upload("kind=landcover&name=lc.tif&mapping=esa-worldcover.toml", landcover_bytes(tmp_));
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const nlohmann::json j = nlohmann::json::parse(r->body);
  EXPECT_EQ(j["backscatter"], "generic-terrain.toml");
  // Every cell with data is forest now (the mapping's 10 = "forest").
  const nlohmann::json& legend = j["run"]["map"]["legend"];
  ASSERT_EQ(legend.size(), 1u) << legend.dump();
  EXPECT_EQ(legend[0]["name"], "forest");
}

TEST_F(ServeUpload, ASceneDescriptionIsEditable) {
  const std::string text = R"(name = "uploaded"
[grid]
rows = 100
cols = 120
cell_size = "20 ft"
base_category = 1
[[object]]
type = "box"
x = "600 ft"
y = "600 ft"
length = "400 ft"
width = "400 ft"
height = "200 ft"
category = 5
)";
  const auto r = upload("kind=scene&name=mine.toml", text);
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const nlohmann::json s = state();
  EXPECT_TRUE(s["scene"]["editable"].get<bool>());
  EXPECT_EQ(s["scene"]["rows"], 100);
  EXPECT_EQ(s["scene"]["file"], "mine.toml");
  // A description too large for memory is refused as on the command line.
  const auto huge = upload("kind=scene&name=huge.toml",
                           "[grid]\nrows = 2000000\ncols = 2000000\ncell_size = 1\n");
  ASSERT_TRUE(huge);
  EXPECT_EQ(huge->status, 400) << huge->body;
  EXPECT_EQ(state()["scene"]["rows"], 100);
}

TEST(ServeUploadFolder, RemovedWithTheSession) {
  test::TempDir tmp;
  std::filesystem::path folder;
  {
    Session session(standard_inputs(tmp));
    session.upload("dem", "SanAnd_dem.tif", "", dem_bytes());
    const auto folders = work_folders(tmp / "work");
    ASSERT_EQ(folders.size(), 1u);
    folder = folders[0];
    EXPECT_TRUE(std::filesystem::exists(folder / "upload-1" / "SanAnd_dem.tif"));
    // Private to the server's user.
    const auto perms = std::filesystem::status(folder).permissions();
    EXPECT_EQ(perms & (std::filesystem::perms::group_all | std::filesystem::perms::others_all),
              std::filesystem::perms::none);
  }
  EXPECT_FALSE(std::filesystem::exists(folder));
}

// `ris serve --scene S` on an imported DEM whose categories only the
// library it names has: the session uses that library, as `ris simulate`.
TEST(ServeSession, UsesTheLibraryTheSceneNames) {
  test::TempDir tmp;
  DemImportOptions options;
  options.category = 20;  // bare soil: generic-terrain.toml, not ku-geometric.toml
  const ImportedDem dem = import_dem(std::filesystem::path(test::data_dir()).parent_path() /
                                         "tests" / "data" / "dem" / "SanAnd_dem.tif",
                                     options);
  RasterMetadata metadata = dem.metadata;
  for (auto& [k, v] : backscatter_library_metadata(
           (std::filesystem::path(test::data_dir()) / kDefaultCategoryLibrary).string())) {
    metadata[k] = v;
  }
  write_scene_geotiff(dem.scene, tmp / "imported.tif", metadata);
  ServeInputs in = standard_inputs(tmp);
  in.scene_path = (tmp / "imported.tif").string();
  Session session(in);
  EXPECT_EQ(session.state()["backscatter"], "generic-terrain.toml");
  // --backscatter still wins (and this library has no category 20).
  in.backscatter_path = default_sigma0_library_path();
  EXPECT_THROW(Session{in}, InputError);
}

TEST(ServeSession, AllowExtrapolationIsASimulateKey) {
  test::TempDir tmp;
  Session session(standard_inputs(tmp));
  EXPECT_FALSE(session.state()["allow_extrapolation"].get<bool>());
  const SimulateOutcome out = session.simulate(R"({"allow_extrapolation": true})");
  EXPECT_FALSE(out.run["film_only"].get<bool>());  // the library is loaded again
  EXPECT_TRUE(session.state()["allow_extrapolation"].get<bool>());
  EXPECT_THROW(session.simulate(R"({"allow_extrapolation": "yes"})"), InputError);
}

}  // namespace
}  // namespace ris
