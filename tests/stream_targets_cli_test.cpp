// `ris simulate --stream --targets` end to end: point targets in a streamed
// SLAR or SAR run (src/sim/stream/slar_stream_targets.h), incoherent or coherent
// (src/sim/stream/sar_coherent_stream.h), give the in-memory run's files byte for
// byte, measurements in metadata.json and the printed summary included; so
// does a streamed PPI (seen and hidden targets).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>

#include "build_paths.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// The standard scene as a raster (in `dir`).
std::string standard_scene(const test::TempDir& dir) {
  const std::string scene = (dir / "std.tif").string();
  EXPECT_EQ(test::run_ris("scene build -o " + scene).exit_code, 0);
  return scene;
}

// A shipped radar with one piece of text replaced.
std::string radar_with(const test::TempDir& dir, const std::string& from,
                       const std::string& old_text, const std::string& new_text) {
  std::string text = test::read_file(fs::path(test::data_dir()) / "radars" / from);
  const auto at = text.find(old_text);
  EXPECT_NE(at, std::string::npos) << old_text;
  if (at != std::string::npos) text.replace(at, old_text.size(), new_text);
  const fs::path p = dir / ("edited-" + from);
  test::write_file(p, text);
  return p.string();
}

std::string corner_reflectors() {
  return (fs::path(test::data_dir()) / "targets" / "corner-reflectors.toml").string();
}

// Every file of `mem` in `out`, byte for byte, and no other.
void expect_same_files(const fs::path& mem, const fs::path& out, const std::string& tag) {
  int files = 0;
  for (const auto& e : fs::directory_iterator(mem)) {
    const fs::path other = out / e.path().filename();
    ASSERT_TRUE(fs::exists(other)) << tag << ": " << other;
    EXPECT_TRUE(test::read_file(e.path()) == test::read_file(other))
        << tag << ": " << e.path().filename();
    ++files;
  }
  int others = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++others;
  EXPECT_EQ(files, others) << tag;
  EXPECT_EQ(files, 12) << tag;  // geocoded_grey.png too
}

// The lines that report the targets (the measurements and hidden names).
std::string target_lines(const std::string& output) {
  std::string out;
  std::size_t at = 0;
  while ((at = output.find("  target ", at)) != std::string::npos) {
    const std::size_t end = output.find('\n', at);
    out += output.substr(at, end - at + 1);
    at = end;
  }
  return out;
}

// The incoherent SAR with the shipped corner reflectors on the standard
// scene, in memory and streamed in blocks of 7, 16 and all lines, on 1 and
// 2 threads: the same files and the same printed measurements.
TEST(StreamTargetsCli, IncoherentSarWithTargetsEqualsInMemory) {
  test::TempDir dir;
  const std::string scene = standard_scene(dir);
  const std::string radar =
      radar_with(dir, "sar-x-band-stripmap.toml", "coherent = true", "coherent = false");
  const std::string args =
      " --scene " + scene + " --radar " + radar + " --targets " + corner_reflectors() + " --out ";
  for (const char* threads : {"1", "2"}) {
    // metadata.json records the threads: an in-memory run on as many.
    const fs::path mem_dir = dir / ("mem-" + std::string(threads));
    const auto mem = test::run_ris(std::string("simulate --quiet --threads ") + threads + args +
                                   mem_dir.string());
    ASSERT_EQ(mem.exit_code, 0) << mem.output;
    const std::string measured = target_lines(mem.output);
    EXPECT_NE(measured.find("PSLR"), std::string::npos) << mem.output;
    for (const char* block : {"7", "16", "700"}) {
      const std::string tag = std::string("threads ") + threads + ", block " + block;
      const fs::path out = dir / ("st-" + std::string(threads) + "-" + block);
      const auto st = test::run_ris(std::string("simulate --quiet --threads ") + threads +
                                    " --block-lines " + block + args + out.string());
      ASSERT_EQ(st.exit_code, 0) << tag << "\n" << st.output;
      EXPECT_EQ(target_lines(st.output), measured) << tag;
      expect_same_files(mem_dir, out, tag);
    }
  }
}

