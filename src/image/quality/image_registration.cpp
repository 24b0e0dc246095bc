#include "ris/image/image_registration.h"

#include <fmt/format.h>
#include <kissfft/kiss_fftnd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <limits>
#include <vector>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

using cpx = std::complex<double>;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One level of the pyramid: intensity (NaN: no data) and its dB.
struct Level {
  int cols = 0, rows = 0;
  std::vector<double> lin, db;
};

std::size_t at(int c, int r, int cols) {
  return static_cast<std::size_t>(r) * static_cast<std::size_t>(cols) + static_cast<std::size_t>(c);
}

void fill_db(Level& l) {
  l.db.resize(l.lin.size());
  for (std::size_t i = 0; i < l.lin.size(); ++i)
    l.db[i] = l.lin[i] > 0.0 ? 10.0 * std::log10(l.lin[i]) : kNaN;
}

// The dB image as intensity, box-averaged over looks x looks pixels on the
// same grid (the mean of the pixels with data; no data where fewer than half
// of the box's pixels hold data). Summed-area tables: O(pixels).
Level multilook(std::span<const float> img_db, int cols, int rows, int looks) {
  std::vector<double> s(at(0, rows + 1, cols + 1), 0.0), n(s.size(), 0.0);
  std::int64_t valid = 0;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const float v = img_db[at(c, r, cols)];
      const bool ok = std::isfinite(v);
      valid += ok;
      s[at(c + 1, r + 1, cols + 1)] = (ok ? std::pow(10.0, v / 10.0) : 0.0) +
                                      s[at(c, r + 1, cols + 1)] + s[at(c + 1, r, cols + 1)] -
                                      s[at(c, r, cols + 1)];
      n[at(c + 1, r + 1, cols + 1)] = (ok ? 1.0 : 0.0) + n[at(c, r + 1, cols + 1)] +
                                      n[at(c + 1, r, cols + 1)] - n[at(c, r, cols + 1)];
    }
  }
  if (valid == 0) throw InputError("image", "registration", "an image has no pixel with data");
  Level out{cols, rows, std::vector<double>(at(0, rows, cols), kNaN), {}};
  const int lo = (looks - 1) / 2, hi = looks / 2;
  for (int r = 0; r < rows; ++r) {
    const int r0 = std::max(0, r - lo), r1 = std::min(rows, r + hi + 1);
    for (int c = 0; c < cols; ++c) {
      const int c0 = std::max(0, c - lo), c1 = std::min(cols, c + hi + 1);
      const auto box = [&](const std::vector<double>& t) {
        return t[at(c1, r1, cols + 1)] - t[at(c0, r1, cols + 1)] - t[at(c1, r0, cols + 1)] +
               t[at(c0, r0, cols + 1)];
      };
      const double count = box(n);
      if (count >= 0.5 * (c1 - c0) * (r1 - r0)) out.lin[at(c, r, cols)] = box(s) / count;
    }
  }
  fill_db(out);
  return out;
}

// The next coarser level: means of 2 x 2 blocks (no data where fewer than
// two of the four hold data). Level k's pixel i covers the full
// resolution's pixels [2^k i, 2^k (i + 1)), so a shift there is 2^k times
// the shift here.
Level halve(const Level& f) {
  Level out{f.cols / 2, f.rows / 2, {}, {}};
  out.lin.assign(at(0, out.rows, out.cols), kNaN);
  for (int r = 0; r < out.rows; ++r) {
    for (int c = 0; c < out.cols; ++c) {
      double s = 0.0;
      int k = 0;
      for (int dr = 0; dr < 2; ++dr)
        for (int dc = 0; dc < 2; ++dc) {
          const double v = f.lin[at(2 * c + dc, 2 * r + dr, f.cols)];
          if (std::isfinite(v)) s += v, ++k;
        }
      if (k >= 2) out.lin[at(c, r, out.cols)] = s / k;
    }
  }
  fill_db(out);
  return out;
}

