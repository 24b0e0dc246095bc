// End-to-end: a radar file with [[channel]] tables (docs/radar-format.md,
// "Channels"). One `ris simulate` run writes each channel's products,
// suffixed by the channel's name, whose pixels are those of the one-channel
// run of that channel; the scene-wide products are written once and are
// every channel's; what the engine cannot run on several channels is
// refused naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "build_paths.h"
#include "refusal_checks.h"
#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// The seed's figure-4-5 radar without its frequency and polarisation.
std::string base_radar() {
  std::string text = test::read_file(fs::path(test::data_dir()) / "radars" / "seed-fig4-5.toml");
  for (const std::string line : {"frequency = \"8.6 GHz\"          # RADAR(13)\n",
                                 "polarisation = \"HH\"            # RADAR(14)\n"}) {
    const auto at = text.find(line);
    EXPECT_NE(at, std::string::npos) << line;
    if (at != std::string::npos) text.erase(at, line.size());
  }
  return text;
}

struct Channel {
  std::string name;  // "" : the default (the polarisation)
  std::string frequency, polarisation, power;
  std::string suffix;  // the products' suffix
};

const std::vector<Channel> kChannels = {{"", "8.6 GHz", "HH", "", "hh"},
                                        {"", "8.6 GHz", "HV", "", "hv"},
                                        {"c_vv", "5.3 GHz", "VV", "2 kW", "c_vv"}};

// The channel's keys as TOML lines.
std::string channel_keys(const Channel& c) {
  std::string s;
  if (!c.name.empty()) s += "name = \"" + c.name + "\"\n";
  s += "frequency = \"" + c.frequency + "\"\npolarisation = \"" + c.polarisation + "\"\n";
  if (!c.power.empty()) s += "transmit_power = \"" + c.power + "\"\n";
  return s;
}

std::string multi_radar() {
  std::string text = base_radar();
  for (const Channel& c : kChannels) text += "\n[[channel]]\n" + channel_keys(c);
  return text;
}

// A channel alone: its keys at the top of the file (name is no radar key).
std::string single_radar(const Channel& c) {
  Channel keys = c;
  keys.name.clear();
  return channel_keys(keys) + base_radar();
}

// Every pixel of every band the same (NaN where NaN), and every byte.
void expect_same_pixels(const fs::path& a, const fs::path& b) {
  ASSERT_TRUE(fs::exists(a)) << a;
  ASSERT_TRUE(fs::exists(b)) << b;
  if (a.extension() == ".txt") {
    EXPECT_EQ(test::read_file(a), test::read_file(b)) << a;
    return;
  }
  const RasterF64 x = read_raster_f64(a);
  const RasterF64 y = read_raster_f64(b);
  ASSERT_EQ(x.cols, y.cols) << a;
  ASSERT_EQ(x.rows, y.rows) << a;
  ASSERT_EQ(x.data.size(), y.data.size()) << a;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < x.data.size(); ++i) {
    if (!(x.data[i] == y.data[i] || (std::isnan(x.data[i]) && std::isnan(y.data[i])))) ++differ;
  }
  EXPECT_EQ(differ, 0u) << a << " vs " << b;
  // And the files themselves (no product names its radar file).
  EXPECT_TRUE(test::read_file(a) == test::read_file(b)) << a << " vs " << b;
}

bool is_scene_wide(const std::string& file) {
  for (const char* stem : {"scene_mask.", "local_incidence_deg.", "mask_slant.", "shadowmap."}) {
    if (file.starts_with(stem)) return true;
  }
  return false;
}

