// Co-registration of two images of the same size (docs/quality.md,
// "ris compare", "Registration"), built for a simulated against a real SAR
// image: independent speckle in each, radiometry that agrees only in its
// large structures (Pearson r of dB around 0.5 at 9-pixel windows).
//
// 1. Multilook: each image's intensity is box-averaged over looks x looks
//    pixels (a sliding window on the same grid) before anything is
//    correlated, so speckle, which the two images do not share, is reduced
//    by about the number of looks (as ISCE3's ampcor and GAMMA's offset_pwr
//    correlate detected, averaged amplitude or intensity rather than SLC
//    phase).
// 2. Pyramid: halving the multilooked intensity (2 x 2 block means) until the
//    search radius is about 8 pixels; the correlation is the normalised
//    cross-correlation (Pearson r) of the dB images over the pixels both hold
//    at each integer shift (ampcor's normalisation per shift), computed over
//    the whole allowed range at the coarsest level and within +-2 pixels of
//    the doubled peak at each finer level (SNAP's coarse registration starts
//    from decimated images the same way).
// 3. Significance, at the coarsest level where the whole range is searched:
//    the peak r against its spread for independent images of the same
//    spatial autocorrelation, z = r sqrt(n / sum_k rho_a(k) rho_b(k))
//    (Clifford, Richardson & Hemon 1989: the effective number of
//    independent pixel pairs); refused below min_z, or when the peak lies
//    on the search range's edge (the shift may be larger). Reported too:
//    the peak-to-sidelobe ratio, (peak - mean) / sd of the surface beyond
//    the peak's lobe (Bolme et al., CVPR 2010; ampcor's SNR is the same idea
//    on r^2), which smooth independent images push up to 8 (docs).
// 4. Sub-pixel: the integer peak refined by the correlation of the
//    multilooked dB images upsampled around it by a matrix-multiply DFT
//    (Guizar-Sicairos, Thurman & Fienup, Optics Letters 33(2), 2008), to
//    1/upsample of a pixel.
//
// The shift s says where the second image's content lies relative to the
// first: b(x) = a(x - s), so b(x + s) is aligned with a(x).
#pragma once

#include <span>

namespace ris {

struct RegistrationRule {
  int max_shift_px = 16;   // searched in each axis, +-
  int upsample = 50;       // sub-pixel resolution 1/upsample
  double min_z = 5.0;      // refuse below (docs/quality.md: the false-alarm rate on noise)
  double whitening = 0.0;  // sub-pixel step: R / |R|^whitening (1 phase correlation, 0 plain)
  int looks = 5;           // multilook box side for the search, pixels (1: none)
  int subpixel_looks = 3;  // multilook box side for the sub-pixel step
  int levels = -1;         // pyramid levels above the full resolution; -1: automatic
};

struct ImageRegistration {
  double shift_x_px = 0.0, shift_y_px = 0.0;  // columns, rows
  double peak_z = 0.0;                        // the significance above (Clifford z)
  double peak_to_sidelobe = 0.0;              // (peak - mean) / sd of the surface off the peak
  double peak_correlation = 0.0;              // Pearson r of multilooked dB at the integer peak
  int looks = 1, levels = 0;                  // what was used
};

// a, b: rows x cols dB images (NaN: no data). Throws InputError: key
// "registration" when no peak stands out or an image has no data, key
// "max_shift" when the peak lies on the edge of the search range.
ImageRegistration register_images(std::span<const float> a_db, std::span<const float> b_db,
                                  int cols, int rows, const RegistrationRule& rule);

}  // namespace ris
