#include "ris/sim/run.h"
#include "build_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "ris/backscatter/library.h"
#include "ris/io/raster_io.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

const std::string kScene = std::string(ris::test::data_dir()) + "/scenes/ku-geometric.toml";
const std::string kRadar = std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml";

RunRequest standard_request() {
  RunRequest r;
  r.scene_path = kScene;
  r.radar_path = kRadar;
  r.seed = 3;
  return r;
}

std::set<std::string> files_in(const std::filesystem::path& dir) {
  std::set<std::string> out;
  for (const auto& f : std::filesystem::directory_iterator(dir))
    out.insert(f.path().filename().string());
  return out;
}

bool same_floats(const UninitVector<float>& a, const UninitVector<float>& b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](float x, float y) {
           return (std::isnan(x) && std::isnan(y)) || x == y;
         });
}

// Inputs given as objects (a server keeps them loaded) give the same run as
// the same inputs given as paths; the result keeps the simulation.
TEST(RunSimulation, LoadedInputsGiveTheSameRunAsPaths) {
  const RunResult by_path = run_simulation(standard_request());
  RunRequest r = standard_request();
  r.scene = std::make_shared<const Scene>(load_scene_source(kScene).scene);
  r.radar = load_radar(kRadar);
  r.sigma0 = load_sigma0_source(default_sigma0_library_path());
  const RunResult loaded = run_simulation(r);
  ASSERT_EQ(by_path.kind, RunKind::slar);
  ASSERT_TRUE(by_path.slar && loaded.slar && by_path.slar_pictures && loaded.slar_pictures);
  EXPECT_EQ(loaded.scene, r.scene);  // shared, not copied
  EXPECT_TRUE(same_floats(by_path.slar->image.mean_power_w, loaded.slar->image.mean_power_w));
  EXPECT_TRUE(
      same_floats(by_path.slar_pictures->speckled_power_w, loaded.slar_pictures->speckled_power_w));
  EXPECT_EQ(by_path.write_seconds, 0.0);  // no out_dir: nothing written
}

// Re-rendering the kept simulation with another seed gives what a fresh run
// with that seed gives; the mean power is untouched. New film constants
// change the greytones only.
TEST(RunSimulation, RerenderEqualsAFreshRunWithThatSeed) {
  RunResult res = run_simulation(standard_request());
  const UninitVector<float> mean = res.slar->image.mean_power_w;
  rerender(res, 11);
  RunRequest r11 = standard_request();
  r11.seed = 11;
  const RunResult fresh = run_simulation(r11);
  EXPECT_TRUE(same_floats(res.slar->image.mean_power_w, mean));
  EXPECT_TRUE(
      same_floats(res.slar_pictures->speckled_power_w, fresh.slar_pictures->speckled_power_w));
  EXPECT_TRUE(std::equal(res.slar_pictures->slant_grey.begin(), res.slar_pictures->slant_grey.end(),
                         fresh.slar_pictures->slant_grey.begin()));
  EXPECT_EQ(res.info.seed, 11u);
  FilmParams film = res.slar->radar.film;
  film.gamma *= 2.0;
  rerender(res, 11, &film);
  EXPECT_TRUE(
      same_floats(res.slar_pictures->speckled_power_w, fresh.slar_pictures->speckled_power_w));
  EXPECT_FALSE(std::equal(res.slar_pictures->slant_grey.begin(),
                          res.slar_pictures->slant_grey.end(),
                          fresh.slar_pictures->slant_grey.begin()));
}

// --products writes only the products asked for (and metadata.json, which
// lists them); every --compress preset writes the same pixels.
TEST(RunSimulation, ProductSelectionAndCompressionPresets) {
  test::TempDir dir;
  RunResult res = run_simulation(standard_request());
  res.info.products.stems = {"slant_range", "mean_power_slant", "shadowmap"};
  write_run_products(res, dir / "some");
  EXPECT_EQ(files_in(dir / "some"),
            (std::set<std::string>{"slant_range.png", "mean_power_slant.tif", "shadowmap.txt",
                                   "metadata.json"}));
  const std::string meta = test::read_file(dir / "some" / "metadata.json");
  EXPECT_NE(meta.find("\"mean_power_slant.tif\""), std::string::npos);
  EXPECT_EQ(meta.find("\"scene_mask.tif\""), std::string::npos);

  res.info.products.stems.clear();
  for (const CompressionPreset p :
       {CompressionPreset::fast, CompressionPreset::small, CompressionPreset::none}) {
    res.info.compression = p;
    write_run_products(res, dir / std::string(to_string(p)));
  }
  EXPECT_EQ(files_in(dir / "fast").size(), 12u);
  for (const std::string& f : files_in(dir / "fast")) {
    if (f.ends_with(".txt") || f.ends_with(".json")) {
      EXPECT_EQ(test::read_file(dir / "fast" / f), test::read_file(dir / "none" / f)) << f;
      continue;
    }
    const RasterF64 fast = read_raster_f64(dir / "fast" / f);
    for (const char* other : {"small", "none"}) {
      const RasterF64 o = read_raster_f64(dir / other / f);
      ASSERT_EQ(o.data.size(), fast.data.size()) << f;
      EXPECT_TRUE(
          std::equal(o.data.begin(), o.data.end(), fast.data.begin(),
                     [](double x, double y) { return (std::isnan(x) && std::isnan(y)) || x == y; }))
          << f << " " << other;
    }
  }
  EXPECT_LT(std::filesystem::file_size(dir / "small" / "geocoded_grey.tif"),
            std::filesystem::file_size(dir / "none" / "geocoded_grey.tif"));
}

TEST(RunSimulation, BadRequestsNameTheOption) {
  RunRequest r = standard_request();
  r.products.stems = {"slant_range", "bscope"};
  try {
    run_simulation(r);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--products");
    EXPECT_NE(std::string(e.what()).find("\"bscope\""), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("geocoded_grey"), std::string::npos) << e.what();
  }
  r = standard_request();
  r.threads = -1;
  EXPECT_THROW(run_simulation(r), InputError);
  EXPECT_THROW(parse_compression_preset("tiny", "--compress"), InputError);
  EXPECT_EQ(parse_compression_preset("small", "--compress"), CompressionPreset::small);
}

}  // namespace
}  // namespace ris