TEST(ChannelsCli, EachChannelsProductsAreItsOwnRunsPixels) {
  test::TempDir dir;
  test::write_file(dir / "multi.toml", multi_radar());
  const fs::path multi = dir / "multi";
  test::RunResult r = test::run_ris("simulate --quiet --radar " + test::q(dir / "multi.toml") +
                                    " --out " + test::q(multi));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("(SLAR, 3 channels)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("  channel c_vv: 5.300 GHz VV, products *_c_vv"), std::string::npos)
      << r.output;
  int compared = 0;
  for (const Channel& c : kChannels) {
    const fs::path radar = dir / (c.suffix + ".toml");
    test::write_file(radar, single_radar(c));
    const fs::path one = dir / c.suffix;
    r = test::run_ris("simulate --quiet --radar " + test::q(radar) + " --out " + test::q(one));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const auto& e : fs::directory_iterator(one)) {
      const std::string file = e.path().filename().string();
      if (file == "metadata.json") continue;
      // A scene-wide product is written once, unsuffixed: every channel's.
      const std::string mine = is_scene_wide(file) ? file
                                                   : file.substr(0, file.find('.')) + "_" +
                                                         c.suffix + file.substr(file.find('.'));
      expect_same_pixels(multi / mine, e.path());
      ++compared;
    }
  }
  EXPECT_EQ(compared, 3 * 11);
  // The folder: 4 scene-wide files, 7 a channel, metadata.json.
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(multi)) ++files;
  EXPECT_EQ(files, 4 + 3 * 7 + 1);
  std::ifstream in(multi / "metadata.json");
  const nlohmann::json meta = nlohmann::json::parse(in);
  ASSERT_EQ(meta["channels"].size(), 3u);
  EXPECT_EQ(meta["channels"][0]["name"], "hh");
  EXPECT_EQ(meta["channels"][1]["polarisation"], "HV");
  EXPECT_EQ(meta["channels"][2]["frequency_hz"], 5.3e9);
  EXPECT_EQ(meta["channels"][2]["radar"]["transmit_power_w"], 2000.0);
  EXPECT_TRUE(meta["channels"][2]["products"].contains("mean_power_slant_c_vv.tif"));
  EXPECT_FALSE(meta["channels"][2]["products"].contains("scene_mask.tif"));
  EXPECT_TRUE(meta["products"].contains("scene_mask.tif"));
  EXPECT_TRUE(meta["products"].contains("slant_range_hv.png"));
  EXPECT_EQ(meta["products"].size(), static_cast<std::size_t>(files));
}

