// The optics' and detector's blur as a Gaussian modulation transfer function
// (issue 35 items 2-3; docs/sensors.md "MTF"):
//   MTF(f) = exp(-2 pi^2 sigma^2 f^2)     (f in cycles per pixel)
// the Fourier transform of a Gaussian point spread function of standard
// deviation sigma pixels (Schowengerdt, Remote Sensing: Models and Methods
// for Image Processing, 3rd ed., 2007, section 3.4). A sensor is specified,
// as Sentinel-2's and Landsat's are, by its MTF at the Nyquist frequency
// (0.5 cycles/pixel): MTF_N = exp(-pi^2 sigma^2 / 2), so
//   sigma = sqrt(-2 ln MTF_N) / pi.
// A sampled Gaussian kernel would not have this response on the pixel grid
// (at sigma ~ 0.5 px its response at Nyquist is about twice MTF_N: the
// Gaussian's transform aliases), so the kernel is the inverse discrete-time
// Fourier transform of the MTF over [-1/2, 1/2] cycles/pixel: the image's
// frequencies are multiplied by exactly MTF(f) (to the kernel's truncation).
#pragma once

#include <vector>

namespace ris {

// sigma [pixels] of the Gaussian whose MTF at Nyquist is mtf_at_nyquist in
// (0, 1]; 0 for 1 (no blur).
double gaussian_sigma_px(double mtf_at_nyquist);

// The separable kernel g[-half .. half] (2 half + 1 taps, summing to 1):
// g[k] = 2 int_0^1/2 MTF(f) cos(2 pi f k) df; half = max(32, ceil(4 sigma)).
std::vector<float> mtf_kernel(double sigma_px);

// Convolves a rows x cols image in place with the kernel along rows and
// columns (OpenCV's sepFilter2D, reflected borders). NaN pixels (no data,
// sky) do not contribute (normalised convolution: blur(v m) / blur(m) with m
// the mask of finite pixels) and stay NaN.
void blur_gaussian_masked(std::vector<float>& image, int rows, int cols, double sigma_px);

}  // namespace ris
