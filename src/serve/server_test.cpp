// The HTTP API, through a real server on a loopback port and httplib's
// client: bad input is refused with the command line's message, bodies over
// the cap with 413, and no request reads a file outside what the server was
// given (path traversal, URL-encoded or not).
#include "ris/serve/server.h"

#include <gtest/gtest.h>
#include <httplib.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "ris/io/config_table.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

constexpr const char* kSecret = "secret-file-content-7f3a";
constexpr std::size_t kMaxBody = 4096;

class ServeApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    tmp_ = new test::TempDir();
    std::filesystem::create_directories(tmp_->path() / "web");
    test::write_file(tmp_->path() / "web" / "index.html", "<html>page</html>");
    test::write_file(tmp_->path() / "secret.txt", kSecret);
    ServeInputs in;
    in.scene_path = std::string(test::data_dir()) + "/scenes/ku-geometric.toml";
    in.radar_path = std::string(test::data_dir()) + "/radars/seed-fig4-5.toml";
    in.data_dir = test::data_dir();
    in.out_dir = tmp_->path() / "out";
    session_ = new Session(in);
    ServerOptions o;
    o.port = 0;
    o.max_body_bytes = kMaxBody;
    o.web_dir = tmp_->path() / "web";
    server_ = new HttpServer(*session_, o);
    port_ = server_->bind();
    thread_ = new std::thread([] { server_->run(); });
  }
  static void TearDownTestSuite() {
    server_->stop();
    thread_->join();
    delete thread_;
    delete server_;
    delete session_;
    delete tmp_;
  }

  static httplib::Client client() {
    httplib::Client c("127.0.0.1", port_);
    c.set_url_encode(false);  // send paths exactly as written
    // A thermal view of the standard scene takes seconds on a loaded 2-core
    // machine (httplib's default read timeout is 5 s).
    c.set_read_timeout(120, 0);
    return c;
  }
  static httplib::Result post(const std::string& path, const std::string& body) {
    return client().Post(path.c_str(), body, "application/json");
  }
  static nlohmann::json json_of(const httplib::Result& r) { return nlohmann::json::parse(r->body); }

  static test::TempDir* tmp_;
  static Session* session_;
  static HttpServer* server_;
  static std::thread* thread_;
  static int port_;
};

test::TempDir* ServeApi::tmp_ = nullptr;
Session* ServeApi::session_ = nullptr;
HttpServer* ServeApi::server_ = nullptr;
std::thread* ServeApi::thread_ = nullptr;
int ServeApi::port_ = 0;

TEST_F(ServeApi, HealthAndState) {
  auto r = client().Get("/api/health");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(json_of(r)["ok"], true);
  r = client().Get("/api/state");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  const nlohmann::json s = json_of(r);
  EXPECT_EQ(s["scene"]["rows"], 700);
  EXPECT_EQ(s["scene"]["cols"], 1000);
  EXPECT_TRUE(s["scene"]["editable"].get<bool>());
}

TEST_F(ServeApi, BadJsonIsRefused) {
  const auto r = post("/api/simulate", "{\"seed\": 3,");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(json_of(r)["error"].get<std::string>().find("not valid JSON"), std::string::npos);
}