// --products applies to every channel; a scene-wide stem alone is written once.
TEST(ChannelsCli, ProductSelectionAppliesToEveryChannel) {
  test::TempDir dir;
  test::write_file(dir / "multi.toml", multi_radar());
  test::RunResult r =
      test::run_ris("simulate --quiet --radar " + test::q(dir / "multi.toml") +
                    " --products mean_power_slant,scene_mask --out " + test::q(dir / "a"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::listing(dir / "a"),
            (std::set<std::string>{"metadata.json", "scene_mask.tif", "mean_power_slant_hh.tif",
                                   "mean_power_slant_hv.tif", "mean_power_slant_c_vv.tif"}));
  r = test::run_ris("simulate --quiet --radar " + test::q(dir / "multi.toml") +
                    " --products scene_mask --out " + test::q(dir / "b"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::listing(dir / "b"), (std::set<std::string>{"metadata.json", "scene_mask.tif"}));
}

// What a run cannot do on several channels, and what a [[channel]] table
// may not say: refused before anything is written, naming the key.
TEST(ChannelsCli, RefusalsNameTheKey) {
  test::TempDir dir;
  const std::set<std::string> before = test::listing(dir.path());
  const auto refused = [&](const std::string& radar_text, const std::string& extra,
                           const std::string& says) {
    test::write_file(dir / "r.toml", radar_text);
    const test::RunResult r = test::run_ris("simulate --quiet --radar " + test::q(dir / "r.toml") +
                                            " " + extra + " --out " + test::q(dir / "out"));
    std::set<std::string> now = before;
    now.insert("r.toml");
    test::expect_refused(r, 1, says, dir.path(), now);
  };
  const std::string multi = multi_radar();
  // Streamed: the scene raster is built first (a file of the folder then).
  ASSERT_EQ(test::run_ris("scene build -o " + test::q(dir / "scene.tif")).exit_code, 0);
  {
    test::write_file(dir / "r.toml", multi);
    const test::RunResult r =
        test::run_ris("simulate --quiet --stream --scene " + test::q(dir / "scene.tif") +
                      " --radar " + test::q(dir / "r.toml") + " --out " + test::q(dir / "out"));
    EXPECT_EQ(r.exit_code, 1) << r.output;
    EXPECT_NE(r.output.find("channel"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("streamed runs take one channel; drop --stream"), std::string::npos)
        << r.output;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  fs::remove(dir / "scene.tif");
  refused(multi, "--targets " + test::q(test::data("targets/corner-reflectors.toml")),
          "'--targets': 3 channels");
  refused(base_radar() + "\n[[channel]]\nfrequency = \"1e15 Hz\"\npolarisation = \"HH\"\n", "",
          "channel[0].frequency");
  refused("frequency = \"9 GHz\"\n" + multi, "", "a radar with [[channel]] tables gives each");
  refused(base_radar() + "\n[[channel]]\nfrequency = \"9 GHz\"\n", "", "channel[0].polarisation");
  refused(
      base_radar() + "\n[[channel]]\nfrequency = \"9 GHz\"\npolarisation = \"HH\"\ncolour = 1\n",
      "", "colour");
  refused(base_radar() + "\n[[channel]]\nfrequency = \"9 GHz\"\npolarisation = \"HH\"\n" +
              "\n[[channel]]\nfrequency = \"5 GHz\"\npolarisation = \"HH\"\n",
          "", "two channels are named \"hh\"");
  refused(base_radar() +
              "\n[[channel]]\nname = \"a/b\"\nfrequency = \"9 GHz\"\npolarisation = "
              "\"HH\"\n",
          "", "channel[0].name");
  // A PPI radar on several channels.
  std::string ppi = test::read_file(test::data("radars/ppi-ground-mast-30m.toml"));
  const auto f = ppi.find("frequency =");
  const auto p = ppi.find("polarisation =");
  ASSERT_TRUE(f != std::string::npos && p != std::string::npos);
  ppi.erase(p, ppi.find('\n', p) - p + 1);
  ppi.erase(f, ppi.find('\n', f) - f + 1);
  refused(ppi + "\n[[channel]]\nfrequency = \"9 GHz\"\npolarisation = \"HH\"\n" +
              "\n[[channel]]\nfrequency = \"9 GHz\"\npolarisation = \"VV\"\n",
          "", "a PPI takes one channel for now");
}

// The commands that image one channel refuse a multi-channel file naming
// the key and themselves (they took its first channel without a word);
// `ris radar info` lists the channels.
TEST(ChannelsCli, OneChannelCommandsRefuseSeveralAndInfoListsThem) {
  test::TempDir dir;
  test::write_file(dir / "r.toml", multi_radar());
  const std::string radar = test::q(dir / "r.toml");
  for (const std::string& cmd : {"study --radar " + radar + " --out " + test::q(dir / "study"),
                                 "sensitivity --vary cell_factor=1,2 --radar " + radar + " --out " +
                                     test::q(dir / "sens")}) {
    const test::RunResult r = test::run_ris(cmd);
    EXPECT_EQ(r.exit_code, 1) << cmd << "\n" << r.output;
    EXPECT_NE(r.output.find("'channel'"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("images one channel; this file lists 3 [[channel]] tables (hh, hv, "
                            "c_vv)"),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find("ris " + cmd.substr(0, cmd.find(' '))), std::string::npos) << r.output;
  }
  EXPECT_FALSE(fs::exists(dir / "study"));
  EXPECT_FALSE(fs::exists(dir / "sens"));
  const test::RunResult info = test::run_ris("radar info " + radar);
  EXPECT_EQ(info.exit_code, 0) << info.output;
  EXPECT_NE(info.output.find("channels                  3"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("c_vv"), std::string::npos) << info.output;
  EXPECT_NE(info.output.find("5.3 GHz VV"), std::string::npos) << info.output;
}

// One [[channel]] is a one-channel radar: the same products, unsuffixed.
TEST(ChannelsCli, OneChannelIsAOneChannelRun) {
  test::TempDir dir;
  const Channel& hv = kChannels[1];
  test::write_file(dir / "one.toml", base_radar() + "\n[[channel]]\n" + channel_keys(hv));
  test::write_file(dir / "flat.toml", single_radar(hv));
  ASSERT_EQ(test::run_ris("simulate --quiet --radar " + test::q(dir / "one.toml") + " --out " +
                          test::q(dir / "a"))
                .exit_code,
            0);
  ASSERT_EQ(test::run_ris("simulate --quiet --radar " + test::q(dir / "flat.toml") + " --out " +
                          test::q(dir / "b"))
                .exit_code,
            0);
  EXPECT_EQ(test::listing(dir / "a"), test::listing(dir / "b"));
  for (const auto& e : fs::directory_iterator(dir / "b")) {
    if (e.path().filename() != "metadata.json") {
      expect_same_pixels(dir / "a" / e.path().filename(), e.path());
    }
  }
}

}  // namespace
}  // namespace ris