// Pearson r of a(x) and b(x + d) over the pixels both hold (NaN when fewer
// than a quarter of the pixels overlap); `pairs`, when given, their number.
double ncc(const Level& a, const Level& b, int dx, int dy, double* pairs = nullptr) {
  double n = 0.0, sa = 0.0, sb = 0.0, saa = 0.0, sbb = 0.0, sab = 0.0;
  const int r0 = std::max(0, -dy), r1 = std::min(a.rows, a.rows - dy);
  const int c0 = std::max(0, -dx), c1 = std::min(a.cols, a.cols - dx);
  for (int r = r0; r < r1; ++r) {
    const double* pa = &a.db[at(0, r, a.cols)];
    const double* pb = &b.db[at(0, r + dy, a.cols)];
    for (int c = c0; c < c1; ++c) {
      const double x = pa[c], y = pb[c + dx];
      if (!std::isfinite(x) || !std::isfinite(y)) continue;
      n += 1.0, sa += x, sb += y, saa += x * x, sbb += y * y, sab += x * y;
    }
  }
  if (pairs != nullptr) *pairs = n;
  if (n < std::max(16.0, 0.25 * a.cols * a.rows)) return kNaN;
  const double vab = sab - sa * sb / n, vaa = saa - sa * sa / n, vbb = sbb - sb * sb / n;
  return vaa > 0.0 && vbb > 0.0 ? vab / std::sqrt(vaa * vbb) : kNaN;
}

// The correlation surface over shifts (cx, cy) +- radius, row-major.
struct Surface {
  int cx = 0, cy = 0, radius = 0;
  std::vector<double> r;
  double value(int dx, int dy) const {
    return r[at(dx - cx + radius, dy - cy + radius, 2 * radius + 1)];
  }
};

Surface surface(const Level& a, const Level& b, int cx, int cy, int radius) {
  Surface s{cx, cy, radius, {}};
  for (int dy = cy - radius; dy <= cy + radius; ++dy)
    for (int dx = cx - radius; dx <= cx + radius; ++dx) s.r.push_back(ncc(a, b, dx, dy));
  return s;
}

// The surface's largest value, its shift, and whether a shift beside it is
// outside the surface (the peak on the surface's edge).
struct Peak {
  int dx = 0, dy = 0;
  double r = kNaN;
};

Peak peak_of(const Surface& s) {
  Peak p;
  double best = -2.0;
  for (int dy = s.cy - s.radius; dy <= s.cy + s.radius; ++dy)
    for (int dx = s.cx - s.radius; dx <= s.cx + s.radius; ++dx) {
      const double v = s.value(dx, dy);
      if (std::isfinite(v) && v > best) best = v, p = {dx, dy, v};
    }
  return p;
}

// z of the peak against the surface away from it: the peak's lobe (the
// Chebyshev rings about the peak whose largest value exceeds half the peak,
// and one more) left out, z = (peak - mean) / sd of the rest.
double peak_significance(const Surface& s, const Peak& p) {
  const auto ring_max = [&](int d) {
    double m = -2.0;
    for (int dy = p.dy - d; dy <= p.dy + d; ++dy)
      for (int dx = p.dx - d; dx <= p.dx + d; ++dx) {
        if (std::max(std::abs(dx - p.dx), std::abs(dy - p.dy)) != d) continue;
        if (std::abs(dx - s.cx) > s.radius || std::abs(dy - s.cy) > s.radius) continue;
        const double v = s.value(dx, dy);
        if (std::isfinite(v)) m = std::max(m, v);
      }
    return m;
  };
  int lobe = 1;
  while (lobe < s.radius && ring_max(lobe) > 0.5 * p.r) ++lobe;
  double n = 0.0, sum = 0.0, sum2 = 0.0;
  for (int dy = s.cy - s.radius; dy <= s.cy + s.radius; ++dy)
    for (int dx = s.cx - s.radius; dx <= s.cx + s.radius; ++dx) {
      const double v = s.value(dx, dy);
      if (!std::isfinite(v) || std::max(std::abs(dx - p.dx), std::abs(dy - p.dy)) <= lobe) continue;
      n += 1.0, sum += v, sum2 += v * v;
    }
  if (n < 8.0) return 0.0;
  const double mean = sum / n, sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  return sd > 0.0 ? (p.r - mean) / sd : 0.0;
}

