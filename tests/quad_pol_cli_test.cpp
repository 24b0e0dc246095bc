// A quad-pol SAR run end to end (docs/polarimetry.md, "Simulated quad-pol
// images"): `ris simulate` with the shipped quad-pol town radar on a plain
// with three reflectors writes four complex SLCs with slant-range GCPs, the
// polsar products of the set and the quad_pol block of metadata.json; the
// reflectors decompose as their Sinclair matrices say (a trihedral's alpha
// near 0 deg, a dihedral's near 90 deg, a dihedral rolled 45 deg about the
// line of sight pure HV); what a quad-pol run cannot do is refused naming
// the key, leaving nothing.
#include <gdal.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "build_paths.h"
#include "refusal_checks.h"
#include "ris/io/gdal_util.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;
using test::q;
using test::run_ris;
using test::TempDir;

// Three 1 m reflectors on a 600 m x 200 m plain of 2 m cells, each pointed
// at the radar (facing west, tilt atan(6000 / 7400) = 39.04 deg): a
// trihedral, a dihedral and a dihedral rolled 45 deg about its boresight.
constexpr const char* kScene = R"(name = "three reflectors"
[grid]
rows = 100
cols = 300
cell_size = 2.0
base_category = 1

[[object]]
type = "reflector"
shape = "trihedral"
x = 150
y = 100
size = 1.0
azimuth = 180
tilt = 39.04

[[object]]
type = "reflector"
shape = "dihedral"
x = 300
y = 100
size = 1.0
azimuth = 180
tilt = 39.04

[[object]]
type = "reflector"
shape = "dihedral"
x = 450
y = 100
size = 1.0
azimuth = 180
tilt = 39.04
roll = 45
)";

std::string radar() {
  return std::string(test::data_dir()) + "/radars/sar-x-band-town-quadpol.toml";
}

struct Raster {
  int cols = 0, rows = 0;
  std::vector<std::complex<double>> v;
  std::complex<double> at(int r, int c) const {
    return v[static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + c];
  }
};

// Band b (from 1) of a raster as complex doubles; the GDAL type in *type.
Raster read_band(const fs::path& p, int b, GDALDataType* type = nullptr) {
  ensure_gdal_registered();
  Raster out;
  GDALDatasetH ds = GDALOpen(p.c_str(), GA_ReadOnly);
  EXPECT_NE(ds, nullptr) << p;
  if (ds == nullptr) return out;
  out.cols = GDALGetRasterXSize(ds);
  out.rows = GDALGetRasterYSize(ds);
  GDALRasterBandH band = GDALGetRasterBand(ds, b);
  if (type != nullptr) *type = GDALGetRasterDataType(band);
  out.v.resize(static_cast<std::size_t>(out.cols) * out.rows);
  EXPECT_EQ(GDALRasterIO(band, GF_Read, 0, 0, out.cols, out.rows, out.v.data(), out.cols, out.rows,
                         GDT_CFloat64, 0, 0),
            CE_None);
  GDALClose(ds);
  return out;
}

int gcp_count(const fs::path& p) {
  GDALDatasetH ds = GDALOpen(p.c_str(), GA_ReadOnly);
  const int n = ds != nullptr ? GDALGetGCPCount(ds) : -1;
  if (ds != nullptr) GDALClose(ds);
  return n;
}

// The brightest pixel of |HH|^2 + 2|HV|^2 + |VV|^2 within the columns
// [c0, c1).
struct Peak {
  int r = 0, c = 0;
};
Peak brightest(const std::array<Raster, 4>& s, int c0, int c1) {
  Peak p;
  double best = -1.0;
  for (int r = 0; r < s[0].rows; ++r)
    for (int c = c0; c < c1; ++c) {
      const double span =
          std::norm(s[0].at(r, c)) + 2.0 * std::norm(s[1].at(r, c)) + std::norm(s[3].at(r, c));
      if (span > best) {
        best = span;
        p = {r, c};
      }
    }
  return p;
}

