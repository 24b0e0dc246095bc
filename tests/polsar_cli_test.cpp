// ris polsar end to end: a simulated quad-pol SLC set (the category
// covariances' sampler) through the command, against Orfeo ToolBox's
// H/A/alpha of the same SLCs, on NISAR products, and its refusals.
#include <fmt/format.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <hdf5.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <vector>

#include "ris/backscatter/category_covariance.h"
#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;
using test::q;
using test::run_ris;
using test::TempDir;

constexpr const char* kSanAnd = "/work/shared/data/real/SanAnd_138.h5";
constexpr const char* kOtb = "/usr/bin/otbcli_SARDecompositions";

void write_cfloat(const fs::path& p, const std::vector<std::complex<float>>& v, int cols,
                  int rows) {
  ensure_gdal_registered();
  GDALDatasetH ds =
      GDALCreate(GDALGetDriverByName("GTiff"), p.c_str(), cols, rows, 1, GDT_CFloat32, nullptr);
  ASSERT_NE(ds, nullptr);
  ASSERT_EQ(
      GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, cols, rows,
                   const_cast<std::complex<float>*>(v.data()), cols, rows, GDT_CFloat32, 0, 0),
      CE_None);
  GDALClose(ds);
}

// Band b (from 1) of a raster as doubles (the real part of a complex band).
std::vector<double> read_band(const fs::path& p, int b, int* cols = nullptr, int* rows = nullptr) {
  ensure_gdal_registered();
  GDALDatasetH ds = GDALOpen(p.c_str(), GA_ReadOnly);
  EXPECT_NE(ds, nullptr) << p;
  if (ds == nullptr) return {};
  const int c = GDALGetRasterXSize(ds), r = GDALGetRasterYSize(ds);
  std::vector<double> v(static_cast<std::size_t>(c) * r);
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, b), GF_Read, 0, 0, c, r, v.data(), c, r, GDT_Float64,
                         0, 0),
            CE_None);
  if (cols != nullptr) *cols = c;
  if (rows != nullptr) *rows = r;
  GDALClose(ds);
  return v;
}

std::string band_name(const fs::path& p, int b) {
  GDALDatasetH ds = GDALOpen(p.c_str(), GA_ReadOnly);
  const std::string s = GDALGetDescription(GDALGetRasterBand(ds, b));
  GDALClose(ds);
  return s;
}

// A 48 x 48 quad-pol set in four 24 x 24 quadrants of known covariance: a
// coherent surface (HH, VV fully correlated), bare soil (rho 0.85), a dipole
// volume and a double-bounce-like mixture (Re C13 < 0). HV = VH.
struct SimulatedSet {
  int n = 48;
  fs::path hh, hv, vh, vv;
};

SimulatedSet simulate(const TempDir& dir) {
  SimulatedSet s;
  const auto c3 = [](double c11, double c22, double c33, Complex c13) {
    Hermitian3 c;
    c(0, 0) = c11;
    c(1, 1) = c22;
    c(2, 2) = c33;
    c(0, 2) = c13;
    c(2, 0) = std::conj(c13);
    return c;
  };
  const std::array<Hermitian3, 4> quadrant = {
      c3(0.04, 0.0, 0.09, 0.06), c3(0.05, 0.004, 0.07, 0.85 * std::sqrt(0.05 * 0.07)),
      c3(0.3, 0.2, 0.3, 0.1), c3(0.5, 0.05, 0.3, Complex(-0.2, 0.1))};
  std::array<std::vector<std::complex<float>>, 3> ch;
  for (auto& v : ch) v.resize(static_cast<std::size_t>(s.n * s.n));
  for (int r = 0; r < s.n; ++r) {
    for (int c = 0; c < s.n; ++c) {
      const int qd = (r >= s.n / 2 ? 2 : 0) + (c >= s.n / 2 ? 1 : 0);
      const CovarianceSampler sampler(quadrant[static_cast<std::size_t>(qd)]);
      const std::size_t i = static_cast<std::size_t>(r * s.n + c);
      const Vector3c k = sampler.sample(2026, i);
      ch[0][i] = std::complex<float>(k[0]);
      ch[1][i] = std::complex<float>(k[1] / std::sqrt(2.0));
      ch[2][i] = std::complex<float>(k[2]);
    }
  }
  s.hh = dir / "hh.tif";
  s.hv = dir / "hv.tif";
  s.vh = dir / "vh.tif";
  s.vv = dir / "vv.tif";
  write_cfloat(s.hh, ch[0], s.n, s.n);
  write_cfloat(s.hv, ch[1], s.n, s.n);
  write_cfloat(s.vh, ch[1], s.n, s.n);
  write_cfloat(s.vv, ch[2], s.n, s.n);
  return s;
}