// The peak's significance against independent images with the same
// spatial autocorrelation (Clifford, Richardson & Hemon 1989, "Assessing
// the significance of the correlation between two spatial processes",
// Biometrics 45(1)): under independence r has the variance
// sum_k rho_a(k) rho_b(k) / n over the lags k (rho the images' own
// autocorrelations), so z = r sqrt(n_eff), n_eff = n / sum_k rho_a rho_b,
// is a standard normal at any one shift. The sum is taken over lags within
// the search radius (an image smoother than that is taken as more
// independent than it is: the radius is 8 pixels or more at the level).
double clifford_z(const Level& a, const Level& b, const Peak& p, int radius) {
  double pairs = 0.0;
  ncc(a, b, p.dx, p.dy, &pairs);
  double sum = 0.0;
  for (int dy = -radius; dy <= radius; ++dy)
    for (int dx = -radius; dx <= radius; ++dx) {
      const double ra = ncc(a, a, dx, dy), rb = ncc(b, b, dx, dy);
      if (std::isfinite(ra) && std::isfinite(rb)) sum += ra * rb;
    }
  return sum > 0.0 ? p.r * std::sqrt(pairs / sum) : 0.0;
}

// The smallest n' >= n whose only prime factors are 2, 3 and 5 (fast FFTs).
int fft_size(int n) {
  for (int m = std::max(n, 1);; ++m) {
    int k = m;
    for (int p : {2, 3, 5})
      while (k % p == 0) k /= p;
    if (k == 1) return m;
  }
}

// Zero-mean image, no-data as 0, tapered to 0 over `taper` pixels at the
// border (a cosine ramp: the image's edge is not a step that correlates at
// zero shift), placed in a px x py zero-padded complex array.
std::vector<kiss_fft_cpx> padded(const std::vector<double>& img, int cols, int rows, int px, int py,
                                 bool mask_only, bool no_taper) {
  double sum = 0.0;
  std::int64_t n = 0;
  for (double v : img)
    if (std::isfinite(v)) sum += v, ++n;
  const double mean = n > 0 ? sum / double(n) : 0.0;
  const int taper = std::max(1, std::min({8, cols / 8, rows / 8}));
  const auto ramp = [&](int i, int size) {
    const int d = std::min(i, size - 1 - i);
    if (no_taper) return 1.0;
    return d >= taper ? 1.0 : 0.5 - 0.5 * std::cos(kPi * (d + 0.5) / taper);
  };
  std::vector<kiss_fft_cpx> out(static_cast<std::size_t>(px) * static_cast<std::size_t>(py),
                                kiss_fft_cpx{0.0f, 0.0f});
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const double v = img[at(c, r, cols)];
      const double x =
          std::isfinite(v) ? (mask_only ? 1.0 : v - mean) * ramp(c, cols) * ramp(r, rows) : 0.0;
      out[at(c, r, px)].r = static_cast<float>(x);
    }
  }
  return out;
}

// Signed frequency of index k in an n-point DFT.
int signed_freq(int k, int n) {
  return k <= n / 2 ? k : k - n;
}

// The cross-power spectrum B conj(A) of the two dB images (its inverse
// transform peaks at the shift of b against a), whitened by |R|^whitening;
// with mask_only, of their tapered masks instead (the overlap's weight at
// each shift).
std::vector<cpx> cross_power(const Level& a, const Level& b, int px, int py, double whitening,
                             bool mask_only) {
  const bool no_taper = whitening == 0.0;
  std::vector<kiss_fft_cpx> ta = padded(a.db, a.cols, a.rows, px, py, mask_only, no_taper);
  std::vector<kiss_fft_cpx> tb = padded(b.db, b.cols, b.rows, px, py, mask_only, no_taper);
  const int dims[2] = {py, px};
  kiss_fftnd_cfg fwd = kiss_fftnd_alloc(dims, 2, 0, nullptr, nullptr);
  std::vector<kiss_fft_cpx> fa(ta.size()), fb(tb.size());
  kiss_fftnd(fwd, ta.data(), fa.data());
  kiss_fftnd(fwd, tb.data(), fb.data());
  kiss_fft_free(fwd);
  std::vector<cpx> R(fa.size());
  for (std::size_t i = 0; i < R.size(); ++i) {
    R[i] = cpx(fb[i].r, fb[i].i) * std::conj(cpx(fa[i].r, fa[i].i));
    const double m = std::abs(R[i]);
    if (whitening > 0.0) R[i] = m > 0.0 ? R[i] / std::pow(m, whitening) : 0.0;
  }
  return R;
}

