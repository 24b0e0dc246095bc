// Comparing two runs (ris/serve/run_history.h, run_compare.h; issue 38 item
// 1): the difference of two runs in two bands is 10 log10(current /
// earlier) of each pixel's power, read back through the inspector; the
// difference picture's colour is the key's; runs on another grid are refused
// with what differs; the routes are read-only and go through the server's
// guards (foreign Origin 403, bad parameters 400), as does the linked
// zoom's /api/link.
#include <gtest/gtest.h>
#include <httplib.h>

#include <cmath>
#include <thread>

#include "ris/io/raster_io.h"
#include "ris/scene/scene_io.h"
#include "ris/serve/run_compare.h"
#include "ris/serve/server.h"
#include "test_util.h"

namespace ris {
namespace {

class CompareRuns : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    tmp_ = new test::TempDir();
    std::filesystem::create_directories(tmp_->path() / "web");
    test::write_file(tmp_->path() / "web" / "index.html", "<html>page</html>");
    ServeInputs in;
    in.scene_path = std::string(test::data_dir()) + "/scenes/ku-geometric.toml";
    in.radar_path = std::string(test::data_dir()) + "/radars/seed-fig4-5.toml";
    in.data_dir = test::data_dir();
    in.out_dir = tmp_->path() / "out";
    session_ = new Session(in);
    ServerOptions o;
    o.port = 0;
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
  static httplib::Result get(const std::string& path, const httplib::Headers& headers = {}) {
    httplib::Client c("127.0.0.1", port_);
    return c.Get(path.c_str(), headers);
  }
  static httplib::Result post(const std::string& path, const std::string& body) {
    httplib::Client c("127.0.0.1", port_);
    return c.Post(path.c_str(), body, "application/json");
  }
  static nlohmann::json json_of(const httplib::Result& r) { return nlohmann::json::parse(r->body); }

