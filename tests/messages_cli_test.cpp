// End-to-end: messages that say what to fix (issue 38, item 4): a
// did-you-mean for a misspelt command, key, enum value or file, a key
// spelled another way named as such, enum values without regard to case,
// and a bare number read in its default unit named with an example.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "build_paths.h"
#include "refusal_checks.h"
#include "ris/scene/scene.h"
#include "ris/scene/scene_io.h"
#include "test_inputs.h"
#include "test_util.h"

namespace ris {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;
using test::q;

using test::data;

// The shipped seed-fig4-5 radar with `from` replaced by `to` (once).
fs::path radar_edited(const test::TempDir& dir, const std::string& from, const std::string& to) {
  std::string text = test::read_file(data("radars/seed-fig4-5.toml"));
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  const fs::path out = dir / "radar.toml";
  test::write_file(out, text);
  return out;
}

// A run of the small SLAR (tests/test_inputs.h) over a flat scene of 60 x
// 200 cells of 10 m (x 0 .. 2000 m, y 0 .. 600 m), its [track] table's
// keys replaced by `track_keys`.
struct SmallRun {
  test::TempDir dir;
  fs::path scene = dir / "scene.tif", radar = dir / "radar.toml", library = dir / "library.toml";
  explicit SmallRun(const std::string& track_keys, const std::string& swath_keys = "",
                    float hill_m = 0.0f) {
    Scene s = Scene::flat(60, 200, 10.0, 0.0f, 1);
    s.elevation_m[s.index(30, 100)] = hill_m;
    write_scene_geotiff(s, scene);
    std::string text = test::kSmallSlarRadar;
    text = text.substr(0, text.find("[track]"));
    if (!swath_keys.empty()) {
      text.replace(text.find("sweep_delay"),
                   text.find("azimuth_beamwidth") - text.find("sweep_delay"), swath_keys);
    }
    test::write_file(radar, text + "[track]\n" + track_keys);
    test::write_file(library, test::constant_gamma_library({{1, "grass", -12.0, ""}}));
  }
  test::RunResult run(const std::string& extra = "") const {
    return test::run_ris("simulate --quiet --scene " + q(scene) + " --radar " + q(radar) +
                         " --backscatter " + q(library) + " --out " + q(dir / "out") + " " + extra);
  }
};

TEST(MessagesCli, ARadarLookingAwayFromTheSceneNamesLookSide) {
  // The track runs north 4 km west of the scene: the scene is on its right.
  const std::string west =
      "altitude = \"3000 m\"\nstart = [\"-4000 m\", \"0 m\"]\n"
      "end = [\"-4000 m\", \"600 m\"]\n";
  for (const char* how : {"", "--stream"}) {
    const auto r = SmallRun(west + "look_side = \"left\"\n").run(how);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_THAT(r.output, HasSubstr("'track.look_side': the radar looks left of its track, but "
                                    "the whole scene lies on the track's right (4000 to 6000 m "
                                    "from it)"));
    EXPECT_THAT(r.output, HasSubstr("expected look_side = \"right\", or track.start and "
                                    "track.end swapped"));
    EXPECT_THAT(r.output, Not(HasSubstr("sweep_delay")));
    EXPECT_THAT(r.output, Not(HasSubstr("inf")));
  }
  EXPECT_EQ(SmallRun(west + "look_side = \"right\"\n").run().exit_code, 0);
  // Wholly behind the start of a track that flies north from y = 1 km.
  auto r = SmallRun(
               "altitude = \"3000 m\"\nstart = [\"-4000 m\", \"1000 m\"]\n"
               "end = [\"-4000 m\", \"3000 m\"]\n")
               .run();
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("'track.start': the whole scene lies behind the start of the "
                                  "track (-1000 to -400 m along it"));
  // Wholly past its end.
  r = SmallRun(
          "altitude = \"3000 m\"\nstart = [\"-4000 m\", \"-3000 m\"]\n"
          "end = [\"-4000 m\", \"-1000 m\"]\n")
          .run();
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("'track.end': the whole scene lies past the end of the track"));
}

TEST(MessagesCli, ASwathBeyondASceneInViewNamesSweepDelay) {
  // On the looked side, but the swath (from 80 us: 12 km) lies beyond it.
  const auto r = SmallRun("altitude = \"3000 m\"\nnear_edge_distance = \"4000 m\"\n",
                          "sweep_delay = \"80 us\"\nsweep_length = \"10 us\"\n")
                     .run();
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("'sweep_delay': the swath (slant range 11991.7 to 13490.7 m) "
                                  "misses the scene, which spans slant range 5004.0 to 6703.7 m"));
}

TEST(MessagesCli, AnAltitudeAtOrBelowTheTerrainNamesAltitude) {
  const std::string track = "altitude = \"3000 m\"\nnear_edge_distance = \"4000 m\"\n";
  for (const char* how : {"", "--stream"}) {
    const auto r = SmallRun(track, "", 3000.0f).run(how);
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_THAT(r.output, HasSubstr("'track.altitude': the terrain reaches 3000.0 m (scene row "
                                    "30, column 100), at or above the sensor altitude 3000.0 m"));
    EXPECT_THAT(r.output, HasSubstr("expected an altitude above 3000.0 m"));
  }
  EXPECT_EQ(SmallRun(track, "", 2999.0f).run().exit_code, 0);
}

