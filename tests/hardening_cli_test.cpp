// End-to-end: hostile inputs (issue 21) through the real executable. One test
// per class of bad input; each asserts a clear message, the documented exit
// status (1 input, 2 usage; docs/limits.md), no output left behind and the
// inputs unchanged.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

#include "build_paths.h"
#include "refusal_checks.h"
#include "test_util.h"

namespace ris {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using test::q;

using test::data;
using test::expect_refused;
using test::listing;

// A copy of a shipped radar file with `line` added before its [track] table.
fs::path radar_with(const test::TempDir& dir, const std::string& shipped, const std::string& line,
                    const std::string& table = "[track]") {
  std::string text = test::read_file(data("radars/" + shipped));
  const auto at = text.find("\n" + table + "\n");
  EXPECT_NE(at, std::string::npos) << shipped << " has no " << table;
  text.insert(at + 1 + (table == "[track]" ? 0 : table.size() + 1), line + "\n");
  const fs::path out = dir / "radar.toml";
  test::write_file(out, text);
  return out;
}

TEST(HardeningCli, ThreadCountAboveTheCapIsRefused) {
  test::TempDir dir;
  const auto before = listing(dir.path());
  for (const char* cmd : {"simulate", "study"}) {
    const auto r =
        test::run_ris(std::string(cmd) + " --threads 100000 --quiet --out " + q(dir / "out"));
    expect_refused(r, 1, "'--threads': 100000 threads is more than the limit", dir.path(), before);
    EXPECT_THAT(r.output, HasSubstr("RIS_MAX_THREADS"));
  }
  const auto neg = test::run_ris("simulate --threads -3 --quiet --out " + q(dir / "out"));
  expect_refused(neg, 1, "expected 0 (all cores) or more", dir.path(), before);
}

TEST(HardeningCli, CommandLineSyntaxErrorsExitTwo) {
  test::TempDir dir;
  const auto before = listing(dir.path());
  expect_refused(test::run_ris("simulate --no-such-option --out " + q(dir / "out")), 2,
                 "--no-such-option", dir.path(), before);
  expect_refused(test::run_ris("simulate --threads many --out " + q(dir / "out")), 2, "--threads",
                 dir.path(), before);
  EXPECT_EQ(test::run_ris("no-such-command").exit_code, 2);
  EXPECT_EQ(test::run_ris("--help").exit_code, 0);
}

TEST(HardeningCli, FifoAndDeviceInputsAreRefusedBeforeOpening) {
  test::TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "radar.toml").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((dir / "dem.tif").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.toml");  // a device, through a link
  const auto before = listing(dir.path());
  // Each would block or read forever if opened; refused at once instead.
  expect_refused(test::run_ris("simulate --quiet --radar " + q(dir / "radar.toml") + " --out " +
                               q(dir / "out")),
                 1, "is a FIFO (named pipe); expected a regular file", dir.path(), before);
  expect_refused(
      test::run_ris("scene import " + q(dir / "dem.tif") + " -o " + q(dir / "scene.tif")), 1,
      "is a FIFO", dir.path(), before);
  expect_refused(test::run_ris("scene info " + q(dir / "zero.toml")), 1,
                 "is a device; expected a regular file", dir.path(), before);
  expect_refused(test::run_ris("scene info " + q(dir.path())), 1,
                 "is a folder; expected a regular file", dir.path(), before);
}

TEST(HardeningCli, DeviceFifoAndFolderOutputsAreRefused) {
  test::TempDir dir;
  const std::string scene = data("scenes/ku-geometric.toml");
  ASSERT_EQ(::mkfifo((dir / "fifo.tif").c_str(), 0600), 0);
  fs::create_symlink("/dev/null", dir / "null.tif");
  fs::create_directory(dir / "folder.tif");
  test::write_file(dir / "file", "not a folder\n");
  const auto before = listing(dir.path());
  for (const char* name : {"fifo.tif", "null.tif"}) {
    expect_refused(test::run_ris("scene build " + scene + " -o " + q(dir / name)), 1,
                   "ris writes only new files or replaces regular files", dir.path(), before);
  }
  EXPECT_TRUE(fs::is_fifo(dir / "fifo.tif"));
  EXPECT_TRUE(fs::is_symlink(dir / "null.tif"));
  expect_refused(test::run_ris("scene build " + scene + " -o " + q(dir / "folder.tif")), 1,
                 "is a folder", dir.path(), before);
  expect_refused(test::run_ris("simulate --quiet --out " + q(dir / "file")), 1,
                 "is a regular file; expected a folder", dir.path(), before);
  EXPECT_EQ(test::read_file(dir / "file"), "not a folder\n");
  // A product's name taken by a folder in the output folder: refused before
  // the run, not when the products are moved in.
  fs::create_directories(dir / "out" / "metadata.json");
  const auto out_before = listing(dir / "out");
  expect_refused(test::run_ris("simulate --quiet --out " + q(dir / "out")), 1,
                 "metadata.json: '--out': is a folder", dir / "out", out_before);
}

TEST(HardeningCli, OutputThatIsAnInputIsRefusedAndTheInputKept) {
  test::TempDir dir;
  const std::string text = test::read_file(data("scenes/ku-geometric.toml"));
  test::write_file(dir / "s.toml", text);
  fs::create_directory(dir / "out");
  const auto r = test::run_ris("scene build " + q(dir / "s.toml") + " -o " + q(dir / "s.toml"));
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("is also an input of this run"));
  EXPECT_EQ(test::read_file(dir / "s.toml"), text);
  // A scene raster inside the output folder under a product's name.
  ASSERT_EQ(test::run_ris("scene build " + q(dir / "s.toml") + " -o " +
                          q(dir / "out" / "mean_power_slant.tif"))
                .exit_code,
            0);
  const std::string scene_bytes = test::read_file(dir / "out" / "mean_power_slant.tif");
  const auto before = listing(dir / "out");
  expect_refused(
      test::run_ris("simulate --quiet --scene " + q(dir / "out" / "mean_power_slant.tif") +
                    " --out " + q(dir / "out")),
      1, "is also an input of this run", dir / "out", before);
  EXPECT_EQ(test::read_file(dir / "out" / "mean_power_slant.tif"), scene_bytes);
}

