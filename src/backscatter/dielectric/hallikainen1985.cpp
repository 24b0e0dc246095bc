// Hallikainen 1985: empirical polynomial fits of soil permittivity.
//
//   eps' (or eps'') = (a0 + a1 S + a2 C) + (b0 + b1 S + b2 C) mv
//                     + (c0 + c1 S + c2 C) mv^2
// with S and C the sand and clay contents in percent, mv in m3/m3, and one
// set of nine coefficients for eps' and for eps'' at each of 1.4, 4, 6, 8, 10,
// 12, 14, 16 and 18 GHz.
// Source: Hallikainen, M. T., Ulaby, F. T., Dobson, M. C., El-Rayes, M. A. &
// Wu, L.-K. (1985), "Microwave dielectric behavior of wet soil - Part I:
// Empirical models and experimental observations", IEEE Trans. Geosci.
// Remote Sens. GE-23(1), 25-34, Table V, as reproduced in open-source
// implementations (a Python moisture_to_eps_hallikainen with all nine rows;
// the 1.4, 4 and 6 GHz rows agree with M. Natali's lib_SOIL.py and wcm_swb;
// one other public transcription, a MATLAB penetration-depth script, has
// c2 = -0.633 for eps' at 1.4 GHz: ris follows the three that agree on +0.633).
// Between the tabulated frequencies ris interpolates eps' and eps''
// linearly in frequency (the paper gives no rule; snapping to the nearest
// frequency, as some implementations do, makes sigma0 jump between bands).
// Validity: 1.4-18 GHz; sand 5-51.5 %, clay 13.4-47.4 % (the five soils
// measured); mv up to about 0.5.
#include <algorithm>
#include <array>
#include <cmath>

#include "ris/backscatter/dielectric.h"

namespace ris {

namespace {

struct Row {
  double f_ghz;
  std::array<double, 9> re;  // a0 a1 a2 b0 b1 b2 c0 c1 c2 for eps'
  std::array<double, 9> im;  // the same for eps''
};

// Hallikainen et al. (1985), Table V.
constexpr std::array<Row, 9> kTable = {{
    {1.4,
     {2.862, -0.012, 0.001, 3.803, 0.462, -0.341, 119.006, -0.500, 0.633},
     {0.356, -0.003, -0.008, 5.507, 0.044, -0.002, 17.753, -0.313, 0.206}},
    {4.0,
     {2.927, -0.012, -0.001, 5.505, 0.371, 0.062, 114.826, -0.389, -0.547},
     {0.004, 0.001, 0.002, 0.951, 0.005, -0.010, 16.759, 0.192, 0.290}},
    {6.0,
     {1.993, 0.002, 0.015, 38.086, -0.176, -0.633, 10.720, 1.256, 1.522},
     {-0.123, 0.002, 0.003, 7.502, -0.058, -0.116, 2.942, 0.452, 0.543}},
    {8.0,
     {1.997, 0.002, 0.018, 25.579, -0.017, -0.412, 39.793, 0.723, 0.941},
     {-0.201, 0.003, 0.003, 11.266, -0.085, -0.155, 0.194, 0.584, 0.581}},
    {10.0,
     {2.502, -0.003, -0.003, 10.101, 0.221, -0.004, 77.482, -0.061, -0.135},
     {-0.070, 0.000, 0.001, 6.620, 0.015, -0.081, 21.578, 0.293, 0.332}},
    {12.0,
     {2.200, -0.001, 0.012, 26.473, 0.013, -0.523, 34.333, 0.284, 1.062},
     {-0.142, 0.001, 0.003, 11.868, -0.059, -0.225, 7.817, 0.570, 0.801}},
    {14.0,
     {2.301, 0.001, 0.009, 17.918, 0.084, -0.282, 50.149, 0.012, 0.387},
     {-0.096, 0.001, 0.002, 8.583, -0.005, -0.153, 28.707, 0.297, 0.357}},
    {16.0,
     {2.237, 0.002, 0.009, 15.505, 0.076, -0.217, 48.260, 0.168, 0.289},
     {-0.027, -0.001, 0.003, 6.179, 0.074, -0.086, 34.126, 0.143, 0.206}},
    {18.0,
     {1.912, 0.007, 0.021, 29.123, -0.190, -0.545, 6.960, 0.822, 1.195},
     {-0.071, 0.000, 0.003, 6.938, 0.029, -0.128, 29.945, 0.275, 0.377}},
}};

double poly(const std::array<double, 9>& k, double s, double c, double mv) {
  return (k[0] + k[1] * s + k[2] * c) + (k[3] + k[4] * s + k[5] * c) * mv +
         (k[6] + k[7] * s + k[8] * c) * mv * mv;
}

}  // namespace

std::complex<double> hallikainen1985_permittivity(const SoilComposition& soil,
                                                  double frequency_hz) {
  const double s = soil.sand_fraction * 100.0;
  const double c = soil.clay_fraction * 100.0;
  const double mv = soil.moisture_m3_m3;
  const double f = std::clamp(frequency_hz / 1e9, kTable.front().f_ghz, kTable.back().f_ghz);
  size_t i = 0;
  while (i + 2 < kTable.size() && f > kTable[i + 1].f_ghz) ++i;
  const Row& lo = kTable[i];
  const Row& hi = kTable[i + 1];
  const double w = (f - lo.f_ghz) / (hi.f_ghz - lo.f_ghz);
  const double re = (1.0 - w) * poly(lo.re, s, c, mv) + w * poly(hi.re, s, c, mv);
  const double im = (1.0 - w) * poly(lo.im, s, c, mv) + w * poly(hi.im, s, c, mv);
  return {re, -im};
}

}  // namespace ris
