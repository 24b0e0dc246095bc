// A Sentinel-1 SAFE product's annotation XML (ESA, "Sentinel-1 Product
// Specification", S1-RS-MDA-52-7441, section 6.2 and appendix: the
// l1ProductType schema): finding the annotation in a .SAFE folder and reading
// its geolocation grid, ESA's own tie points for checking geometry.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "ris/util/utc_time.h"

namespace ris {

// The annotation XML of a SAFE folder whose file name contains `swath`
// (e.g. "iw1-slc-vv"; empty: the only one). A path to an XML file is returned
// as it is. Throws InputError listing the candidates when the choice is
// ambiguous or none matches.
std::filesystem::path sentinel1_annotation_path(const std::filesystem::path& path,
                                                const std::string& swath);

// One point of the annotation's geolocationGrid.
struct Sentinel1TiePoint {
  UtcTime azimuth_time;           // zero-Doppler time
  double slant_range_time_s = 0;  // two-way
  int line = 0, pixel = 0;
  double lat_deg = 0, lon_deg = 0, height_m = 0;
  double incidence_deg = 0;  // from the geocentric radius (see docs/geometry.md)
  double elevation_deg = 0;  // the look angle at the sensor
};

std::vector<Sentinel1TiePoint> read_sentinel1_tie_points(const std::filesystem::path& path,
                                                         const std::string& swath = "");

}  // namespace ris