// The inverse transform of R upsampled `u` times over +-1 pixel around
// (bx, by) by a separable matrix-multiply DFT: (2u + 1)^2 values, row-major
// from (bx - 1, by - 1).
std::vector<double> upsampled(const std::vector<cpx>& R, int px, int py, int bx, int by, int u) {
  const int n_up = 2 * u + 1;
  std::vector<cpx> ex(static_cast<std::size_t>(px) * n_up),
      rowsum(static_cast<std::size_t>(py) * n_up);
  for (int j = 0; j < n_up; ++j) {
    const double x = bx + double(j - u) / u;
    for (int k = 0; k < px; ++k)
      ex[at(k, j, px)] = std::polar(1.0, 2.0 * kPi * signed_freq(k, px) * x / px);
  }
  for (int ky = 0; ky < py; ++ky) {
    const cpx* r = &R[at(0, ky, px)];
    for (int j = 0; j < n_up; ++j) {
      const cpx* e = &ex[at(0, j, px)];
      cpx s = 0.0;
      for (int k = 0; k < px; ++k) s += r[k] * e[k];
      rowsum[at(j, ky, n_up)] = s;
    }
  }
  std::vector<cpx> ey(static_cast<std::size_t>(n_up) * py);
  for (int i = 0; i < n_up; ++i) {
    const double y = by + double(i - u) / u;
    for (int ky = 0; ky < py; ++ky)
      ey[at(ky, i, py)] = std::polar(1.0, 2.0 * kPi * signed_freq(ky, py) * y / py);
  }
  std::vector<double> out(static_cast<std::size_t>(n_up) * n_up);
  for (int i = 0; i < n_up; ++i) {
    const cpx* e = &ey[at(0, i, py)];
    for (int j = 0; j < n_up; ++j) {
      cpx s = 0.0;
      for (int ky = 0; ky < py; ++ky) s += rowsum[at(j, ky, n_up)] * e[ky];
      out[at(j, i, n_up)] = s.real();
    }
  }
  return out;
}

// The sub-pixel peak: the correlation upsampled over +-1 pixel around the
// integer peak (bx, by), divided by the overlap's weight at each shift (the
// tapered masks' correlation), so that the overlap shrinking with the shift
// does not pull a broad peak towards zero (a smooth correlation of 5-pixel
// width moved by 0.2-0.7 pixel without it).
void subpixel(const Level& a, const Level& b, int bx, int by, const RegistrationRule& rule,
              ImageRegistration& out) {
  const int px = fft_size(2 * a.cols), py = fft_size(2 * a.rows);
  const int u = rule.upsample, n_up = 2 * u + 1;
  const std::vector<double> c =
      upsampled(cross_power(a, b, px, py, rule.whitening, false), px, py, bx, by, u);
  const std::vector<double> w =
      rule.whitening > 0.0 ? std::vector<double>(c.size(), 1.0)
                           : upsampled(cross_power(a, b, px, py, 0.0, true), px, py, bx, by, u);
  double best = -1e300;
  for (int i = 0; i < n_up; ++i)
    for (int j = 0; j < n_up; ++j) {
      const double v = w[at(j, i, n_up)] > 0.0 ? c[at(j, i, n_up)] / w[at(j, i, n_up)] : -1e300;
      if (v > best) {
        best = v;
        out.shift_x_px = bx + double(j - u) / u;
        out.shift_y_px = by + double(i - u) / u;
      }
    }
}