// The shipped coherent SAR (4 looks, NESZ) with the corner reflectors on
// the standard scene: streamed in blocks of 7, 16 and all lines (each with
// its halo of lines for the azimuth response), on 1 and 2 threads, the
// in-memory files byte for byte and the same printed measurements.
TEST(StreamTargetsCli, CoherentSarWithTargetsEqualsInMemory) {
  test::TempDir dir;
  const std::string scene = standard_scene(dir);
  const std::string radar =
      (fs::path(test::data_dir()) / "radars" / "sar-x-band-stripmap.toml").string();
  const std::string args =
      " --scene " + scene + " --radar " + radar + " --targets " + corner_reflectors() + " --out ";
  for (const char* threads : {"1", "2"}) {
    const fs::path mem_dir = dir / ("mem-" + std::string(threads));
    const auto mem = test::run_ris(std::string("simulate --quiet --threads ") + threads + args +
                                   mem_dir.string());
    ASSERT_EQ(mem.exit_code, 0) << mem.output;
    EXPECT_NE(mem.output.find("(coherent SAR)"), std::string::npos) << mem.output;
    const std::string measured = target_lines(mem.output);
    EXPECT_NE(measured.find("PSLR"), std::string::npos) << mem.output;
    for (const char* block : {"7", "16", "700"}) {
      const std::string tag = std::string("coherent, threads ") + threads + ", block " + block;
      const fs::path out = dir / ("st-" + std::string(threads) + "-" + block);
      const auto st = test::run_ris(std::string("simulate --quiet --threads ") + threads +
                                    " --block-lines " + block + args + out.string());
      ASSERT_EQ(st.exit_code, 0) << tag << "\n" << st.output;
      EXPECT_EQ(target_lines(st.output), measured) << tag;
      expect_same_files(mem_dir, out, tag);
    }
  }
}

// The line the PPI summary reports its targets on.
std::string ppi_target_line(const std::string& output) {
  const auto at = output.find("point targets:");
  if (at == std::string::npos) return "";
  return output.substr(at, output.find('\n', at) - at);
}

// A streamed PPI takes point targets (src/sim/targets/ppi_ray_targets.h): the
// in-memory run's files byte for byte (metadata.json's seen and hidden
// included) and the same printed count, in blocks of 7 rays and the
// default, on 1 and 2 threads.
TEST(StreamTargetsCli, StreamedPpiTakesTargets) {
  test::TempDir dir;
  const std::string scene = standard_scene(dir);
  const std::string args =
      " --scene " + scene + " --radar " +
      (fs::path(test::data_dir()) / "radars" / "ppi-ground-mast-30m.toml").string() +
      " --targets " + corner_reflectors() + " --out ";
  for (const char* threads : {"1", "2"}) {
    const std::string run = std::string("simulate --quiet --threads ") + threads;
    const fs::path mem_dir = dir / ("mem-" + std::string(threads));
    const auto mem = test::run_ris(run + args + mem_dir.string());
    ASSERT_EQ(mem.exit_code, 0) << mem.output;
    const std::string counted = ppi_target_line(mem.output);
    // CR far lies in the shadow of the terrain seen from the 30 m mast.
    EXPECT_EQ(counted, "point targets: 2 seen, 1 hidden") << mem.output;
    for (const auto& [blocks, name] : {std::pair{" --block-lines 7", "b7"}, {" --stream", "s"}}) {
      const fs::path out = dir / ("stream-" + std::string(threads) + name);
      const auto r = test::run_ris(run + blocks + args + out.string());
      const std::string tag = std::string(threads) + " threads," + blocks;
      ASSERT_EQ(r.exit_code, 0) << tag << "\n" << r.output;
      EXPECT_EQ(ppi_target_line(r.output), counted) << tag << "\n" << r.output;
      int files = 0;
      for (const auto& e : fs::directory_iterator(mem_dir)) {
        EXPECT_TRUE(test::read_file(e.path()) == test::read_file(out / e.path().filename()))
            << tag << ": " << e.path().filename();
        ++files;
      }
      EXPECT_EQ(files, 8) << tag;  // 7 products and metadata.json
    }
  }
}

}  // namespace
}  // namespace ris
