#include "ris/image/image_registration.h"

#include <fmt/format.h>
#include <kissfft/kiss_fftnd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

using cpx = std::complex<double>;

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
std::vector<kiss_fft_cpx> padded(std::span<const float> img, int cols, int rows, int px, int py) {
  double sum = 0.0;
  std::int64_t n = 0;
  for (float v : img)
    if (std::isfinite(v)) sum += v, ++n;
  if (n == 0) throw InputError("image", "registration", "an image has no pixel with data");
  const double mean = sum / double(n);
  const int taper = std::max(1, std::min({8, cols / 8, rows / 8}));
  const auto ramp = [&](int i, int size) {
    const int d = std::min(i, size - 1 - i);
    return d >= taper ? 1.0 : 0.5 - 0.5 * std::cos(kPi * (d + 0.5) / taper);
  };
  std::vector<kiss_fft_cpx> out(static_cast<std::size_t>(px) * static_cast<std::size_t>(py),
                                kiss_fft_cpx{0.0f, 0.0f});
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const float v = img[static_cast<std::size_t>(r) * cols + c];
      const double x = std::isfinite(v) ? (v - mean) * ramp(c, cols) * ramp(r, rows) : 0.0;
      out[static_cast<std::size_t>(r) * px + c].r = static_cast<float>(x);
    }
  }
  return out;
}

// Signed frequency of index k in an n-point DFT.
int signed_freq(int k, int n) {
  return k <= n / 2 ? k : k - n;
}

}  // namespace

ImageRegistration register_images(std::span<const float> a_db, std::span<const float> b_db,
                                  int cols, int rows, const RegistrationRule& rule) {
  const int px = fft_size(2 * cols), py = fft_size(2 * rows);
  std::vector<kiss_fft_cpx> a = padded(a_db, cols, rows, px, py);
  std::vector<kiss_fft_cpx> b = padded(b_db, cols, rows, px, py);
  const int dims[2] = {py, px};
  kiss_fftnd_cfg fwd = kiss_fftnd_alloc(dims, 2, 0, nullptr, nullptr);
  kiss_fftnd_cfg inv = kiss_fftnd_alloc(dims, 2, 1, nullptr, nullptr);
  std::vector<kiss_fft_cpx> fa(a.size()), fb(b.size()), cc(a.size());
  kiss_fftnd(fwd, a.data(), fa.data());
  kiss_fftnd(fwd, b.data(), fb.data());
  // R = B conj(A): its inverse transform peaks at the shift s of b against a.
  std::vector<cpx> R(a.size());
  for (std::size_t i = 0; i < R.size(); ++i)
    R[i] = cpx(fb[i].r, fb[i].i) * std::conj(cpx(fa[i].r, fa[i].i));
  if (rule.whitening > 0.0) {
    for (cpx& r : R) {
      const double m = std::abs(r);
      r = m > 0.0 ? r / std::pow(m, rule.whitening) : 0.0;
    }
  }
  for (std::size_t i = 0; i < R.size(); ++i)
    fa[i] = {static_cast<float>(R[i].real()), static_cast<float>(R[i].imag())};
  kiss_fftnd(inv, fa.data(), cc.data());
  kiss_fft_free(fwd);
  kiss_fft_free(inv);

  // The integer peak within the search window, and the window's statistics.
  const int m = rule.max_shift_px;
  double best = -1e300, sum = 0.0, sum2 = 0.0;
  int bx = 0, by = 0, count = 0;
  for (int dy = -m; dy <= m; ++dy) {
    for (int dx = -m; dx <= m; ++dx) {
      const std::size_t i = static_cast<std::size_t>((dy + py) % py) * px + (dx + px) % px;
      const double v = cc[i].r;
      sum += v, sum2 += v * v, ++count;
      if (v > best) best = v, bx = dx, by = dy;
    }
  }
  const double mean = sum / count;
  const double sd = std::sqrt(std::max(0.0, sum2 / count - mean * mean));
  ImageRegistration out;
  out.peak_z = sd > 0.0 ? (best - mean) / sd : 0.0;
  double ea = 0.0, eb = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) ea += a[i].r * a[i].r, eb += b[i].r * b[i].r;
  out.peak_correlation = best / (double(px) * py) / std::sqrt(ea * eb);
  if (!(out.peak_z >= rule.min_z) || std::abs(bx) == m || std::abs(by) == m) {
    throw InputError(
        "image", "registration",
        fmt::format("no correlation peak stands out within +-{} pixels (peak {:.1f} "
                    "standard deviations above the mean, {:.1f} needed{}): the images "
                    "do not show the same scene, or are shifted further",
                    m, out.peak_z, rule.min_z,
                    std::abs(bx) == m || std::abs(by) == m ? ", peak on the edge" : ""));
  }

  // Upsampled correlation over +-1 pixel around the peak (separable DFT).
  const int u = rule.upsample, n_up = 2 * u + 1;
  std::vector<cpx> ex(static_cast<std::size_t>(px) * n_up),
      rowsum(static_cast<std::size_t>(py) * n_up);
  for (int j = 0; j < n_up; ++j) {
    const double x = bx + double(j - u) / u;
    for (int k = 0; k < px; ++k)
      ex[static_cast<std::size_t>(j) * px + k] =
          std::polar(1.0, 2.0 * kPi * signed_freq(k, px) * x / px);
  }
  for (int ky = 0; ky < py; ++ky) {
    const cpx* r = &R[static_cast<std::size_t>(ky) * px];
    for (int j = 0; j < n_up; ++j) {
      const cpx* e = &ex[static_cast<std::size_t>(j) * px];
      cpx s = 0.0;
      for (int k = 0; k < px; ++k) s += r[k] * e[k];
      rowsum[static_cast<std::size_t>(ky) * n_up + j] = s;
    }
  }
  std::vector<cpx> ey(static_cast<std::size_t>(n_up) * py);
  for (int i = 0; i < n_up; ++i) {
    const double y = by + double(i - u) / u;
    for (int ky = 0; ky < py; ++ky)
      ey[static_cast<std::size_t>(i) * py + ky] =
          std::polar(1.0, 2.0 * kPi * signed_freq(ky, py) * y / py);
  }
  double up_best = -1e300;
  for (int i = 0; i < n_up; ++i) {
    const double y = by + double(i - u) / u;
    const cpx* e = &ey[static_cast<std::size_t>(i) * py];
    for (int j = 0; j < n_up; ++j) {
      cpx s = 0.0;
      for (int ky = 0; ky < py; ++ky) s += rowsum[static_cast<std::size_t>(ky) * n_up + j] * e[ky];
      if (s.real() > up_best) {
        up_best = s.real();
        out.shift_x_px = bx + double(j - u) / u;
        out.shift_y_px = y;
      }
    }
  }
  return out;
}

}  // namespace ris
