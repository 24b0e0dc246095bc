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
#include "ris/util/units.h"
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
  ASSERT_EQ(run_kind_name(by_path), "slar");
  const auto* a = std::get_if<SlarRun>(&by_path.run);
  const auto* b = std::get_if<SlarRun>(&loaded.run);
  ASSERT_TRUE(a != nullptr && b != nullptr);
  EXPECT_EQ(loaded.scene, r.scene);  // shared, not copied
  EXPECT_TRUE(same_floats(a->sim.image.mean_power_w, b->sim.image.mean_power_w));
  EXPECT_TRUE(same_floats(a->pictures.speckled_power_w, b->pictures.speckled_power_w));
  EXPECT_EQ(by_path.write_seconds, 0.0);  // no out_dir: nothing written
}

// Re-rendering the kept simulation with another seed gives what a fresh run
// with that seed gives; the mean power is untouched. New film constants
// change the greytones only.
TEST(RunSimulation, RerenderEqualsAFreshRunWithThatSeed) {
  RunResult res = run_simulation(standard_request());
  const SlarRun& run = std::get<SlarRun>(res.run);
  const UninitVector<float> mean = run.sim.image.mean_power_w;
  rerender(res, 11);
  RunRequest r11 = standard_request();
  r11.seed = 11;
  const RunResult fresh_res = run_simulation(r11);
  const SlarRun& fresh = std::get<SlarRun>(fresh_res.run);
  EXPECT_TRUE(same_floats(run.sim.image.mean_power_w, mean));
  EXPECT_TRUE(same_floats(run.pictures.speckled_power_w, fresh.pictures.speckled_power_w));
  EXPECT_TRUE(std::equal(run.pictures.slant_grey.begin(), run.pictures.slant_grey.end(),
                         fresh.pictures.slant_grey.begin()));
  EXPECT_EQ(res.info.seed, 11u);
  FilmParams film = run.sim.radar.film;
  film.gamma *= 2.0;
  rerender(res, 11, &film);
  EXPECT_TRUE(same_floats(run.pictures.speckled_power_w, fresh.pictures.speckled_power_w));
  EXPECT_FALSE(std::equal(run.pictures.slant_grey.begin(), run.pictures.slant_grey.end(),
                          fresh.pictures.slant_grey.begin()));
}

// A swath over less than half of the scene is a warning of the run's
// summary (issue 38; a streamed run's: MessagesCli); metadata.json does not
// hold it (products of runs valid before keep their bytes).
TEST(RunSimulation, ASwathOverPartOfTheSceneIsASummaryWarning) {
  RunRequest r = standard_request();
  RadarParams radar = load_radar(kRadar);
  // 12,000 ft farther out: ground range 33.5 .. 39.7 km (R = 35.7 .. 41.6
  // km, H = 12.2 km; MODEL.md section 2) over the scene's 37.2 .. 43.3 km.
  radar.track.near_edge_ground_m += 12000 * kFeetToMetres;
  r.radar = radar;
  test::TempDir out;
  r.out_dir = out.path();
  const RunSummary s = run_summary(run_simulation(r));
  ASSERT_EQ(s.warnings.size(), 1u);
  EXPECT_TRUE(
      s.warnings[0].starts_with("the swath images 2.6 km of the scene's 6.1 km across "
                                "track (near side)"))
      << s.warnings[0];
  EXPECT_EQ(test::read_file(out / "metadata.json").find("the swath images"), std::string::npos);
  // The shipped radar images most of it: nothing said.
  EXPECT_TRUE(run_summary(run_simulation(standard_request())).warnings.empty());
}

// Each mode's result gives its own summary: the SLAR's lines name its image
// size and geometry counts (values as well as text), a PPI's its B-scope;
// the kind is computed from the result, the strategy is a property.
TEST(RunSimulation, EachModeSummarisesItself) {
  const RunResult slar = run_simulation(standard_request());
  const RunSummary s = run_summary(slar);
  EXPECT_EQ(s.mode, "SLAR");
  EXPECT_EQ(s.strategy, RunStrategy::in_memory);
  ASSERT_EQ(s.lines.size(), 3u);
  EXPECT_EQ(s.lines[0].text,
            "simulated " + kScene + " (1000 x 700 cells) with " + kRadar + " (SLAR)");
  const SlarRun& run = std::get<SlarRun>(slar.run);
  EXPECT_EQ(s.lines[1].values.at(0).key, "lines");
  EXPECT_EQ(s.lines[1].values.at(0).value, run.sim.image.lines);
  EXPECT_EQ(s.lines[2].values.at(0).unit, "%");
  EXPECT_NE(std::find(s.products.begin(), s.products.end(), "mean_power_slant"), s.products.end());
  const nlohmann::json j = run_summary_json(s);
  EXPECT_EQ(j["strategy"], "in_memory");
  EXPECT_EQ(j["lines"][1]["values"][1]["key"], "bins");

  RunRequest ppi = standard_request();
  ppi.radar_path = std::string(ris::test::data_dir()) + "/radars/ppi-ground-mast-30m.toml";
  const RunResult p = run_simulation(ppi);
  EXPECT_EQ(run_kind_name(p), "ppi");
  EXPECT_EQ(slar_image_run(p), nullptr);
  const RunSummary ps = run_summary(p);
  EXPECT_EQ(ps.mode, "PPI");
  ASSERT_GE(ps.lines.size(), 2u);
  EXPECT_TRUE(ps.lines[1].text.starts_with("  B-scope: 720 rays x 400 range bins"));
  EXPECT_EQ(std::find(ps.products.begin(), ps.products.end(), "mean_power_slant"),
            ps.products.end());
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