  static test::TempDir* tmp_;
  static Session* session_;
  static HttpServer* server_;
  static std::thread* thread_;
  static int port_;
};

test::TempDir* CompareRuns::tmp_ = nullptr;
Session* CompareRuns::session_ = nullptr;
HttpServer* CompareRuns::server_ = nullptr;
std::thread* CompareRuns::thread_ = nullptr;
int CompareRuns::port_ = 0;

// Two bands on the same grid: the difference is each pixel's dB ratio.
TEST_F(CompareRuns, DifferenceOfTwoBandsIsTheDbRatioOfTheirPixels) {
  auto r = post("/api/simulate", R"({"radar": {"frequency": "9.6 GHz"}})");
  ASSERT_EQ(r->status, 200) << r->body;
  const std::uint64_t earlier = json_of(r)["id"];
  r = post("/api/simulate", R"({"radar": {"frequency": "16 GHz"}})");
  ASSERT_EQ(r->status, 200) << r->body;
  const std::uint64_t current = json_of(r)["id"];
  const nlohmann::json runs = json_of(get("/api/runs"));
  EXPECT_EQ(runs["current"], current);
  bool listed = false;
  for (const auto& k : runs["runs"]) {
    if (k["id"] == earlier) listed = k["comparable"].get<bool>();
  }
  EXPECT_TRUE(listed) << runs.dump();
  for (const std::string quantity : {"mean", "speckled"}) {
    r = get("/api/compare?earlier=" + std::to_string(earlier) + "&quantity=" + quantity);
    ASSERT_EQ(r->status, 200) << r->body;
    const nlohmann::json cmp = json_of(r);
    const double range = cmp["range_db"];
    EXPECT_EQ(cmp["key"].size(), 11u);
    EXPECT_DOUBLE_EQ(cmp["key"][0]["db"].get<double>(), -range);
    EXPECT_DOUBLE_EQ(cmp["key"][10]["db"].get<double>(), range);
    // The difference picture, decoded.
    r = get(cmp["images"]["difference"].get<std::string>());
    ASSERT_EQ(r->status, 200);
    test::write_file(tmp_->path() / "d.png", r->body);
    const RasterF64 png = read_raster_f64(tmp_->path() / "d.png");
    const std::string key = quantity == "mean" ? "mean_power_w" : "speckled_power_w";
    int checked = 0;
    for (int y = 100; y < 700; y += 125) {
      for (int x = 20; x < 241; x += 50) {
        const std::string xy = "&x=" + std::to_string(x) + "&y=" + std::to_string(y);
        const nlohmann::json now = json_of(get("/api/inspect?view=slant" + xy));
        const nlohmann::json then =
            json_of(get("/api/inspect?view=slant&run=" + std::to_string(earlier) + xy));
        const nlohmann::json px =
            json_of(get("/api/compare/pixel?earlier=" + std::to_string(earlier) +
                        "&quantity=" + quantity + xy));
        if (!(now[key].is_number() && then[key].is_number() && now[key].get<double>() > 0.0 &&
              then[key].get<double>() > 0.0)) {
          // Shadow (no power) or no data: no finite difference, transparent.
          EXPECT_TRUE(px["difference_db"].is_null()) << px.dump();
          const std::size_t a = (3 * static_cast<std::size_t>(png.rows) + y) * png.cols + x;
          EXPECT_EQ(png.data[a], 0.0);
          continue;
        }
        const double expected = 10.0 * std::log10(now[key].get<double>() / then[key].get<double>());
        ASSERT_TRUE(px["difference_db"].is_number()) << px.dump();
        EXPECT_NEAR(px["difference_db"].get<double>(), expected, 1e-9 + 1e-6 * std::abs(expected));
        // The pixel's colour is the ramp's at that difference.
        const auto rgb = difference_colour(px["difference_db"].get<double>(), range);
        ASSERT_EQ(png.bands, 4);
        for (int c = 0; c < 3; ++c) {
          const std::size_t i = (static_cast<std::size_t>(c) * png.rows + y) * png.cols + x;
          EXPECT_EQ(png.data[i], rgb[static_cast<std::size_t>(c)]) << x << "," << y;
        }
        ++checked;
      }
    }
    EXPECT_GT(checked, 15);
  }
  // A band change raises the mean power of every lit pixel the same way up
  // to the library's dispersion: the difference is not all zero.
  const nlohmann::json px =
      json_of(get("/api/compare/pixel?earlier=" + std::to_string(earlier) + "&x=120&y=350"));
  EXPECT_GT(std::abs(px["difference_db"].get<double>()), 0.01);
}

TEST_F(CompareRuns, AnotherGridIsRefusedSayingWhatDiffers) {
  auto r = post("/api/simulate", R"({"seed": 5})");
  ASSERT_EQ(r->status, 200);
  const std::uint64_t earlier = json_of(r)["id"];
  r = post("/api/simulate", R"({"depression": "22 deg"})");
  ASSERT_EQ(r->status, 200) << r->body;
  r = get("/api/compare?earlier=" + std::to_string(earlier));
  ASSERT_EQ(r->status, 400);
  const std::string e = json_of(r)["error"];
  EXPECT_NE(e.find("not on the same grid"), std::string::npos) << e;
  EXPECT_NE(e.find("near range"), std::string::npos) << e;
  EXPECT_EQ(get("/api/compare/difference.png?earlier=" + std::to_string(earlier))->status, 400);
  ASSERT_EQ(post("/api/simulate", R"({"depression": "20 deg"})")->status, 200);
}

TEST_F(CompareRuns, HostileAndBadRequestsAreRefused) {
  const httplib::Headers evil = {{"Origin", "http://evil.example"}};
  for (const char* path :
       {"/api/runs", "/api/compare?earlier=1", "/api/runs/1/slant.png",
        "/api/compare/difference.png?earlier=1", "/api/compare/pixel?earlier=1&x=0&y=0",
        "/api/inspect?view=slant&run=1&x=0&y=0"}) {
    const auto r = get(path, evil);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 403) << path;
  }
  for (const char* path :
       {"/api/compare?earlier=0", "/api/compare?earlier=x", "/api/compare?earlier=99999",
        "/api/compare?earlier=1&quantity=phase", "/api/compare?earlier=1&range_db=-3",
        "/api/compare?earlier=1&range_db=nan", "/api/compare?earlier=1&range_db=1e9",
        "/api/compare/pixel?earlier=1&x=99999&y=0", "/api/compare/pixel?earlier=1&x=a&y=0",
        "/api/runs/99999/slant.png", "/api/inspect?view=scene&run=1&x=0&y=0",
        "/api/inspect?view=slant&run=1&x=-1&y=0", "/api/link?from=ground&x0=0&y0=0&x1=1&y1=1",
        "/api/link?from=scene&x0=0&y0=0&x1=nan&y1=1", "/api/link?from=scene&x0=5&y0=0&x1=1&y1=1",
        "/api/link?from=scene&x0=0&y0=0&x1=1"}) {
    const auto r = get(path);
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 400) << path << " " << r->body;
  }
}

}  // namespace
}  // namespace ris
