// End-to-end: `ris simulate --calibrated` (docs/outputs.md, "Calibrated
// products") writes the image after fading as sigma0, beta0 and gamma0,
// linear and in dB, each the power times its range bin's factor, NaN where
// no data; a run without it keeps its files; what cannot be calibrated yet
// is refused naming the flag or key, leaving the folder as it was. The
// physics (flat ground reads sigma0(theta)) is src/sim/modes/
// calibrated_image_test.cpp's.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "acquisition_paths.h"
#include "build_paths.h"
#include "refusal_checks.h"
#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

TEST(CalibratedCli, WritesTheCoefficientsAsThePowerTimesEachBinsFactor) {
  test::TempDir dir;
  const fs::path out = dir / "out";
  const test::RunResult r = test::run_ris(
      "simulate --quiet --calibrated --products "
      "speckled_power_slant,sigma0_slant,sigma0_slant_db,beta0_slant,gamma0_slant --out " +
      test::q(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::listing(out),
            (std::set<std::string>{"metadata.json", "speckled_power_slant.tif", "sigma0_slant.tif",
                                   "sigma0_slant_db.tif", "beta0_slant.tif", "gamma0_slant.tif"}));
  const RasterF64 p = read_raster_f64(out / "speckled_power_slant.tif");
  const RasterF64 s0 = read_raster_f64(out / "sigma0_slant.tif");
  const RasterF64 db = read_raster_f64(out / "sigma0_slant_db.tif");
  const RasterF64 b0 = read_raster_f64(out / "beta0_slant.tif");
  const RasterF64 g0 = read_raster_f64(out / "gamma0_slant.tif");
  ASSERT_EQ(s0.cols, p.cols);
  ASSERT_EQ(s0.rows, p.rows);
  ASSERT_TRUE(s0.nodata && std::isnan(*s0.nodata));
  // Per bin one factor (the first line with power sets it); beta0 / sigma0 =
  // 1 / sin and gamma0 / sigma0 = 1 / cos of one angle: 1/b^2 + 1/g^2 = 1.
  int checked = 0, nan_alike = 0;
  for (int b = 0; b < p.cols; b += 4) {
    double factor = 0.0;
    for (int line = 0; line < p.rows; line += 7) {
      const std::size_t i = static_cast<std::size_t>(line) * p.cols + b;
      if (std::isnan(p.data[i])) {
        nan_alike += std::isnan(s0.data[i]) && std::isnan(db.data[i]);
        continue;
      }
      if (p.data[i] <= 0.0) continue;
      const double f = s0.data[i] / p.data[i];
      if (factor == 0.0) factor = f;
      EXPECT_NEAR(f / factor, 1.0, 1e-6) << b;  // float32 rounding
      EXPECT_NEAR(db.data[i], 10.0 * std::log10(s0.data[i]), 1e-4);
      const double rb = s0.data[i] / b0.data[i], rg = s0.data[i] / g0.data[i];
      EXPECT_NEAR(rb * rb + rg * rg, 1.0, 1e-5);
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
  EXPECT_GT(nan_alike, 0);  // the standard scene has no-data pixels
  const nlohmann::json m = nlohmann::json::parse(test::read_file(out / "metadata.json"));
  EXPECT_TRUE(m["products"].contains("sigma0_slant_db.tif")) << m["products"].dump(1);
  EXPECT_FALSE(m["products"].contains("gamma0_slant_db.tif"));
}

TEST(CalibratedCli, WithoutTheFlagOnlyANamedCoefficientIsWritten) {
  test::TempDir dir;
  test::RunResult r = test::run_ris(
      "simulate --quiet --products mean_power_slant,gamma0_slant_db --out " + test::q(dir / "a"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(
      test::listing(dir / "a"),
      (std::set<std::string>{"metadata.json", "mean_power_slant.tif", "gamma0_slant_db.tif"}));
  r = test::run_ris("simulate --quiet --products mean_power_slant,mask_slant --calibrated --out " +
                    test::q(dir / "b"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::listing(dir / "b"),
            (std::set<std::string>{"metadata.json", "mean_power_slant.tif", "mask_slant.tif"}));
}

// On a product's grid the image is beta0 as a NISAR RSLC's |z|^2 is: the
// same units for `ris compare` (docs/outputs.md).
TEST(CalibratedCli, AnAcquisitionRunWritesBeta0OnTheProductsGrid) {
  test::TempDir dir;
  const test::RunResult r = test::run_ris(
      "simulate --quiet -a " + test::winnipeg_h5() + " --dem " +
      test::q(test::test_dem("winnipeg_dem.tif")) +
      " --calibrated --products beta0_slant,sigma0_slant_db --out " + test::q(dir / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(test::listing(dir / "out"),
            (std::set<std::string>{"metadata.json", "beta0_slant.tif", "sigma0_slant_db.tif"}));
  const RasterF64 b0 = read_raster_f64(dir / "out" / "beta0_slant.tif");
  const RasterF64 s0 = read_raster_f64(dir / "out" / "sigma0_slant_db.tif");
  EXPECT_EQ(b0.cols, 250);
  EXPECT_EQ(b0.rows, 250);
  // sigma0 = beta0 sin(theta) with theta in (0, 90) deg: below beta0.
  int below = 0, finite = 0;
  for (std::size_t i = 0; i < b0.data.size(); ++i) {
    if (!std::isfinite(b0.data[i]) || !std::isfinite(s0.data[i]) || b0.data[i] <= 0.0) continue;
    ++finite;
    below += s0.data[i] < 10.0 * std::log10(b0.data[i]);
  }
  EXPECT_GT(finite, 50000);
  EXPECT_EQ(below, finite);
}

TEST(CalibratedCli, WhatCannotBeCalibratedIsRefusedNamingTheKey) {
  test::TempDir dir;
  const std::set<std::string> before = test::listing(dir.path());
  const auto refused = [&](const std::string& args, const std::string& key) {
    const test::RunResult r =
        test::run_ris("simulate --quiet " + args + " --out " + test::q(dir / "out"));
    test::expect_refused(r, 1, key, dir.path(), before);
  };
  refused("--calibrated --stream", "--calibrated");
  refused("--products sigma0_slant --block-lines 64", "--calibrated");
  refused("--calibrated --radar " + test::q(test::data("radars/ppi-ground-mast-30m.toml")),
          "--calibrated");
  test::write_file(dir / "r.toml", test::read_file(test::data("radars/seed-fig4-5.toml")) +
                                       "\n[film.terms]\nrange = false\n");
  const std::set<std::string> with_radar = test::listing(dir.path());
  const test::RunResult r =
      test::run_ris("simulate --quiet --calibrated --radar " + test::q(dir / "r.toml") + " --out " +
                    test::q(dir / "out"));
  test::expect_refused(r, 1, "film.terms.range", dir.path(), with_radar);
}

}  // namespace
}  // namespace ris
