// A DEM for radar geometry on the ellipsoidal Earth: a geographic (latitude,
// longitude) grid of heights above the WGS 84 ellipsoid, in memory.
//
// The DEM's horizontal CRS must be geographic on WGS 84 (EPSG:4326, as SRTM,
// Copernicus and the test DEMs are); other CRSs are refused with a message
// saying to gdalwarp them. Heights: when the file declares a vertical CRS
// that is not the ellipsoid (EGM96, EGM2008 geoid heights), PROJ converts
// them to ellipsoidal heights (EPSG:4979) with its geoid grids where
// installed (Debian's proj-data ships egm96_15.gtx); when PROJ cannot, the
// heights are used as they are and `vertical_note` says so. A DEM with no
// vertical CRS is taken as ellipsoidal (ISCE3 and sarsen do the same) and
// the note says that too.
//
// Example:
//   ris::EllipsoidalDem dem = ris::read_ellipsoidal_dem("Rome-30m-DEM.tif");
//   double h = dem.height_at(ris::deg_to_rad(41.9), ris::deg_to_rad(12.5));
#pragma once

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace ris {

struct EllipsoidalDem {
  // Cell centres: latitude lat0 + row * dlat, longitude lon0 + col * dlon
  // (radians; dlat is negative for north-up files).
  double lat0_rad = 0.0, lon0_rad = 0.0;
  double dlat_rad = 0.0, dlon_rad = 0.0;
  int cols = 0, rows = 0;
  std::vector<float> height_m;  // rows * cols, ellipsoidal; NaN = no data
  std::string source;
  std::string vertical_note;         // what was done about the vertical datum
  double geoid_offset_mean_m = 0.0;  // mean added to reach the ellipsoid

  float at(int row, int col) const { return height_m[static_cast<std::size_t>(row) * cols + col]; }

  // Bilinear height at a latitude/longitude (radians); NaN outside the grid
  // or next to no-data. Inline: called per sample by rdr2geo.
  double height_at(double lat_rad, double lon_rad) const {
    const double r = (lat_rad - lat0_rad) / dlat_rad;
    const double c = (lon_rad - lon0_rad) / dlon_rad;
    if (!(r >= 0.0 && c >= 0.0 && r <= rows - 1 && c <= cols - 1)) return std::nan("");
    int r0 = static_cast<int>(r), c0 = static_cast<int>(c);
    r0 = r0 >= rows - 1 ? rows - 2 : r0;
    c0 = c0 >= cols - 1 ? cols - 2 : c0;
    const double fr = r - r0, fc = c - c0;
    const double h00 = at(r0, c0), h01 = at(r0, c0 + 1), h10 = at(r0 + 1, c0),
                 h11 = at(r0 + 1, c0 + 1);
    return (h00 * (1.0 - fc) + h01 * fc) * (1.0 - fr) + (h10 * (1.0 - fc) + h11 * fc) * fr;
  }
  double mean_height_m() const;
};

// Throws InputError naming the file when it cannot be read, is not
// geographic WGS 84, or is smaller than 2 x 2.
EllipsoidalDem read_ellipsoidal_dem(const std::filesystem::path& path);

// A flat DEM (constant ellipsoidal height) over a latitude/longitude box,
// for tests and for "no DEM" runs.
EllipsoidalDem flat_ellipsoidal_dem(double lat_min_rad, double lat_max_rad, double lon_min_rad,
                                    double lon_max_rad, int rows, int cols, double height_m);

}  // namespace ris
