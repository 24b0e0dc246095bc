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
}

}  // namespace
}  // namespace ris