// The memory and disk ceilings of ris runs in this scope (RIS_MAX_MEMORY_MB,
// RIS_MAX_DISK_MB): a refusal must not depend on the test machine's free
// memory or disk (a big one would otherwise start the 50 GB run).
class MemoryCeiling {
 public:
  explicit MemoryCeiling(const char* mb) {
    ::setenv("RIS_MAX_MEMORY_MB", mb, 1);
    ::setenv("RIS_MAX_DISK_MB", mb, 1);
  }
  ~MemoryCeiling() {
    ::unsetenv("RIS_MAX_MEMORY_MB");
    ::unsetenv("RIS_MAX_DISK_MB");
  }
  MemoryCeiling(const MemoryCeiling&) = delete;
  MemoryCeiling& operator=(const MemoryCeiling&) = delete;
};

TEST(HardeningCli, LineCountOverflowAndHugeImagesAreRefused) {
  const MemoryCeiling ceiling("2048");
  test::TempDir dir;
  // 0.001 mm over the track once wrapped to a one-line image (exit 0).
  const fs::path tiny = radar_with(dir, "seed-fig4-5.toml", "azimuth_line_spacing = \"0.001 mm\"");
  auto before = listing(dir.path());
  expect_refused(test::run_ris("simulate --quiet --radar " + q(tiny) + " --out " + q(dir / "out")),
                 1, "'azimuth_line_spacing': gives 4.267e+09 azimuth lines, more than the limit",
                 dir.path(), before);
  // 1 cm: 426,720 lines and a ground-range image of ~10^11 pixels, refused
  // by the memory estimate before the image is formed.
  const fs::path cm = radar_with(dir, "seed-fig4-5.toml", "azimuth_line_spacing = \"1 cm\"");
  expect_refused(test::run_ris("simulate --quiet --radar " + q(cm) + " --out " + q(dir / "out")), 1,
                 "needs about", dir.path(), before);
  // A 1 mm PPI scope pixel.
  const fs::path ppi = radar_with(dir, "ppi-ground-mast-30m.toml", "pixel = \"1 mm\"", "[scan]");
  expect_refused(test::run_ris("simulate --quiet --radar " + q(ppi) + " --out " + q(dir / "out")),
                 1, "'scan.pixel'", dir.path(), before);
  // 1.8 M rays of a PPI: their products would not fit on the disk (checked
  // before the run; without an output folder, their geometry in memory).
  const fs::path rays =
      radar_with(dir, "ppi-ground-mast-30m.toml", "ray_spacing = \"2e-4 deg\"", "[scan]");
  expect_refused(test::run_ris("simulate --quiet --radar " + q(rays) + " --out " + q(dir / "out")),
                 1, "'scan.ray_spacing': the products of a PPI run (1800000 rays", dir.path(),
                 before);
}

