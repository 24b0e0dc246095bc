// `ris simulate --stream` / `--block-lines` and `ris scene fractal
// --generator noise` end to end.
#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>

#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// The standard scene as a raster, simulated in memory and streamed: the same
// bytes in every product.
TEST(StreamCli, StreamedRunWritesTheSameFiles) {
  test::TempDir dir;
  const std::string scene = (dir / "std.tif").string();
  ASSERT_EQ(test::run_ris("scene build -o " + scene).exit_code, 0);
  const auto mem = test::run_ris("simulate --quiet --threads 2 --scene " + scene + " --out " +
                                 (dir / "mem").string());
  ASSERT_EQ(mem.exit_code, 0) << mem.output;
  const auto st = test::run_ris("simulate --threads 2 --block-lines 96 --scene " + scene +
                                " --out " + (dir / "st").string());
  ASSERT_EQ(st.exit_code, 0) << st.output;
  EXPECT_NE(st.output.find("streamed in 8 blocks of 96 lines"), std::string::npos) << st.output;
  int files = 0;
  for (const auto& e : fs::directory_iterator(dir / "mem")) {
    const fs::path other = dir / "st" / e.path().filename();
    EXPECT_TRUE(test::read_file(e.path()) == test::read_file(other)) << e.path().filename();
    ++files;
  }
  EXPECT_EQ(files, 12);  // geocoded_grey.png too
}

// The files of `a` and `b`: the same names, byte for byte; their count.
int expect_same_folder_bytes(const fs::path& a, const fs::path& b, const std::string& tag) {
  int files = 0, others = 0;
  for (const auto& e : fs::directory_iterator(a)) {
    const fs::path other = b / e.path().filename();
    EXPECT_TRUE(fs::exists(other)) << tag << ": " << other;
    if (fs::exists(other)) {
      EXPECT_TRUE(test::read_file(e.path()) == test::read_file(other))
          << tag << ": " << e.path().filename();
    }
    ++files;
  }
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(b)) ++others;
  EXPECT_EQ(files, others) << tag;
  return files;
}

// A streamed run honours --products (only the selected products and
// metadata.json, listing them) and --compress (a preset other than the
// default): the in-memory run's files, byte for byte, for SLAR, the
// incoherent SAR and PPI; an unknown stem fails as in memory.
TEST(StreamCli, ProductsAndCompressGiveTheInMemoryBytes) {
  test::TempDir dir;
  const std::string slar_scene = (dir / "slar.tif").string();
  const std::string ppi_scene = (dir / "ppi.tif").string();
  ASSERT_EQ(test::run_ris("scene fractal --quiet --generator noise --size 300x200 --cell-size 10 "
                          "--relief 300 --base 50 -o " +
                          slar_scene)
                .exit_code,
            0);
  ASSERT_EQ(test::run_ris("scene fractal --quiet --generator noise --size 200x600 --cell-size 30 "
                          "--relief 300 --base 50 --patches 1,2,3 -o " +
                          ppi_scene)
                .exit_code,
            0);
  const std::string radars = std::string(test::data_dir()) + "/radars/";
  struct Case {
    std::string radar, scene, options;
    int files;  // products and metadata.json
  };
  const Case cases[] = {
      {"seed-fig4-5.toml", slar_scene,
       "--products slant_range,scene_mask,geocoded_grey --compress small", 5},  // + its PNG
      {"seed-fig4-5.toml", slar_scene, "--compress none", 12},
      {"sar-x-band-stripmap.toml", slar_scene,
       "--products mean_power_slant,ground_range --compress small", 3},
      {"ppi-ground-mast-30m.toml", ppi_scene, "--products ppi_scope,mask_bscope --compress small",
       3},
      {"ppi-ground-mast-30m.toml", ppi_scene, "--compress none", 8},
  };
  int k = 0;
  for (const Case& c : cases) {
    const std::string tag = c.radar + " " + c.options;
    const std::string args = "simulate --quiet --threads 1 --scene " + c.scene + " --radar " +
                             radars + c.radar + " " + c.options;
    const fs::path mem = dir / ("mem" + std::to_string(k)), st = dir / ("st" + std::to_string(k));
    ++k;
    const auto m = test::run_ris(args + " --out " + mem.string());
    ASSERT_EQ(m.exit_code, 0) << tag << "\n" << m.output;
    const auto s = test::run_ris(args + " --stream --block-lines 16 --out " + st.string());
    ASSERT_EQ(s.exit_code, 0) << tag << "\n" << s.output;
    EXPECT_EQ(expect_same_folder_bytes(mem, st, tag), c.files) << tag;
  }
  const auto bad = test::run_ris("simulate --quiet --stream --scene " + slar_scene +
                                 " --products slant_range,bscope --out " + (dir / "bad").string());
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  EXPECT_NE(bad.output.find("\"bscope\""), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir / "bad"));
}

TEST(StreamCli, BadInputsFailWithoutOutput) {
  test::TempDir dir;
  const std::string out = (dir / "out").string();
  auto r = test::run_ris("simulate --stream --scene " + (dir / "missing.tif").string() + " --out " +
                         out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("missing.tif"), std::string::npos) << r.output;
  r = test::run_ris("simulate --stream --out " + out);  // the default scene is a description
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("ris scene build"), std::string::npos) << r.output;
  r = test::run_ris("simulate --block-lines -3 --out " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--block-lines"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(StreamCli, NoiseFractalIsATiledCompressedScene) {
  test::TempDir dir;
  const std::string path = (dir / "n.tif").string();
  const auto r = test::run_ris(
      "scene fractal --generator noise --size 300x200 --cell-size 10 "
      "--relief 400 --base 50 -o " +
      path);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RasterF64 s = read_raster_f64(path);
  EXPECT_EQ(s.cols, 300);
  EXPECT_EQ(s.rows, 200);
  EXPECT_EQ(s.metadata.at("RIS_SCENE"), "1");
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < 300 * 200; ++i) lo = std::min(lo, s.data[i]), hi = std::max(hi, s.data[i]);
  EXPECT_GE(lo, 50.0);
  EXPECT_LE(hi, 450.0);
  EXPECT_GT(hi - lo, 380.0);
  // Tiled (square blocks, not strips of rows) and compressed, as the name says.
  GDALAllRegister();
  std::unique_ptr<GDALDataset> ds(GDALDataset::Open(path.c_str(), GDAL_OF_RASTER));
  ASSERT_TRUE(ds);
  int bx = 0, by = 0;
  ds->GetRasterBand(1)->GetBlockSize(&bx, &by);
  EXPECT_LT(bx, 300);
  EXPECT_EQ(bx, by);
  const char* compression = ds->GetMetadataItem("COMPRESSION", "IMAGE_STRUCTURE");
  ASSERT_NE(compression, nullptr);
  EXPECT_NE(std::string(compression), "NONE");
  EXPECT_NE(test::run_ris("scene fractal --generator fft -o " + path).exit_code, 0);
}

}  // namespace
}  // namespace ris