TEST(MessagesCli, ASwathOverLessThanHalfTheSceneIsWarnedOf) {
  // A 3 us sweep: slant range 5007 .. 5457 m, ground 4009 .. 4558 m of the
  // scene's 4000 .. 6000 m (MODEL.md section 2), 55 of 200 columns.
  const std::string track = "altitude = \"3000 m\"\nnear_edge_distance = \"4000 m\"\n";
  const std::string narrow = "sweep_delay = \"33.4 us\"\nsweep_length = \"3 us\"\n";
  const std::string said =
      "the swath images 0.5 km of the scene's 2.0 km across track (near side): 28 % of its "
      "cells, on flat ground at the reference height 0 m; widen sweep_length or move the track";
  for (const char* how : {"", "--stream"}) {
    const SmallRun run(track, narrow);
    const auto r = run.run(how);
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_THAT(r.output, HasSubstr(said)) << how;
    // Said, but not written into metadata.json (the run summary's
    // warnings hold it: RunSimulation.ASwathOverPartOfTheSceneIsASummaryWarning).
    EXPECT_THAT(test::read_file(run.dir / "out" / "metadata.json"),
                Not(HasSubstr("the swath images")))
        << how;
  }
  // The default 10 us sweep images 88 % of it: nothing said.
  const auto wide = SmallRun(track).run();
  EXPECT_EQ(wide.exit_code, 0) << wide.output;
  EXPECT_THAT(wide.output, Not(HasSubstr("the swath images")));
}

TEST(MessagesCli, MisspeltCommandsAreNamedWithTheNearestOne) {
  auto r = test::run_ris("simulat --quiet");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("'simulat' is not a command of ris (did you mean \"simulate\"?)"));
  r = test::run_ris("scene biuld x.toml");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("is not a command of ris scene (did you mean \"build\"?)"));
  r = test::run_ris("frobnicate");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("the commands are:"));
  EXPECT_THAT(r.output, Not(HasSubstr("did you mean")));
  EXPECT_EQ(test::run_ris("-v --version").exit_code, 0);
}

TEST(MessagesCli, KeysSpelledAnotherWayAreNamed) {
  test::TempDir dir;
  // A required key written another way: named, with the key it stands for.
  auto r =
      test::run_ris("radar info " + q(radar_edited(dir, "polarisation = ", "polarization = ")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("'polarisation': missing required key; the table has "
                                  "\"polarization\", which is not a key: did you mean "
                                  "\"polarisation\"?"));
  // An optional key: the unknown-key message suggests the known one.
  r = test::run_ris("radar info " +
                    q(radar_edited(dir, "[track]\n", "[track]\ntransmit_powr = \"2 kW\"\n")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("track.transmit_powr"));
  r = test::run_ris("radar info " + q(radar_edited(dir, "look_side = ", "look_sid = ")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("track.look_sid (did you mean \"look_side\"?)"));
}

TEST(MessagesCli, EnumValuesIgnoreCaseAndSuggest) {
  test::TempDir dir;
  auto r = test::run_ris("radar info " +
                         q(radar_edited(dir, "look_side = \"right\"", "look_side = \"Right\"")));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = test::run_ris("radar info " +
                    q(radar_edited(dir, "look_side = \"right\"", "look_side = \"rigth\"")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("expected \"right\" or \"left\", got \"rigth\" (did you mean "
                                  "\"right\"?)"));
}

TEST(MessagesCli, AMissingFileSuggestsItsNeighbour) {
  const auto r = test::run_ris("radar info " + data("radars/seed-fig4-5.tom"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("no such file (did you mean"));
  EXPECT_THAT(r.output, HasSubstr("seed-fig4-5.toml?)"));
  const auto far = test::run_ris("radar info /nonexistent-folder/radar.toml");
  EXPECT_THAT(far.output, HasSubstr("no such file (nor its folder /nonexistent-folder)"));
}

TEST(MessagesCli, ABareFrequencyIsNamedWithItsUnit) {
  test::TempDir dir;
  const auto r = test::run_ris("radar info " +
                               q(radar_edited(dir, "frequency = \"8.6 GHz\"", "frequency = 8.6")));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("'frequency': 8.6 Hz is outside"));
  EXPECT_THAT(r.output, HasSubstr("a bare number is read in Hz"));
  EXPECT_THAT(r.output, HasSubstr("\"9.6 GHz\""));
  EXPECT_THAT(r.output, HasSubstr("the units accepted: Hz, kHz, MHz, GHz"));
}

TEST(MessagesCli, AFrequencyOutsideTheImagingRadarBandsNamesFrequency) {
  test::TempDir dir;
  for (const char* f : {"\"99 MHz\"", "\"101 GHz\"", "8.6e12"}) {
    const auto r = test::run_ris("radar info " + q(radar_edited(dir, "frequency = \"8.6 GHz\"",
                                                                std::string("frequency = ") + f)));
    EXPECT_EQ(r.exit_code, 1) << f << r.output;
    EXPECT_THAT(r.output, HasSubstr("'frequency': "));
    EXPECT_THAT(r.output, HasSubstr("is outside 100 MHz .. 100 GHz, the band of the imaging "
                                    "radars ris simulates (P to W band)"));
  }
  // The bounds themselves are radars (P band's edge, W band's).
  for (const char* f : {"\"100 MHz\"", "\"100 GHz\"", "\"435 MHz\"", "94e9"}) {
    const auto r = test::run_ris("radar info " + q(radar_edited(dir, "frequency = \"8.6 GHz\"",
                                                                std::string("frequency = ") + f)));
    EXPECT_EQ(r.exit_code, 0) << f << r.output;
  }
}

}  // namespace
}  // namespace ris
