// Dual- and compact-pol syntheses against closed forms: a trihedral is all
// odd bounce in m-chi (m = 1, chi = 45 deg), a dihedral and a dihedral
// rolled 45 deg all even bounce; a random dipole volume is unpolarised
// under circular transmit (m = 0: <|RH|^2> = <|RV|^2>, <RH RV*> = 0 for
// C3 = [1 0 1/3; 0 2/3 0; 1/3 0 1]); the dual-pol pairs are the channels.
#include "ris/image/polsar/pol_synthesis.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

#include "ris/backscatter/category_covariance.h"

namespace ris {
namespace {

using cf = std::complex<float>;

QuadPolSlc one_pixel(cf hh, cf hv, cf vv) {
  QuadPolSlc s;
  s.cols = s.rows = 1;
  s.hh = {hh};
  s.hv = {hv};
  s.vh = {hv};
  s.vv = {vv};
  return s;
}

StokesMChi compact_of(const QuadPolSlc& s) {
  const CovarianceImage c2 =
      boxcar_c2(synthesise_two_channel(s, TwoChannelMode::compact_ctlr), 1, 1);
  return stokes_m_chi(c2.m[0]);
}

constexpr double kPi = 3.14159265358979323846;

TEST(PolSynthesis, TrihedralIsAllOddBounce) {
  const StokesMChi p = compact_of(one_pixel(1.0f, 0.0f, 1.0f));
  EXPECT_NEAR(p.g0, 1.0, 1e-6);  // |S|^2 span 2, half of it per circular transmit
  EXPECT_NEAR(p.g3, -1.0, 1e-6);
  EXPECT_NEAR(p.m, 1.0, 1e-6);
  EXPECT_NEAR(p.chi_rad, kPi / 4.0, 1e-3);
  EXPECT_NEAR(p.odd, 1.0, 1e-6);
  EXPECT_NEAR(p.even, 0.0, 1e-6);
  EXPECT_NEAR(p.volume, 0.0, 1e-6);
}

TEST(PolSynthesis, DihedralsAreAllEvenBounce) {
  for (const QuadPolSlc& s : {one_pixel(1.0f, 0.0f, -1.0f), one_pixel(0.0f, 1.0f, 0.0f)}) {
    const StokesMChi p = compact_of(s);
    EXPECT_NEAR(p.m, 1.0, 1e-6);
    EXPECT_NEAR(p.chi_rad, -kPi / 4.0, 1e-3);
    EXPECT_NEAR(p.even, p.g0, 1e-6);
    EXPECT_NEAR(p.odd, 0.0, 1e-6);
  }
}

TEST(PolSynthesis, CompactFieldsAreTheCircularTransmitCombinations) {
  const QuadPolSlc s = one_pixel(cf(0.3f, 0.1f), cf(-0.2f, 0.4f), cf(0.5f, -0.7f));
  const TwoChannelSlc c = synthesise_two_channel(s, TwoChannelMode::compact_ctlr);
  const cf i(0.0f, 1.0f);
  const float r = 1.0f / std::sqrt(2.0f);
  EXPECT_NEAR(std::abs(c.a[0] - (s.hh[0] - i * s.vh[0]) * r), 0.0, 1e-6);
  EXPECT_NEAR(std::abs(c.b[0] - (s.hv[0] - i * s.vv[0]) * r), 0.0, 1e-6);
  EXPECT_EQ(c.a_name, "RH");
  const TwoChannelSlc h = synthesise_two_channel(s, TwoChannelMode::dual_h);
  const TwoChannelSlc v = synthesise_two_channel(s, TwoChannelMode::dual_v);
  EXPECT_EQ(h.a[0], s.hh[0]);
  EXPECT_EQ(h.b[0], s.hv[0]);
  EXPECT_EQ(v.a[0], s.vv[0]);
  EXPECT_EQ(v.b[0], s.vh[0]);
}

// 300 x 300 dipole-volume pixels from the covariance sampler, one 301 x 301
// boxcar value at the centre (all 90,000 pixels): the Stokes ratios' standard
// errors are about 1/sqrt(90,000) = 0.003, so m < 0.02.
TEST(PolSynthesis, RandomVolumeIsUnpolarisedUnderCircularTransmit) {
  Hermitian3 c3;
  c3(0, 0) = 1.0;
  c3(1, 1) = 2.0 / 3.0;
  c3(2, 2) = 1.0;
  c3(0, 2) = 1.0 / 3.0;
  c3(2, 0) = 1.0 / 3.0;
  const CovarianceSampler sampler(c3);
  QuadPolSlc s;
  s.cols = s.rows = 300;
  const std::size_t n = 300 * 300;
  for (std::size_t i = 0; i < n; ++i) {
    const Vector3c k = sampler.sample(3, i);
    const cf hv(k[1] / std::sqrt(2.0));
    s.hh.push_back(cf(k[0]));
    s.hv.push_back(hv);
    s.vh.push_back(hv);
    s.vv.push_back(cf(k[2]));
  }
  const CovarianceImage c2 =
      boxcar_c2(synthesise_two_channel(s, TwoChannelMode::compact_ctlr), 301, 301);
  const StokesMChi p = stokes_m_chi(c2.m[150 * 300 + 150]);
  EXPECT_NEAR(p.g0, (1.0 + 2.0 / 3.0 + 1.0) / 2.0, 0.02);  // span / 2
  EXPECT_LT(p.m, 0.02);
  EXPECT_NEAR(p.volume / p.g0, 1.0, 0.02);
}

}  // namespace
}  // namespace ris
