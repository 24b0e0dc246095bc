// End-to-end: the hostile inputs of the second hardening round (issue 37)
// through the real executable, each class with variants: nesting that would
// exhaust the parser's stack, work a small file can ask for, rasters that
// name files elsewhere, outputs into the kernel's file systems, radar
// quantities that overflow, and seeds that do not fit. Each asserts the
// message names the key or file at fault, the exit status and no output.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <array>
#include <filesystem>
#include <regex>
#include <set>
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
using test::expect_refused;
using test::listing;

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

// A shipped radar with the line `key = ...` replaced by `key = value`.
fs::path radar_replacing(const fs::path& dir, const std::string& shipped, const std::string& key,
                         const std::string& value) {
  const std::string text = test::read_file(data("radars/" + shipped));
  const std::regex line("(^|\n)" + key + " = [^\n]*");
  EXPECT_TRUE(std::regex_search(text, line)) << shipped << " has no " << key;
  const fs::path out = dir / (key + ".toml");
  test::write_file(out, std::regex_replace(text, line, "$1" + key + " = " + value,
                                           std::regex_constants::format_first_only));
  return out;
}

TEST(HostileInputsCli, DeeplyNestedTomlIsRefusedBeforeTheParser) {
  test::TempDir dir;
  const std::string grid = "[grid]\nrows = 10\ncols = 10\ncell_size = 10\n";
  // A header of 100,000 parts crashed toml++ (stack overflow); deep arrays
  // and inline tables recurse as well; and a radar, a library, a target list.
  const std::vector<std::pair<std::string, std::string>> files = {
      {"header.toml", grid + "[a" + repeat(".a", 100000) + "]\n"},
      {"array.toml", grid + "x = " + repeat("[", 100000) + repeat("]", 100000) + "\n"},
      {"inline.toml", grid + "x = " + repeat("{a=", 100000) + "1" + repeat("}", 100000) + "\n"},
  };
  for (const auto& [name, text] : files) test::write_file(dir / name, text);
  const auto before = listing(dir.path());
  for (const auto& [name, text] : files) {
    expect_refused(test::run_ris("scene build " + q(dir / name) + " -o " + q(dir / "s.tif")), 1,
                   "more than 64 levels deep", dir.path(), before);
  }
  expect_refused(test::run_ris("radar info " + q(dir / "header.toml")), 1,
                 "more than 64 levels deep", dir.path(), before);
  expect_refused(test::run_ris("simulate --quiet --backscatter " + q(dir / "array.toml") +
                               " --out " + q(dir / "out")),
                 1, "more than 64 levels deep", dir.path(), before);
}

TEST(HostileInputsCli, ObjectWorkPastTheGuardIsRefusedBeforePainting) {
  test::TempDir dir;
  // 5,000 patches covering a 3,000^2 grid (0.3 MB): 4.5e10 cell tests.
  std::string text = "[grid]\nrows = 3000\ncols = 3000\ncell_size = 1\n";
  for (int i = 0; i < 5000; ++i) {
    text +=
        "[[object]]\ntype = \"patch\"\nx = 0\ny = 0\nlength = 3000\nwidth = 3000\n"
        "category = 1\n";
  }
  test::write_file(dir / "many.toml", text);
  const auto before = listing(dir.path());
  const auto r = test::run_ris("scene build " + q(dir / "many.toml") + " -o " + q(dir / "s.tif"));
  expect_refused(r, 1, "the 5000 objects' cell tests", dir.path(), before);
  EXPECT_THAT(r.output, HasSubstr("'object'"));
  EXPECT_THAT(r.output, HasSubstr("RIS_NO_RESOURCE_LIMITS"));
  // Twenty of them is work the guard allows (1.8e8 tests).
  text = "[grid]\nrows = 3000\ncols = 3000\ncell_size = 1\n";
  for (int i = 0; i < 20; ++i) {
    text +=
        "[[object]]\ntype = \"patch\"\nx = 0\ny = 0\nlength = 3000\nwidth = 3000\n"
        "category = 1\n";
  }
  test::write_file(dir / "some.toml", text);
  const auto ok = test::run_ris("scene build " + q(dir / "some.toml") + " -o " + q(dir / "s.tif"));
  EXPECT_EQ(ok.exit_code, 0) << ok.output;
}

// A VRT of one band whose source (SourceFilename, relative or not) is `source`.
std::string simple_vrt(const std::string& source, bool relative) {
  return "<VRTDataset rasterXSize=\"20\" rasterYSize=\"20\">\n"
         "  <GeoTransform>0, 10, 0, 200, 0, -10</GeoTransform>\n"
         "  <VRTRasterBand dataType=\"Float32\" band=\"1\">\n    <SimpleSource>\n"
         "      <SourceFilename relativeToVRT=\"" +
         std::string(relative ? "1" : "0") + "\">" + source +
         "</SourceFilename>\n      <SourceBand>1</SourceBand>\n"
         "    </SimpleSource>\n  </VRTRasterBand>\n</VRTDataset>\n";
}