TEST_F(ServeApi, UnknownRadarKeyGivesTheCliMessage) {
  // What `ris simulate` prints for the same key in the radar file.
  const std::string radar_path = std::string(test::data_dir()) + "/radars/seed-fig4-5.toml";
  toml::table doc = parse_toml_file(radar_path);
  doc.insert("frequncy", "9 GHz");
  std::string cli_message;
  try {
    radar_from_toml(doc, radar_path);
  } catch (const InputError& e) {
    cli_message = e.what();
  }
  ASSERT_NE(cli_message.find("frequncy"), std::string::npos);
  // The server names the file without its folder (ris/serve/client_paths.h).
  cli_message = cli_message.substr(cli_message.find("seed-fig4-5.toml"));
  const auto r = post("/api/simulate", R"({"radar": {"frequncy": "9 GHz"}})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(json_of(r)["error"], cli_message);
}

TEST_F(ServeApi, UnknownAndBadTopLevelKeys) {
  auto r = post("/api/simulate", R"({"sed": 3})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(json_of(r)["error"].get<std::string>().find("sed"), std::string::npos);
  r = post("/api/simulate", R"({"radar": {"frequency": "-3 GHz"}})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(json_of(r)["error"].get<std::string>().find("frequency"), std::string::npos);
  r = post("/api/simulate", R"({"depression": "95 deg"})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  r = post("/api/simulate", R"({"backscatter": "../../etc/passwd"})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
}

TEST_F(ServeApi, OversizeBodyIsRefused) {
  const std::string body = "{\"seed\": 1, \"pad\": \"" + std::string(2 * kMaxBody, 'x') + "\"}";
  const auto r = post("/api/simulate", body);
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 413);
}

TEST_F(ServeApi, PathTraversalReadsNothing) {
  for (const char* path :
       {"/../secret.txt", "/../../etc/passwd", "/%2e%2e/secret.txt", "/%2E%2E%2Fsecret.txt",
        "/..%2fsecret.txt", "/%2e%2e%2f%2e%2e%2fetc%2fpasswd", "/web/../secret.txt", "//etc/passwd",
        "/api/products/..%2f..%2fsecret.txt", "/api/products/../../secret.txt",
        "/api/image/..%2f..%2fsecret.png"}) {
    const auto r = client().Get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_TRUE(r->status == 404 || r->status == 400) << path << ": " << r->status;
    EXPECT_EQ(r->body.find(kSecret), std::string::npos) << path;
    EXPECT_EQ(r->body.find("root:"), std::string::npos) << path;
  }
  const auto index = client().Get("/");
  ASSERT_TRUE(index);
  EXPECT_EQ(index->body, "<html>page</html>");
  // A save name cannot leave the output folder.
  for (const char* name : {"../escaped", "..", "/tmp/escaped", "a/b", "%2e%2e"}) {
    const auto r = post("/api/scene/save", nlohmann::json{{"name", name}}.dump());
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(tmp_->path() / "escaped.toml"));
}

// The PNG's width and height from its IHDR chunk (bytes 16-23, big-endian).
std::pair<std::uint32_t, std::uint32_t> png_size(const std::string& png) {
  auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(png[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

// The optical and thermal views of the scene: PNGs on the scene's grid (the
// standard scene: 1000 x 700 cells, its crops' table), another picture at
// another time of day, the same bytes asked twice; a bad kind or minute is
// a 400 naming the parameter.
TEST_F(ServeApi, SensorViewsLieOnTheScenesGrid) {
  const auto optical = client().Get("/api/sensor/optical.png");
  ASSERT_TRUE(optical);
  ASSERT_EQ(optical->status, 200) << optical->body;
  EXPECT_EQ(optical->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(png_size(optical->body), (std::pair<std::uint32_t, std::uint32_t>{1000, 700}));
  const auto evening = client().Get("/api/sensor/optical.png?minute=1080");
  ASSERT_TRUE(evening);
  ASSERT_EQ(evening->status, 200);
  EXPECT_NE(evening->body, optical->body);
  const auto thermal = client().Get("/api/sensor/thermal.png?minute=780");
  ASSERT_TRUE(thermal);
  ASSERT_EQ(thermal->status, 200) << thermal->body;
  EXPECT_EQ(client().Get("/api/sensor/thermal.png?minute=780")->body, thermal->body);
  for (const char* bad : {"/api/sensor/radar.png", "/api/sensor/optical.png?minute=1440",
                          "/api/sensor/optical.png?minute=noon"}) {
    const auto r = client().Get(bad);
    ASSERT_TRUE(r) << bad;
    EXPECT_EQ(r->status, 400) << bad;
    EXPECT_TRUE(r->body.find("kind") != std::string::npos ||
                r->body.find("minute") != std::string::npos)
        << r->body;
  }
}

TEST_F(ServeApi, SimulateFilmOnlyAndImages) {
  auto r = post("/api/simulate", R"({"seed": 5})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const nlohmann::json first = json_of(r);
  const auto png1 = client().Get("/api/image/slant.png");
  ASSERT_TRUE(png1);
  ASSERT_EQ(png1->status, 200);
  EXPECT_EQ(png1->body.substr(1, 3), "PNG");
  r = post("/api/simulate", R"({"radar": {"film": {"gamma": 1.2}}})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const nlohmann::json second = json_of(r);
  EXPECT_TRUE(second["film_only"].get<bool>());
  EXPECT_EQ(second["id"].get<int>(), first["id"].get<int>() + 1);
  const auto png2 = client().Get("/api/image/slant.png");
  ASSERT_TRUE(png2);
  EXPECT_NE(png1->body, png2->body);  // steeper film: other greytones
  r = post("/api/simulate", R"({"radar": {"film": {"gamma": 0.6}}})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  for (const char* view : {"ground", "geocoded", "scene"}) {
    const auto img = client().Get((std::string("/api/image/") + view + ".png").c_str());
    ASSERT_TRUE(img);
    EXPECT_EQ(img->status, 200) << view;
  }
  const auto overlay = client().Get("/api/overlay/scene.png?masks=shadow,layover,backfacing");
  ASSERT_TRUE(overlay);
  EXPECT_EQ(overlay->status, 200);
  const auto bad = client().Get("/api/overlay/scene.png?masks=shade");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
}

TEST_F(ServeApi, FadingOffIsFilmOnlyAndIgnoresTheSeed) {
  auto r = post("/api/simulate", R"({"radar": {"film": {"terms": {"fading": false}}}, "seed": 3})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_TRUE(json_of(r)["film_only"].get<bool>());
  const auto no_fading = client().Get("/api/image/slant.png");
  ASSERT_EQ(post("/api/simulate", R"({"seed": 4})")->status, 200);
  const auto other_seed = client().Get("/api/image/slant.png");
  ASSERT_TRUE(no_fading && other_seed);
  EXPECT_EQ(no_fading->body, other_seed->body);  // no speckle: the seed does nothing
  r = post("/api/simulate", R"({"radar": {"film": {"terms": {"fading": true}}}})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  const auto fading = client().Get("/api/image/slant.png");
  ASSERT_TRUE(fading);
  EXPECT_NE(fading->body, other_seed->body);
}

TEST_F(ServeApi, DepressionSetsNearRange) {
  const auto r = post("/api/simulate", R"({"depression": "25 deg"})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  // R_near = H / sin(depression), H = 40,000 ft.
  const double expected_m = 40000.0 * 0.3048 / std::sin(25.0 * 3.14159265358979323846 / 180.0);
  EXPECT_NEAR(json_of(r)["near_range_m"].get<double>(), expected_m, 1e-3);
  ASSERT_EQ(post("/api/simulate", R"({"depression": "20 deg"})")->status, 200);
}

TEST_F(ServeApi, InspectorReadsAPixel) {
  auto r = client().Get("/api/inspect?view=slant&x=10&y=300");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const nlohmann::json s = json_of(r);
  const nlohmann::json state = json_of(client().Get("/api/state"));
  const double near = state["run"]["near_range_m"];
  const double bin = state["run"]["range_bin_m"];
  EXPECT_NEAR(s["slant_range_m"].get<double>(), near + 10.5 * bin, 1e-6);
  EXPECT_TRUE(s.contains("greytone"));
  // The ground image's pixel and the slant pixel at its range.
  r = client().Get("/api/inspect?view=ground&x=100&y=300");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const nlohmann::json g = json_of(r);
  ASSERT_TRUE(g.contains("pixel"));
  const double H = 40000 * 0.3048;
  const double R = g["pixel"]["slant_range_m"];
  // The slant bin holds the ground pixel's range, within half a bin; h_ref is
  // 0 (the standard scene's median elevation).
  EXPECT_NEAR(std::hypot(g["ground_range_m"].get<double>(), H), R, 0.5 * bin + 1e-6);
  r = client().Get("/api/inspect?view=scene&x=500&y=100");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_TRUE(json_of(r).contains("category"));
  r = client().Get("/api/inspect?view=slant&x=99999&y=0");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  r = client().Get("/api/inspect?view=slant&x=ten&y=0");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
}

TEST_F(ServeApi, EditUndoAndSaveTheScene) {
  const nlohmann::json before = json_of(client().Get("/api/state"));
  const std::size_t objects = before["scene"]["description"]["object"].size();
  const auto scene_before =
      client().Get(before["run"]["images"]["scene"].get<std::string>().c_str());
  ASSERT_TRUE(scene_before);
  auto r = post("/api/scene/objects",
                R"({"type": "box", "x": 2500, "y": 600, "length": 300, "width": 300,
                    "height": 200, "category": 5})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(json_of(r)["objects"].size(), objects + 1);
  // The scene picture is cached per scene version: a new URL and new bytes.
  const std::string scene_url = json_of(r)["run"]["images"]["scene"];
  EXPECT_NE(scene_url, before["run"]["images"]["scene"].get<std::string>());
  const auto scene_after = client().Get(scene_url.c_str());
  ASSERT_TRUE(scene_after);
  EXPECT_NE(scene_after->body, scene_before->body);
  // A bad key in an object: the scene parser's message naming the object.
  r = post("/api/scene/objects/" + std::to_string(objects), R"({"heigth": 300})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_NE(json_of(r)["error"].get<std::string>().find("heigth"), std::string::npos);
  r = post("/api/scene/objects/" + std::to_string(objects), R"({"height": 400})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  r = post("/api/scene/save", R"({"name": "edited"})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const auto saved = tmp_->path() / "out" / "edited.toml";
  ASSERT_TRUE(std::filesystem::exists(saved));
  EXPECT_NE(test::read_file(saved).find("height = 400"), std::string::npos);
  ASSERT_EQ(post("/api/scene/undo", "")->status, 200);
  r = post("/api/scene/undo", "");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200);
  EXPECT_EQ(json_of(r)["objects"].size(), objects);
}

TEST_F(ServeApi, ProductsOneByOneAndAsZip) {
  const auto r = post("/api/products", "{}");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  const nlohmann::json files = json_of(r)["files"];
  EXPECT_NE(std::find(files.begin(), files.end(), "metadata.json"), files.end());
  EXPECT_NE(std::find(files.begin(), files.end(), "slant_range.png"), files.end());
  const auto meta = client().Get("/api/products/metadata.json");
  ASSERT_TRUE(meta);
  ASSERT_EQ(meta->status, 200);
  EXPECT_TRUE(nlohmann::json::parse(meta->body).contains("inputs"));
  const auto zip = client().Get("/api/products.zip");
  ASSERT_TRUE(zip);
  ASSERT_EQ(zip->status, 200);
  EXPECT_EQ(zip->body.substr(0, 2), "PK");
}

TEST_F(ServeApi, PresetMessagesNameThePresetFile) {
  auto r = post("/api/simulate", R"({"radar_preset": "seed-fig7.toml"})");
  ASSERT_TRUE(r);
  ASSERT_EQ(r->status, 200) << r->body;
  EXPECT_EQ(json_of(client().Get("/api/state"))["radar"]["file"], "seed-fig7.toml");
  r = post("/api/simulate", R"({"radar": {"pulse_widht": "1 us"}})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  EXPECT_EQ(json_of(r)["error"].get<std::string>().rfind("seed-fig7.toml: ", 0), 0u);
  r = post("/api/simulate", R"({"radar_preset": "no-such-radar.toml"})");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 400);
  ASSERT_EQ(post("/api/simulate", R"({"radar_preset": "seed-fig4-5.toml"})")->status, 200);
}

}  // namespace
}  // namespace ris