TEST(HardeningCli, HugeSizesAreRefusedBeforeAnyWork) {
  const MemoryCeiling ceiling("2048");
  test::TempDir dir;
  const auto before = listing(dir.path());
  expect_refused(test::run_ris("scene fractal --quiet --size 1000000 -o " + q(dir / "f.tif")), 1,
                 "'--size': a scene of 1000000 x 1000000 cells needs about 3.6 TiB of disk",
                 dir.path(), before);
  expect_refused(test::run_ris("bench --size 1000000"), 1,
                 "'--size': an in-memory run of 1000000 x 1000000 cells needs about", dir.path(),
                 before);
  expect_refused(test::run_ris("scene fractal --quiet --patches 21,22 --patch-size '1 mm' -o " +
                               q(dir / "f.tif")),
                 1, "smaller than a cell", dir.path(), before);
}

TEST(HardeningCli, TinyAngleStepIsRefused) {
  const auto r = test::run_ris("sigma0 -a 0:90:1e-9");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("'--angles': gives 9e+10 values"));
}

TEST(HardeningCli, InfiniteHeightIsRefusedAtTheParseEdge) {
  test::TempDir dir;
  for (const char* height : {"1e39", "inf", "nan"}) {
    test::write_file(dir / "s.toml", std::string("[grid]\nrows = 20\ncols = 20\ncell_size = 10\n"
                                                 "[[object]]\ntype = \"box\"\nx = 50\ny = 50\n"
                                                 "length = 40\nwidth = 40\nheight = ") +
                                         height + "\n");
    const auto before = listing(dir.path());
    expect_refused(test::run_ris("scene build " + q(dir / "s.toml") + " -o " + q(dir / "s.tif")), 1,
                   "'object[0].height'", dir.path(), before);
  }
}

TEST(HardeningCli, ObjectsSmallerThanACellWarnWithTheConsequence) {
  test::TempDir dir;
  test::write_file(dir / "s.toml",
                   "[grid]\nrows = 20\ncols = 20\ncell_size = 10\n"
                   "[[object]]\ntype = \"checkerboard\"\nsquare = 3\ncategories = [1, 2]\n");
  const auto r = test::run_ris("scene build " + q(dir / "s.toml") + " -o " + q(dir / "s.tif"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("object[0] (checkerboard) has details of 3 m, smaller than a "
                                  "cell (10 m)"));
  EXPECT_THAT(r.output, HasSubstr("alias"));
}

TEST(HardeningCli, StreamedRunWithAnUndefinedCategoryFailsAtItsFirstCell) {
  test::TempDir dir;
  // Categories 1-3 are ku-geometric's, not generic-terrain's.
  ASSERT_EQ(test::run_ris("scene fractal --quiet --size 300 --patches 1,2,3 -o " + q(dir / "s.tif"))
                .exit_code,
            0);
  const auto before = listing(dir.path());
  expect_refused(
      test::run_ris("simulate --quiet --stream --scene " + q(dir / "s.tif") + " --backscatter " +
                    data("backscatter/generic-terrain.toml") + " --out " + q(dir / "out")),
      1, "uses it, first at row 0, column 0", dir.path(), before);
}

TEST(HardeningCli, BareDemAndFractalSceneSimulateWithShippedFiles) {
  test::TempDir dir;
  // The README's fractal example as printed, with its shipped radar.
  const auto fractal = test::run_ris(
      "scene fractal --quiet --size 300 --relief 1500 --hurst 0.75 --seed 7 --centre 46.5,8.0 -o " +
      q(dir / "alps.tif"));
  ASSERT_EQ(fractal.exit_code, 0) << fractal.output;
  EXPECT_THAT(fractal.output, HasSubstr("no --category: every cell is grass"));
  const auto alps =
      test::run_ris("simulate --quiet --scene " + q(dir / "alps.tif") + " --radar " +
                    data("radars/slar-x-band-alps.toml") + " --out " + q(dir / "alps-out"));
  ASSERT_EQ(alps.exit_code, 0) << alps.output;
  EXPECT_THAT(alps.output, HasSubstr("generic-terrain.toml, the library the scene names"));
  EXPECT_TRUE(fs::exists(dir / "alps-out" / "geocoded_grey.tif"));
  // A bare DEM import, simulated with the standard radar and no options.
  const auto dem = test::run_ris("scene import " + std::string(test::test_data_dir()) +
                                 "/dem/Rome-30m-DEM.tif -o " + q(dir / "rome.tif"));
  ASSERT_EQ(dem.exit_code, 0) << dem.output;
  const auto rome = test::run_ris("simulate --quiet --scene " + q(dir / "rome.tif") + " --out " +
                                  q(dir / "rome-out"));
  EXPECT_EQ(rome.exit_code, 0) << rome.output;
  EXPECT_TRUE(fs::exists(dir / "rome-out" / "metadata.json"));
}

}  // namespace
}  // namespace ris
