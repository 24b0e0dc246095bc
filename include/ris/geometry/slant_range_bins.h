// The slant-range sampling of a simulated image: bin k holds
// near_m + k bin_m <= R < near_m + (k + 1) bin_m. Owned by geometry (the
// scene-grid maps say which bin each cell falls in); the image
// (ris/image/slar_image.h) is laid out on it.
#pragma once

namespace ris {

struct SlantRangeBins {
  double near_m = 0.0;
  double bin_m = 0.0;
  int count = 0;
  double centre_m(int k) const { return near_m + (k + 0.5) * bin_m; }
  double far_m() const { return near_m + count * bin_m; }
};

}  // namespace ris
