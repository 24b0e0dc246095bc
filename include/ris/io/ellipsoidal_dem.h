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
#include <memory>
#include <string>
#include <vector>

namespace ris {

struct EllipsoidalDem {
  // Cell centres of the file's grid: latitude lat0 + row * dlat, longitude
  // lon0 + col * dlon (radians; dlat is negative for north-up files).
  double lat0_rad = 0.0, lon0_rad = 0.0;
  double dlat_rad = 0.0, dlon_rad = 0.0;
  // The postings held: rows [row0, row0 + rows) x columns [col0, col0 +
  // cols) of the file's grid, which is grid_rows x grid_cols (0: the held
  // postings are the whole grid). A window (EllipsoidalDemFile::read) keeps
  // the file's origin, so it interpolates exactly as the whole DEM does
  // wherever it holds the four postings around a point.
  int cols = 0, rows = 0;
  int row0 = 0, col0 = 0;
  int grid_rows = 0, grid_cols = 0;
  std::vector<float> height_m;  // rows * cols, ellipsoidal; NaN = no data
  std::string source;
  std::string vertical_note;         // what was done about the vertical datum
  double geoid_offset_mean_m = 0.0;  // mean added to reach the ellipsoid

  int all_rows() const { return grid_rows > 0 ? grid_rows : rows; }
  int all_cols() const { return grid_cols > 0 ? grid_cols : cols; }
  // A held posting, by its index among the held postings.
  float at(int row, int col) const { return height_m[static_cast<std::size_t>(row) * cols + col]; }

  // Bilinear height at a latitude/longitude (radians); NaN outside the grid
  // or next to no-data. Inline: called per sample by rdr2geo. A window must
  // hold the four postings around the point.
  double height_at(double lat_rad, double lon_rad) const {
    const double r = (lat_rad - lat0_rad) / dlat_rad;
    const double c = (lon_rad - lon0_rad) / dlon_rad;
    const int gr = all_rows(), gc = all_cols();
    if (!(r >= 0.0 && c >= 0.0 && r <= gr - 1 && c <= gc - 1)) return std::nan("");
    int r0 = static_cast<int>(r), c0 = static_cast<int>(c);
    r0 = r0 >= gr - 1 ? gr - 2 : r0;
    c0 = c0 >= gc - 1 ? gc - 2 : c0;
    const double fr = r - r0, fc = c - c0;
    r0 -= row0;
    c0 -= col0;
    const double h00 = at(r0, c0), h01 = at(r0, c0 + 1), h10 = at(r0 + 1, c0),
                 h11 = at(r0 + 1, c0 + 1);
    return (h00 * (1.0 - fc) + h01 * fc) * (1.0 - fr) + (h10 * (1.0 - fc) + h11 * fc) * fr;
  }
  double mean_height_m() const;
};

// Throws InputError naming the file when it cannot be read, is not
// geographic WGS 84, or is smaller than 2 x 2.
EllipsoidalDem read_ellipsoidal_dem(const std::filesystem::path& path);

// The DEM's heights with data: their range, and what was done about the
// vertical datum over the whole file (as read_ellipsoidal_dem says it).
struct EllipsoidalDemSummary {
  float min_m = 0.0F, max_m = 0.0F;  // +inf / -inf when no height has data
  std::string vertical_note;
  double geoid_offset_mean_m = 0.0;
};

// A DEM file open for windows of it (a streamed run reads the postings each
// block needs). The checks are read_ellipsoidal_dem's, made on opening.
class EllipsoidalDemFile {
 public:
  explicit EllipsoidalDemFile(const std::filesystem::path& path);
  ~EllipsoidalDemFile();
  EllipsoidalDemFile(const EllipsoidalDemFile&) = delete;
  EllipsoidalDemFile& operator=(const EllipsoidalDemFile&) = delete;

  // The file's grid and source, no heights (rows x cols: the whole grid).
  const EllipsoidalDem& grid() const { return grid_; }
  // Rows [row0, row0 + rows) x columns [col0, col0 + cols) of the grid
  // (clipped to it), ellipsoidal heights as read_ellipsoidal_dem gives them;
  // its vertical note and mean geoid offset are the window's.
  EllipsoidalDem read(int row0, int rows, int col0, int cols) const;
  // The whole file, band_rows rows at a time.
  EllipsoidalDemSummary summarise(int band_rows) const;

 private:
  struct Impl;
  EllipsoidalDem grid_;
  std::unique_ptr<Impl> impl_;
};

// A flat DEM (constant ellipsoidal height) over a latitude/longitude box,
// for tests and for "no DEM" runs.
EllipsoidalDem flat_ellipsoidal_dem(double lat_min_rad, double lat_max_rad, double lon_min_rad,
                                    double lon_max_rad, int rows, int cols, double height_m);

}  // namespace ris