// Pyramid levels above the full resolution: halve while the search radius
// stays at 8 pixels or more and the image at 32 pixels or more a side.
int automatic_levels(int cols, int rows, int max_shift) {
  int k = 0;
  while (k < 6 && (max_shift >> (k + 1)) >= 8 && std::min(cols, rows) >> (k + 1) >= 32) ++k;
  return k;
}

[[noreturn]] void refuse_edge(int m) {
  throw InputError(
      "", "max_shift",
      fmt::format("the correlation peak lies on the edge of the +-{} pixel search range: the "
                  "images are shifted further, or do not show the same scene; widen the search "
                  "with --max-shift (max_shift_px in Python)",
                  m));
}

}  // namespace

ImageRegistration register_images(std::span<const float> a_db, std::span<const float> b_db,
                                  int cols, int rows, const RegistrationRule& rule) {
  const int m = rule.max_shift_px;
  const int levels = rule.levels >= 0 ? rule.levels : automatic_levels(cols, rows, m);
  std::vector<Level> pa{multilook(a_db, cols, rows, std::max(1, rule.looks))};
  std::vector<Level> pb{multilook(b_db, cols, rows, std::max(1, rule.looks))};
  for (int k = 0; k < levels; ++k) {
    pa.push_back(halve(pa.back()));
    pb.push_back(halve(pb.back()));
  }
  ImageRegistration out;
  out.looks = std::max(1, rule.looks);
  out.levels = levels;

  // The whole range at the coarsest level, and the peak's significance there.
  const int coarse_radius = (m + (1 << levels) - 1) >> levels;
  const Surface coarse = surface(pa.back(), pb.back(), 0, 0, coarse_radius);
  Peak p = peak_of(coarse);
  if (!std::isfinite(p.r)) {
    throw InputError("image", "registration",
                     "the images overlap nowhere with data at any shift searched");
  }
  out.peak_to_sidelobe = peak_significance(coarse, p);
  out.peak_z = clifford_z(pa.back(), pb.back(), p, coarse_radius);
  if (!(out.peak_z >= rule.min_z)) {
    throw InputError(
        "image", "registration",
        fmt::format("no correlation peak stands out within +-{} pixels (peak r = {:.3f} at "
                    "{:.1f} standard errors of independent images, {:.1f} needed): the images "
                    "do not show the same scene, or are shifted further (widen the search with "
                    "--max-shift, max_shift_px in Python)",
                    m, p.r, out.peak_z, rule.min_z));
  }
  if (std::max(std::abs(p.dx), std::abs(p.dy)) == coarse_radius) refuse_edge(m);

  // Refined within +-2 pixels of the doubled peak at each finer level.
  for (int k = levels - 1; k >= 0; --k) {
    const int lim = (m + (1 << k) - 1) >> k;
    const Level &ak = pa[static_cast<std::size_t>(k)], &bk = pb[static_cast<std::size_t>(k)];
    int cx = std::clamp(2 * p.dx, -lim, lim), cy = std::clamp(2 * p.dy, -lim, lim);
    // A peak on the window's edge moves the window (a few times at most).
    for (int step = 0; step < 4; ++step) {
      p = peak_of(surface(ak, bk, cx, cy, 2));
      if (std::max(std::abs(p.dx - cx), std::abs(p.dy - cy)) < 2) break;
      cx = std::clamp(p.dx, -lim, lim), cy = std::clamp(p.dy, -lim, lim);
    }
  }
  if (std::max(std::abs(p.dx), std::abs(p.dy)) >= m) refuse_edge(m);
  out.peak_correlation = p.r;
  // The sub-pixel step on lighter multilooking: the peak's position is in
  // the finer detail that heavy averaging removes.
  const int sl = std::max(1, rule.subpixel_looks);
  if (sl == out.looks) {
    subpixel(pa.front(), pb.front(), p.dx, p.dy, rule, out);
  } else {
    subpixel(multilook(a_db, cols, rows, sl), multilook(b_db, cols, rows, sl), p.dx, p.dy, rule,
             out);
  }
  return out;
}

}  // namespace ris