TEST(QuadPolCli, ReflectorsDecomposeAsTheirSinclairMatrices) {
  TempDir dir;
  const fs::path scene = dir.path() / "three.toml";
  test::write_file(scene, kScene);
  const fs::path out = dir.path() / "o";
  const auto r = run_ris("simulate --quiet --scene " + q(scene) + " --radar " + q(radar()) +
                         " --out " + q(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;

  std::array<Raster, 4> s;
  const std::array<const char*, 4> names = {"slc_hh.tif", "slc_hv.tif", "slc_vh.tif", "slc_vv.tif"};
  for (std::size_t c = 0; c < 4; ++c) {
    GDALDataType type = GDT_Unknown;
    s[c] = read_band(out / names[c], 1, &type);
    EXPECT_EQ(type, GDT_CFloat32) << names[c];
    EXPECT_GT(gcp_count(out / names[c]), 3) << names[c] << ": slant-range GCPs";
  }
  ASSERT_GT(s[0].cols, 0);
  const Raster alpha = read_band(out / "polsar" / "h_a_alpha.tif", 3);
  ASSERT_EQ(alpha.cols, s[0].cols);

  // The reflectors lie at increasing ground range, so at increasing slant
  // range: split the columns at the bins between them.
  std::vector<Peak> peaks;
  {
    // Slant range of ground range x at 6 km altitude, 7 km from the track.
    const auto bin = [&](double x_m) {
      return static_cast<int>((std::hypot(7000.0 + x_m, 6000.0) - 9150.0) / 0.5);
    };
    for (double x : {150.0, 300.0, 450.0}) {
      peaks.push_back(brightest(s, std::max(0, bin(x - 60.0)), std::min(s[0].cols, bin(x + 60.0))));
    }
  }
  const auto ratio_db = [&](const Peak& p, int a, int b) {
    return 10.0 * std::log10(std::norm(s[a].at(p.r, p.c)) / std::norm(s[b].at(p.r, p.c)));
  };
  // Trihedral: HH = VV in phase, no HV, alpha near 0 (7 x 7 boxcar over the
  // peak and its dark surroundings).
  const Peak& tri = peaks[0];
  EXPECT_NEAR(ratio_db(tri, 3, 0), 0.0, 0.5);
  EXPECT_NEAR(std::arg(s[3].at(tri.r, tri.c) / s[0].at(tri.r, tri.c)), 0.0, 0.2);
  EXPECT_LT(ratio_db(tri, 1, 0), -20.0);
  EXPECT_LT(alpha.at(tri.r, tri.c).real(), 10.0);
  // Dihedral: HH = -VV, alpha near 90.
  const Peak& di = peaks[1];
  EXPECT_NEAR(ratio_db(di, 3, 0), 0.0, 1.0);
  EXPECT_NEAR(std::abs(std::arg(s[3].at(di.r, di.c) / s[0].at(di.r, di.c))), M_PI, 0.2);
  EXPECT_LT(ratio_db(di, 1, 0), -20.0);
  EXPECT_GT(alpha.at(di.r, di.c).real(), 80.0);
  // Rolled by 45 deg: pure HV (HV = VH), alpha near 90.
  const Peak& rolled = peaks[2];
  EXPECT_GT(ratio_db(rolled, 1, 0), 20.0);
  EXPECT_GT(ratio_db(rolled, 1, 3), 20.0);
  EXPECT_NEAR(ratio_db(rolled, 2, 1), 0.0, 0.1);
  EXPECT_GT(alpha.at(rolled.r, rolled.c).real(), 80.0);

  // Compact pol (CTLR) of the same set: m-chi's odd bounce at the
  // trihedral, even bounce at the dihedral.
  const Raster odd = read_band(out / "polsar" / "m_chi.tif", 7);
  const Raster even = read_band(out / "polsar" / "m_chi.tif", 8);
  EXPECT_GT(odd.at(tri.r, tri.c).real(), 10.0 * even.at(tri.r, tri.c).real());
  EXPECT_GT(even.at(di.r, di.c).real(), 10.0 * odd.at(di.r, di.c).real());

  const nlohmann::json m = nlohmann::json::parse(test::read_file(out / "metadata.json"));
  ASSERT_TRUE(m.contains("quad_pol")) << m.dump(1);
  EXPECT_EQ(m["quad_pol"]["looks"], 1);
  EXPECT_EQ(m["quad_pol"]["channels"].size(), 4u);
  EXPECT_TRUE(m["products"].contains("slc_hh.tif"));
  for (const char* f :
       {"c3.tif", "t3.tif", "h_a_alpha.tif", "freeman_durden.tif", "pauli.png", "dual_h_c2.tif",
        "dual_v_c2.tif", "compact_rh.tif", "compact_rv.tif", "compact_c2.tif", "m_chi.tif"}) {
    EXPECT_TRUE(fs::exists(out / "polsar" / f)) << f;
  }
}

TEST(QuadPolCli, WhatAQuadPolRunCannotDoIsRefusedLeavingNothing) {
  TempDir dir;
  const fs::path scene = dir.path() / "three.toml";
  test::write_file(scene, kScene);
  std::string text = test::read_file(radar());
  const std::string coherent = "coherent = true\n";
  const auto at = text.find(coherent);
  ASSERT_NE(at, std::string::npos);

  // An incoherent quad-pol SAR: the radar file's key.
  std::string incoherent = text;
  incoherent.replace(at, coherent.size(), "coherent = false\n");
  const fs::path bad = dir.path() / "incoherent.toml";
  test::write_file(bad, incoherent);
  const std::set<std::string> with_bad = test::listing(dir.path());
  test::expect_refused(run_ris("simulate --quiet --scene " + q(scene) + " --radar " + q(bad) +
                               " --out " + q(dir.path() / "o")),
                       1, "quad_pol", dir.path(), with_bad);
  // Multilooked: the SLCs are single-look.
  std::string looks = text;
  looks.replace(at, coherent.size(), coherent + "range_looks = 2\n");
  test::write_file(bad, looks);
  test::expect_refused(run_ris("simulate --quiet --scene " + q(scene) + " --radar " + q(bad) +
                               " --out " + q(dir.path() / "o")),
                       1, "quad_pol", dir.path(), with_bad);
  // Streamed (a streamed run reads a scene raster): in memory only for now.
  const fs::path tif = dir.path() / "three.tif";
  ASSERT_EQ(run_ris("scene build " + q(scene) + " -o " + q(tif)).exit_code, 0);
  const std::set<std::string> with_tif = test::listing(dir.path());
  test::expect_refused(run_ris("simulate --quiet --scene " + q(tif) + " --radar " + q(radar()) +
                               " --stream --out " + q(dir.path() / "o")),
                       1, "sar.quad_pol", dir.path(), with_tif);
}

}  // namespace
}  // namespace ris
