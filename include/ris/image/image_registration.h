// Co-registration of two images of the same size by cross-correlation
// (docs/quality.md, "ris compare"): the integer shift from the peak of the
// FFT cross-correlation of their zero-mean dB images, then the sub-pixel
// shift from the correlation upsampled around that peak by a matrix-multiply
// DFT (Guizar-Sicairos, Thurman & Fienup, "Efficient subpixel image
// registration algorithms", Optics Letters 33(2), 2008), to 1/upsample of a
// pixel.
//
// The cross-power spectrum is whitened (phase correlation, Kuglin & Hines
// 1975): every frequency weighs the same, so the peak is sharp for smooth
// images (mean power) and speckled ones alike, and its height above the
// surface's spread tells a real match from noise.
//
// The shift s says where the second image's content lies relative to the
// first: b(x) = a(x - s), so b(x + s) is aligned with a(x). Confidence: the
// peak's height above the mean of the correlation over the search window, in
// standard deviations of it (z); with no peak standing out (z below the
// rule's min_z) registration is refused.
#pragma once

#include <span>

namespace ris {

struct RegistrationRule {
  int max_shift_px = 16;   // searched in each axis, +-
  int upsample = 50;       // sub-pixel resolution 1/upsample
  double min_z = 8.0;      // refuse below (pure noise gives ~3.5)
  double whitening = 1.0;  // R / |R|^whitening: 1 phase correlation, 0 plain
};

struct ImageRegistration {
  double shift_x_px = 0.0, shift_y_px = 0.0;  // columns, rows
  double peak_z = 0.0;                        // the confidence above
  double peak_correlation = 0.0;              // normalised, at the integer peak
};

// a, b: rows x cols dB images (NaN: no data). Throws InputError (key
// "registration") when no peak stands out, or an image has no data.
ImageRegistration register_images(std::span<const float> a_db, std::span<const float> b_db,
                                  int cols, int rows, const RegistrationRule& rule);

}  // namespace ris
