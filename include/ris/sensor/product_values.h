// The physical ranges of the values a radar product's metadata gives (NISAR
// RSLC HDF5, Sentinel-1 annotation XML), checked where they are read: a
// damaged or hostile product (a NaN slant range, a zero position, a
// rangeSamplingRate of 0, a negative azimuthTimeInterval, linesPerBurst 0)
// is refused naming the file and the dataset or XML element, never carried
// into the geometry as NaN, infinity or a wrapped integer.
//
// The ranges are wide on purpose: every airborne and spaceborne SAR falls
// well inside them (docs/limits.md, "Product values"); outside them the
// value is not a radar's.
//
// Example:
//   const double dt_s = require_in_range(v, kLineIntervalRange, file, "azimuthTimeInterval");
//   const int lines = require_whole_number(v, 1, kMaxGridLines, file, "numberOfLines");
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ris/sensor/orbit.h"

namespace ris {

// A closed interval [lo, hi] in the value's own unit; `what` names the
// quantity in messages ("a slant range", "a frequency").
struct ValueRange {
  double lo;
  double hi;
  const char* unit;
  const char* what;
};

// Slant range of a sample, one way: above 1 m, below 10^8 m (beyond the
// farthest geostationary slant range, ~4.2e7 m).
inline constexpr ValueRange kSlantRangeRange{1.0, 1e8, "m", "a slant range"};
// Slant-range spacing of the bins: 1 mm to 1 km.
inline constexpr ValueRange kRangeSpacingRange{1e-3, 1e3, "m", "a range spacing"};
// Range sampling rate: c / (2 fs) within the spacing range above.
inline constexpr ValueRange kRangeSamplingRateRange{1.5e5, 1.5e11, "Hz", "a sampling rate"};
// Time between image lines: 1 us to 10 s.
inline constexpr ValueRange kLineIntervalRange{1e-6, 10.0, "s", "a line interval"};
// Carrier frequency: the radar bands of IEEE Std 521-2019, HF (3 MHz) to mm
// (300 GHz).
inline constexpr ValueRange kRadarFrequencyRange{3e6, 3e11, "Hz", "a radar frequency"};
// Pulse repetition frequency: 1 Hz to 1 MHz.
inline constexpr ValueRange kPrfRange{1.0, 1e6, "Hz", "a PRF"};
// A time against the product's epoch: within 10^7 s (116 days) either side;
// products reference their times to the acquisition's day.
inline constexpr ValueRange kProductTimeRange{-1e7, 1e7, "s", "a time since the epoch"};
// Distance of the platform from the Earth's centre: above 6,300 km (below
// the polar radius, 6,356.8 km, is underground), below 5 x 10^7 m (beyond
// the geostationary radius, 4.216e7 m).
inline constexpr ValueRange kOrbitRadiusRange{6.3e6, 5e7, "m",
                                              "a distance from the Earth's centre"};
// Platform speed (Earth-fixed): 1 m/s (a slow drone) to 12 km/s (above the
// escape speed at the surface, 11.2 km/s).
inline constexpr ValueRange kPlatformSpeedRange{1.0, 1.2e4, "m/s", "a platform speed"};
// An ellipsoid axis (Sentinel-1 annotations state theirs): 6,300 to 6,400 km
// (WGS 84: 6,378,137 and 6,356,752.3 m).
inline constexpr ValueRange kEllipsoidAxisRange{6.3e6, 6.4e6, "m", "an Earth ellipsoid axis"};

// A point on the ground (geolocation tie points, `ris geo2rdr --point`):
// latitude, longitude in degrees, and a height above the ellipsoid from
// below the deepest ocean floor (-10,935 m) to the edge of space (100 km).
inline constexpr ValueRange kLatitudeRange{-90.0, 90.0, "deg", "a latitude"};
inline constexpr ValueRange kLongitudeRange{-180.0, 360.0, "deg", "a longitude"};
inline constexpr ValueRange kGroundHeightRange{-12e3, 1e5, "m", "a height above the ellipsoid"};

// The most lines or bins a product's grid may have (the TOML reader's bound
// too): 10^7, past any real product (a debursted Sentinel-1 IW sub-swath has
// ~12,000 lines, 25,000 bins).
inline constexpr std::int64_t kMaxGridLines = 10'000'000;
// The most orbit state vectors a product may hold (NISAR: one a second over
// the acquisition's ~ minutes; Sentinel-1 annotations: ~20).
inline constexpr std::int64_t kMaxStateVectors = 1'000'000;

// `value` when finite and within r; else InputError(file, key) saying what
// was expected.
double require_in_range(double value, const ValueRange& r, const std::string& file,
                        const std::string& key);

// A count or index given as a number (an XML element): a whole number in
// [lo, hi], else InputError(file, key). Never casts an out-of-range double
// to an integer (undefined behaviour).
int require_whole_number(double value, std::int64_t lo, std::int64_t hi, const std::string& file,
                         const std::string& key);

// Every element of v finite, within r and strictly increasing; InputError
// naming key and the first bad element's index otherwise.
void require_increasing_in_range(const std::vector<double>& v, const ValueRange& r,
                                 const std::string& file, const std::string& key);

// The dataset or element names of a product's state vectors, for messages.
struct StateVectorKeys {
  std::string time, position, velocity;
};

// Each state vector's time within kProductTimeRange, its position and
// velocity finite and of physical size (kOrbitRadiusRange,
// kPlatformSpeedRange); InputError naming the key and the vector's index
// otherwise. (Increasing times are the Orbit constructor's check.)
void require_physical_state_vectors(const std::vector<StateVector>& sv, const std::string& file,
                                    const StateVectorKeys& keys);

}  // namespace ris
