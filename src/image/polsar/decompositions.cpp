// Cloude-Pottier, Freeman-Durden and the Pauli picture
// (ris/image/polsar/decompositions.h).
#include "ris/image/polsar/decompositions.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ris {

namespace {

// PolSARpro's eps (1e-30): the floor of span_min and of "what is left".
constexpr double kEps = 1e-30;

Hermitian3 t3_of(const CovarianceImage& c, std::size_t i) {
  return c.is_t3 ? c.m[i] : t3_from_c3(c.m[i]);
}

Hermitian3 c3_of(const CovarianceImage& c, std::size_t i) {
  return c.is_t3 ? c3_from_t3(c.m[i]) : c.m[i];
}

}  // namespace

CloudePottier cloude_pottier(const Hermitian3& t3) {
  const HermitianEigen e = hermitian_eigen(t3);
  CloudePottier out;
  out.eigenvalues = e.values;
  std::array<double, 3> l{};
  double total = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    l[i] = std::max(e.values[i], 0.0);
    total += l[i];
  }
  if (!(total > 0.0)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.entropy = out.anisotropy = out.alpha_rad = nan;
    return out;
  }
  const double log3 = std::log(3.0);
  for (std::size_t i = 0; i < 3; ++i) {
    const double p = l[i] / total;
    if (p > 0.0) out.entropy -= p * std::log(p) / log3;
    out.alpha_rad += p * std::acos(std::min(1.0, std::abs(e.vectors[i][0])));
  }
  // A numerically rank-one pixel (l2 + l3 at rounding level) has no
  // anisotropy to speak of: 0, not the 1 that rounding noise would give.
  out.anisotropy = l[1] + l[2] > 1e-12 * total ? (l[1] - l[2]) / (l[1] + l[2]) : 0.0;
  return out;
}

FreemanDurden freeman_durden(const Hermitian3& c3) {
  double c11 = c3(0, 0).real(), c22 = c3(1, 1).real(), c33 = c3(2, 2).real();
  Complex c13 = c3(0, 2);
  // The dipole volume first.
  double fv = 1.5 * c22;
  c11 -= fv;
  c33 -= fv;
  c13 -= fv / 3.0;
  FreemanDurden out;
  if (c11 <= kEps || c33 <= kEps) {  // the volume takes everything
    fv = 3.0 * (c11 + c22 + c33 + 2.0 * fv) / 8.0;
    out.volume = 8.0 * fv / 3.0;
    return out;
  }
  // A non-realisable <HH VV*>: its magnitude limited to sqrt(C11 C33).
  const double n13 = std::norm(c13);
  if (n13 > c11 * c33) c13 *= std::sqrt(c11 * c33 / n13);
  const double det = c11 * c33 - std::norm(c13);
  double fs = 0.0, fd = 0.0, alpha2 = 0.0, beta2 = 0.0;
  if (c13.real() >= 0.0) {  // surface dominant: alpha = -1
    fd = det / (c11 + c33 + 2.0 * c13.real());
    fs = c33 - fd;
    beta2 = std::norm(c13 + fd) / (fs * fs);
    alpha2 = 1.0;
  } else {  // double bounce dominant: beta = 1
    fs = det / (c11 + c33 - 2.0 * c13.real());
    fd = c33 - fs;
    alpha2 = std::norm(fs - c13) / (fd * fd);
    beta2 = 1.0;
  }
  out.surface = fs * (1.0 + beta2);
  out.double_bounce = fd * (1.0 + alpha2);
  out.volume = 8.0 * fv / 3.0;
  return out;
}

std::vector<CloudePottier> cloude_pottier_image(const CovarianceImage& c) {
  std::vector<CloudePottier> out(c.m.size());
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < c.m.size(); ++i) out[i] = cloude_pottier(t3_of(c, i));
  return out;
}

std::vector<FreemanDurden> freeman_durden_image(const CovarianceImage& c) {
  double span_min = std::numeric_limits<double>::infinity();
  double span_max = -std::numeric_limits<double>::infinity();
  for (const Hermitian3& m : c.m) {
    const double span = m.trace();
    if (!std::isfinite(span)) continue;
    span_min = std::min(span_min, span);
    span_max = std::max(span_max, span);
  }
  span_min = std::max(span_min, kEps);
  std::vector<FreemanDurden> out(c.m.size());
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < c.m.size(); ++i) {
    FreemanDurden f = freeman_durden(c3_of(c, i));
    for (double* p : {&f.surface, &f.double_bounce, &f.volume}) {
      if (std::isfinite(*p)) *p = std::clamp(*p, span_min, span_max);
    }
    out[i] = f;
  }
  return out;
}

std::vector<std::uint8_t> pauli_rgb(const CovarianceImage& c) {
  const std::size_t n = c.m.size();
  std::vector<std::uint8_t> rgb(3 * n, 0);
  // T3's diagonal element per colour: red T22, green T33, blue T11.
  constexpr std::array<int, 3> kElement = {1, 2, 0};
  for (std::size_t ch = 0; ch < 3; ++ch) {
    std::vector<double> db(n, std::numeric_limits<double>::quiet_NaN());
    std::vector<double> finite;
    finite.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double p = t3_of(c, i)(kElement[ch], kElement[ch]).real();
      if (std::isfinite(p) && p > 0.0) {
        db[i] = 10.0 * std::log10(p);  // 20 log10 of the amplitude sqrt(p)
        finite.push_back(db[i]);
      }
    }
    if (finite.empty()) continue;
    std::sort(finite.begin(), finite.end());
    const auto pct = [&](double q) {
      return finite[static_cast<std::size_t>(q * static_cast<double>(finite.size() - 1))];
    };
    const double lo = pct(0.02), hi = pct(0.98);
    const double scale = hi > lo ? 255.0 / (hi - lo) : 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(db[i])) continue;
      const double v = hi > lo ? (db[i] - lo) * scale : 128.0;
      rgb[3 * i + ch] = static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0, 255.0)));
    }
  }
  return rgb;
}

}  // namespace ris