std::string rasters(const SimulatedSet& s) {
  return "--hh " + q(s.hh) + " --hv " + q(s.hv) + " --vh " + q(s.vh) + " --vv " + q(s.vv);
}

TEST(PolsarCli, WritesEveryProductWithNamedBands) {
  TempDir dir;
  const SimulatedSet s = simulate(dir);
  const fs::path out = dir / "polsar";
  const auto r = run_ris("polsar " + rasters(s) + " --window 5 --out " + q(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f :
       {"c3.tif", "t3.tif", "h_a_alpha.tif", "freeman_durden.tif", "pauli.png", "metadata.json"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  EXPECT_EQ(band_name(out / "c3.tif", 2), "C12_real");
  EXPECT_EQ(band_name(out / "c3.tif", 9), "C33");
  EXPECT_EQ(band_name(out / "t3.tif", 5), "T13_imag");
  EXPECT_EQ(band_name(out / "h_a_alpha.tif", 3), "alpha_deg");
  EXPECT_EQ(band_name(out / "freeman_durden.tif", 2), "Freeman_Dbl");
  // The first quadrant (rank-one surface) has low entropy, the volume high.
  const std::vector<double> h = read_band(out / "h_a_alpha.tif", 1);
  EXPECT_LT(h[static_cast<std::size_t>(10 * s.n + 10)], 0.3);
  EXPECT_GT(h[static_cast<std::size_t>(34 * s.n + 10)], 0.8);
  // C11 averaged over the surface quadrant's interior: the category's 0.04 within speckle.
  const std::vector<double> c11 = read_band(out / "c3.tif", 1);
  double m = 0.0;
  for (int rr = 4; rr < 20; ++rr)
    for (int cc = 4; cc < 20; ++cc) m += c11[static_cast<std::size_t>(rr * s.n + cc)];
  EXPECT_NEAR(m / 256.0, 0.04, 0.004);
}

// OTB 8.1's SARDecompositions (haa): inco.kernelsize is the RADIUS of its
// itk::MeanImageFilter (kernelsize 1 = a 3 x 3 box, edges by zero-flux
// Neumann replication, so only pixels a radius from the edge compare); it
// takes one of HV and VH (HV here; ris averages them, equal here); its
// output is complex, the real parts of bands 1, 2, 3 are entropy (log 3),
// alpha in DEGREES and anisotropy (otbReciprocalHAlphaImageFilter.h).
TEST(PolsarCli, AgreesWithOrfeoToolBox) {
  if (!fs::exists(kOtb)) GTEST_SKIP() << "otb-bin is not installed (" << kOtb << ")";
  TempDir dir;
  const SimulatedSet s = simulate(dir);
  for (int radius : {1, 3}) {
    const int w = 2 * radius + 1;
    const fs::path out = dir / fmt::format("polsar{}", w);
    ASSERT_EQ(
        run_ris(fmt::format("polsar {} --window {} --out {}", rasters(s), w, q(out))).exit_code, 0);
    const fs::path otb = dir / fmt::format("otb_haa{}.tif", w);
    const std::string cmd = fmt::format(
        "{} -inhh {} -inhv {} -invv {} -decomp haa -inco.kernelsize {} -out {} cfloat "
        "> {} 2>&1",
        kOtb, q(s.hh), q(s.hv), q(s.vv), radius, q(otb), q(dir / "otb.log"));
    ASSERT_EQ(std::system(cmd.c_str()), 0) << test::read_file(dir / "otb.log");
    const std::vector<double> h = read_band(out / "h_a_alpha.tif", 1);
    const std::vector<double> a = read_band(out / "h_a_alpha.tif", 2);
    const std::vector<double> al = read_band(out / "h_a_alpha.tif", 3);
    const std::vector<double> oh = read_band(otb, 1), oal = read_band(otb, 2),
                              oa = read_band(otb, 3);
    double dh = 0.0, dal = 0.0, da = 0.0, mean_dal = 0.0;
    int n = 0;
    for (int r = radius; r < s.n - radius; ++r) {
      for (int c = radius; c < s.n - radius; ++c) {
        const auto i = static_cast<std::size_t>(r * s.n + c);
        dh = std::max(dh, std::abs(h[i] - oh[i]));
        dal = std::max(dal, std::abs(al[i] - oal[i]));
        da = std::max(da, std::abs(a[i] - oa[i]));
        mean_dal += std::abs(al[i] - oal[i]);
        ++n;
      }
    }
    EXPECT_LT(dal, 0.5) << "alpha (deg), window " << w;
    EXPECT_LT(dh, 0.01) << "entropy, window " << w;
    EXPECT_LT(da, 0.01) << "anisotropy, window " << w;
    RecordProperty(fmt::format("w{}_max_abs_diff_alpha_deg", w), fmt::format("{:.3g}", dal));
    RecordProperty(fmt::format("w{}_max_abs_diff_entropy", w), fmt::format("{:.3g}", dh));
    RecordProperty(fmt::format("w{}_max_abs_diff_anisotropy", w), fmt::format("{:.3g}", da));
    std::printf(
        "ris vs OTB, %d x %d window, %d interior pixels: max |d alpha| %.3g deg (mean "
        "%.3g), max |d H| %.3g, max |d A| %.3g\n",
        w, w, n, dal, mean_dal / n, dh, da);
  }
}

// The Pauli components: OTB's -decomp pauli gives (HH+VV)/sqrt2, (HH-VV)/sqrt2,
// sqrt2 HV (complex); their powers are ris's single-look T11, T22, T33, the
// blue, red and green of pauli.png.
TEST(PolsarCli, PauliComponentsAgreeWithOrfeoToolBox) {
  if (!fs::exists(kOtb)) GTEST_SKIP() << "otb-bin is not installed (" << kOtb << ")";
  TempDir dir;
  const SimulatedSet s = simulate(dir);
  const fs::path out = dir / "polsar";
  ASSERT_EQ(run_ris("polsar " + rasters(s) + " --window 1 --out " + q(out)).exit_code, 0);
  const fs::path otb = dir / "otb_pauli.tif";
  const std::string cmd =
      fmt::format("{} -inhh {} -inhv {} -invv {} -decomp pauli -out {} cfloat > {} 2>&1", kOtb,
                  q(s.hh), q(s.hv), q(s.vv), q(otb), q(dir / "otb.log"));
  ASSERT_EQ(std::system(cmd.c_str()), 0) << test::read_file(dir / "otb.log");
  ensure_gdal_registered();
  GDALDatasetH ds = GDALOpen(otb.c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  double worst = 0.0;
  const std::array<int, 3> t3_band = {1, 6, 9};  // T11, T22, T33
  for (int b = 0; b < 3; ++b) {
    std::vector<std::complex<double>> v(static_cast<std::size_t>(s.n * s.n));
    ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, b + 1), GF_Read, 0, 0, s.n, s.n, v.data(), s.n,
                           s.n, GDT_CFloat64, 0, 0),
              CE_None);
    const std::vector<double> t = read_band(out / "t3.tif", t3_band[static_cast<std::size_t>(b)]);
    for (std::size_t i = 0; i < v.size(); ++i)
      worst = std::max(worst, std::abs(t[i] - std::norm(v[i])) / std::max(t[i], 1e-12));
  }
  GDALClose(ds);
  EXPECT_LT(worst, 1e-5);
  RecordProperty("pauli_max_rel_diff", fmt::format("{:.3g}", worst));
}

TEST(PolsarCli, RefusesChannelsOnDifferentGrids) {
  TempDir dir;
  const SimulatedSet s = simulate(dir);
  write_cfloat(s.vh, std::vector<std::complex<float>>(47 * 48), 47, 48);
  const fs::path out = dir / "polsar";
  const auto r = run_ris("polsar " + rasters(s) + " --out " + q(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(s.vh.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(s.hh.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("47 x 48"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(PolsarCli, RefusesBadInputs) {
  TempDir dir;
  const SimulatedSet s = simulate(dir);
  const fs::path out = dir / "polsar";
  // A real (not complex) raster.
  const std::vector<float> real(48 * 48, 1.0f);
  write_geotiff<float>(dir / "real.tif", real.data(), 48, 48, nullptr);
  auto r = run_ris("polsar --hh " + q(dir / "real.tif") + " --hv " + q(s.hv) + " --vh " + q(s.vh) +
                   " --vv " + q(s.vv) + " --out " + q(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("complex"), std::string::npos) << r.output;
  // A missing channel, an even window, both kinds of input.
  r = run_ris("polsar --hh " + q(s.hh) + " --hv " + q(s.hv) + " --vv " + q(s.vv) + " --out " +
              q(out));
  EXPECT_NE(r.output.find("all four"), std::string::npos) << r.output;
  r = run_ris("polsar " + rasters(s) + " --window 4 --out " + q(out));
  EXPECT_NE(r.output.find("--window"), std::string::npos) << r.output;
  r = run_ris("polsar " + rasters(s) + " --window 3x --out " + q(out));
  EXPECT_NE(r.output.find("--window"), std::string::npos) << r.output;
  r = run_ris("polsar " + rasters(s) + " --product x.h5 --out " + q(out));
  EXPECT_NE(r.output.find("either"), std::string::npos) << r.output;
  r = run_ris("polsar --hh " + q(dir / "none.tif") + " --hv " + q(s.hv) + " --vh " + q(s.vh) +
              " --vv " + q(s.vv) + " --out " + q(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("none.tif"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

// The shared UAVSAR product lists HH, HV, VH, VV in listOfPolarizations but
// stores the HH layer only (the isce3 test excerpt): refused, naming what it
// holds. With HV, VH and VV layers added (copies of HH, through the HDF5
// library), the reader takes it.
TEST(PolsarCli, NisarProducts) {
  if (!fs::exists(kSanAnd)) GTEST_SKIP() << kSanAnd << " is not here";
  TempDir dir;
  const fs::path out = dir / "polsar";
  auto r = run_ris("polsar --product " + q(kSanAnd) + " --out " + q(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no SLC layer HV, VH, VV"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("holds HH"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("listOfPolarizations names HH, HV, VH, VV"), std::string::npos)
      << r.output;
  EXPECT_FALSE(fs::exists(out));
  const fs::path copy = dir / "quad.h5";
  fs::copy_file(kSanAnd, copy);
  {
    const hid_t f = H5Fopen(copy.c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    ASSERT_GE(f, 0);
    const std::string base = "/science/LSAR/SLC/swaths/frequencyA/";
    for (const char* pol : {"HV", "VH", "VV"}) {
      ASSERT_GE(
          H5Ocopy(f, (base + "HH").c_str(), f, (base + pol).c_str(), H5P_DEFAULT, H5P_DEFAULT), 0);
    }
    H5Fclose(f);
  }
  r = run_ris("polsar --product " + q(copy) + " --window 3 --out " + q(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  int cols = 0, rows = 0;
  const std::vector<double> h = read_band(out / "h_a_alpha.tif", 1, &cols, &rows);
  EXPECT_EQ(cols, 400);
  EXPECT_EQ(rows, 150);
  // HV = HH = VV at every pixel: k_P = [2 HH, 0, 2 HH] / sqrt2, rank one over
  // any window: H 0 and alpha acos(1 / sqrt2) = 45 deg wherever the product
  // holds data.
  const std::vector<double> al = read_band(out / "h_a_alpha.tif", 3);
  int checked = 0;
  for (std::size_t i = 0; i < h.size(); ++i) {
    if (!std::isfinite(h[i])) continue;
    EXPECT_NEAR(h[i], 0.0, 1e-3);
    EXPECT_NEAR(al[i], 45.0, 0.01);
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace
}  // namespace ris
