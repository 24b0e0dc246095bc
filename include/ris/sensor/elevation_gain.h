// The elevation antenna pattern as a small value type: one-way power gain
// G_e(beta) relative to boresight at look angle beta from nadir (MODEL.md
// section 3; the radar equation uses G_e^2 and the radar's peak gain).
//
// Evaluated per sample without a virtual call: the shape is an enum switched
// on inline (DESIGN.md principle 5); a table is searched by bisection.
//
//   uniform   G_e = 1
//   sinc2     G_e = sinc^2(x), sinc(x) = sin(pi x)/(pi x),
//             x = 2 * 0.442946 (beta - boresight) / beamwidth, so that
//             G_e = 1/2 at boresight +- beamwidth/2 (one-way 3 dB beamwidth;
//             sinc^2(0.442946) = 0.5)
//   gaussian  G_e = exp(-4 ln2 ((beta - boresight) / beamwidth)^2), also
//             1/2 at boresight +- beamwidth/2
//   table     linear interpolation in linear gain between listed angles;
//             outside the table the end value is held
//
// Example:
//   ris::ElevationGain g(radar.elevation_pattern);
//   double ge = g(look_rad);                     // one-way, relative, <= 1
//   double two_way = radar.peak_gain * radar.peak_gain * ge * ge;
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "ris/sensor/radar_params.h"
#include "ris/util/units.h"

namespace ris {

class ElevationGain {
 public:
  // x at which sinc^2(x) = 1/2 (solved numerically; checked in the tests).
  static constexpr double kSinc2HalfPower = 0.44294647;

  ElevationGain() = default;
  explicit ElevationGain(const ElevationPattern& p)
      : kind_(p.kind),
        boresight_rad_(p.boresight_rad),
        inv_beamwidth_(p.beamwidth_rad > 0.0 ? 1.0 / p.beamwidth_rad : 0.0),
        look_rad_(p.table_look_rad),
        gain_(p.table_gain) {}

  // One-way relative power gain at look angle look_rad (radians from nadir).
  double operator()(double look_rad) const {
    switch (kind_) {
      case ElevationPattern::Kind::uniform:
        return 1.0;
      case ElevationPattern::Kind::sinc2: {
        const double x = 2.0 * kSinc2HalfPower * (look_rad - boresight_rad_) * inv_beamwidth_;
        if (std::abs(x) < 1e-8) return 1.0;
        const double s = std::sin(kPi * x) / (kPi * x);
        return s * s;
      }
      case ElevationPattern::Kind::gaussian: {
        const double d = (look_rad - boresight_rad_) * inv_beamwidth_;
        return std::exp(-4.0 * kLn2 * d * d);
      }
      case ElevationPattern::Kind::table:
        return table(look_rad);
    }
    return 1.0;
  }

 private:
  static constexpr double kLn2 = 0.69314718055994530942;

  double table(double look_rad) const {
    if (look_rad <= look_rad_.front()) return gain_.front();
    if (look_rad >= look_rad_.back()) return gain_.back();
    const auto it = std::upper_bound(look_rad_.begin(), look_rad_.end(), look_rad);
    const auto i = static_cast<std::size_t>(it - look_rad_.begin());
    const double f = (look_rad - look_rad_[i - 1]) / (look_rad_[i] - look_rad_[i - 1]);
    return gain_[i - 1] + f * (gain_[i] - gain_[i - 1]);
  }

  ElevationPattern::Kind kind_ = ElevationPattern::Kind::uniform;
  double boresight_rad_ = 0.0;
  double inv_beamwidth_ = 0.0;
  std::vector<double> look_rad_;
  std::vector<double> gain_;
};

}  // namespace ris