TEST(HostileInputsCli, RastersNamingFilesElsewhereAreRefused) {
  test::TempDir dir;
  fs::create_directories(dir / "in");
  fs::create_directories(dir / "other");
  // A DEM outside the VRT's folder, one beside it, a FIFO beside it.
  ASSERT_EQ(
      test::run_ris("scene fractal --quiet --size 20 -o " + q(dir / "other" / "dem.tif")).exit_code,
      0);
  fs::copy_file(dir / "other" / "dem.tif", dir / "in" / "dem.tif");
  ASSERT_EQ(::mkfifo((dir / "in" / "fifo.tif").c_str(), 0600), 0);
  test::write_file(dir / "in" / "outside.vrt", simple_vrt("../other/dem.tif", true));
  test::write_file(dir / "in" / "absolute.vrt",
                   simple_vrt((dir / "other" / "dem.tif").string(), false));
  test::write_file(dir / "in" / "vsi.vrt", simple_vrt("/vsizip/x.zip/dem.tif", false));
  test::write_file(dir / "in" / "fifo.vrt", simple_vrt("fifo.tif", true));
  test::write_file(dir / "in" / "beside.vrt", simple_vrt("dem.tif", true));
  // Named .tif: a VRT is known by its text, not its name.
  test::write_file(dir / "in" / "raw.tif",
                   "<VRTDataset rasterXSize=\"8\" rasterYSize=\"8\">\n"
                   "  <VRTRasterBand dataType=\"Byte\" band=\"1\" subClass=\"VRTRawRasterBand\">\n"
                   "    <SourceFilename relativeToVRT=\"0\">/etc/passwd</SourceFilename>\n"
                   "  </VRTRasterBand>\n</VRTDataset>\n");
  const auto before = listing(dir / "in");
  const auto import = [&](const std::string& name, const std::string& env = "") {
    return test::run_ris_env(env, "scene import --crs EPSG:32633 " + q(dir / "in" / name) + " -o " +
                                      q(dir / "in" / "scene.tif"));
  };
  expect_refused(import("outside.vrt"), 1, "outside its own folder", dir / "in", before);
  expect_refused(import("absolute.vrt"), 1, "outside its own folder", dir / "in", before);
  expect_refused(import("vsi.vrt"), 1, "a GDAL virtual file system path", dir / "in", before);
  expect_refused(import("fifo.vrt"), 1, "is a FIFO", dir / "in", before);  // no hang
  expect_refused(import("raw.tif"), 1, "raw raster band", dir / "in", before);
  EXPECT_THAT(import("raw.tif").output, HasSubstr("RIS_ALLOW_FILE_REFERENCES=1"));
  // Beside it, or trusted by the user: imported.
  auto r = import("beside.vrt");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  fs::remove(dir / "in" / "scene.tif");
  r = import("outside.vrt", "RIS_ALLOW_FILE_REFERENCES=1");
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

TEST(HostileInputsCli, OutputsIntoDevAndProcAreRefused) {
  test::TempDir dir;
  const std::string scene = data("scenes/ku-geometric.toml");
  // A link to this process's standard output (as /dev/stdout is): as root,
  // renaming over /dev/stdout replaced the system's link.
  fs::create_symlink("/proc/self/fd/1", dir / "stdout.tif");
  const auto before = listing(dir.path());
  for (const std::string& out : {std::string("/dev/ris-hostile-test.tif"),
                                 std::string("/proc/self/fd/1"), (dir / "stdout.tif").string()}) {
    const auto r = test::run_ris("scene build " + scene + " -o " + q(out));
    EXPECT_EQ(r.exit_code, 1) << out << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("a device or kernel file system")) << out;
  }
  EXPECT_FALSE(fs::exists("/dev/ris-hostile-test.tif"));
  EXPECT_TRUE(fs::is_symlink(dir / "stdout.tif"));
  EXPECT_EQ(listing(dir.path()), before);
  const auto r = test::run_ris("simulate --quiet --out /proc/self");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("a device or kernel file system"));
}

TEST(HostileInputsCli, OverflowingRadarQuantitiesAreRefusedAtTheirKey) {
  test::TempDir dir;
  const std::vector<std::array<std::string, 3>> cases = {
      {"frequency", "\"1e-300 Hz\"", "'frequency': 1e-300 Hz is outside"},
      {"frequency", "8.6", "'frequency': 8.6 Hz is outside"},  // no unit: Hz
      {"transmit_power", "\"1e300 W\"", "'transmit_power': 1e+300 W is outside"},
      {"antenna_gain_db", "3000", "'antenna_gain_db': 3000 dB is outside"},
      {"pulse_width", "\"1e-300 s\"", "'pulse_width': 1e-300 s is outside"},
  };
  for (const auto& [key, value, message] : cases) {
    const fs::path radar = radar_replacing(dir.path(), "ppi-ground-mast-30m.toml", key, value);
    const auto r = test::run_ris("radar info " + q(radar));
    EXPECT_EQ(r.exit_code, 1) << key << "=" << value << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr(message));
    EXPECT_THAT(r.output, Not(HasSubstr("inf")));
  }
  // A ray spacing of 1e-7 deg: 3.6e9 rays, once printed as -2147483648.
  std::string text = test::read_file(data("radars/ppi-ground-mast-30m.toml"));
  text.replace(text.find("[scan]\n"), 7, "[scan]\nray_spacing = \"1e-7 deg\"\n");
  test::write_file(dir / "rays.toml", text);
  const auto r = test::run_ris("radar info " + q(dir / "rays.toml"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("'scan.ray_spacing': 3.6e+09 rays over the scan: too many"));
  EXPECT_THAT(r.output, Not(HasSubstr("-2147483648")));
}

TEST(HostileInputsCli, SeedsOutsideTheirRangeAreRefused) {
  test::TempDir dir;
  for (const char* seed : {"-1", "18446744073709551616", "1e3", "0x10", ""}) {
    const auto r = test::run_ris("simulate --quiet --seed '" + std::string(seed) + "' --out " +
                                 q(dir / "out"));
    EXPECT_EQ(r.exit_code, 2) << seed << ": " << r.output;
    EXPECT_THAT(r.output, HasSubstr("--seed")) << seed;
    EXPECT_FALSE(fs::exists(dir / "out"));
  }
  const auto r = test::run_ris(
      "simulate --quiet --products slant_range --seed "
      "18446744073709551615 --out " +
      q(dir / "ok"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
}

}  // namespace
}  // namespace ris
