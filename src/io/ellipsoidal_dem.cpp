#include "ris/io/ellipsoidal_dem.h"

#include <fmt/format.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <array>
#include <limits>
#include <memory>
#include <utility>

#include "ris/io/gdal_util.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

double EllipsoidalDem::mean_height_m() const {
  double sum = 0.0;
  std::size_t n = 0;
  for (float h : height_m) {
    if (std::isfinite(h)) {
      sum += h;
      ++n;
    }
  }
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

// The open file and what converting its heights needs.
struct EllipsoidalDemFile::Impl {
  explicit Impl(GdalDataset d) : ds(std::move(d)) {}

  GdalDataset ds;
  std::array<double, 6> gt{};
  OGRSpatialReference srs;
  GDALRasterBandH band = nullptr;
  int has_nodata = 0, has_scale = 0, has_offset = 0;
  double nodata = 0.0, scale = 1.0, offset = 0.0;
  std::string vertical;  // the vertical datum's name (a compound CRS)
  std::unique_ptr<OGRCoordinateTransformation> to_ellipsoid;  // null: none, or PROJ cannot

  // Geoid offsets added so far, in row-major order (the mean and the note).
  struct Shift {
    bool shifted = false;
    double sum = 0.0;
    std::size_t n = 0;
  };

  // Rows [row0, row0 + rows) x columns [col0, col0 + cols): heights in
  // metres (NaN: no data), on the ellipsoid where PROJ can convert them.
  std::vector<double> heights(const std::string& file, int row0, int rows, int col0, int cols,
                              Shift& shift) const {
    std::vector<double> buf(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
    if (buf.empty()) return buf;
    if (GDALRasterIO(band, GF_Read, col0, row0, cols, rows, buf.data(), cols, rows, GDT_Float64, 0,
                     0) != CE_None) {
      throw InputError(file, "", "cannot read band 1: " + last_gdal_error());
    }
    for (double& v : buf) {
      if ((has_nodata != 0 && v == nodata) || !std::isfinite(v)) {
        v = std::nan("");
      } else {
        v = v * (has_scale != 0 ? scale : 1.0) + (has_offset != 0 ? offset : 0.0);
      }
    }
    if (!to_ellipsoid) return buf;
    // Geoid heights to ellipsoidal heights, a row at a time.
    std::vector<double> x(static_cast<std::size_t>(cols)), y(x.size()), z(x.size());
    CPLPushErrorHandler(CPLQuietErrorHandler);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        x[c] = gt[0] + (col0 + c + 0.5) * gt[1];
        y[c] = gt[3] + (row0 + r + 0.5) * gt[5];
        z[c] = 0.0;
      }
      if (!to_ellipsoid->Transform(cols, x.data(), y.data(), z.data())) break;
      for (int c = 0; c < cols; ++c) {
        double& v = buf[static_cast<std::size_t>(r) * cols + c];
        if (z[c] != 0.0) shift.shifted = true;
        if (std::isfinite(v)) {
          v += z[c];
          shift.sum += z[c];
          ++shift.n;
        }
      }
    }
    CPLPopErrorHandler();
    return buf;
  }

  // What was done about the vertical datum (read_ellipsoidal_dem's note).
  std::string note(const Shift& shift, double& mean_offset) const {
    mean_offset = 0.0;
    if (!srs.IsCompound()) {
      return "the DEM declares no vertical datum: heights taken as above the WGS 84 ellipsoid";
    }
    if (!shift.shifted) {
      return fmt::format(
          "heights above {} used as ellipsoidal heights: PROJ has no geoid grid for it here "
          "(install proj-data, or set PROJ_NETWORK=ON); expect errors of the geoid undulation",
          vertical);
    }
    mean_offset = shift.n > 0 ? shift.sum / static_cast<double>(shift.n) : 0.0;
    return fmt::format(
        "heights above {} converted to WGS 84 ellipsoidal heights with PROJ (mean geoid "
        "undulation {:.2f} m)",
        vertical, mean_offset);
  }
};

EllipsoidalDemFile::EllipsoidalDemFile(const std::filesystem::path& path)
    : impl_(std::make_unique<Impl>(open_raster(path.string()))) {
  const std::string file = path.string();
  GDALDatasetH h = handle(impl_->ds);
  EllipsoidalDem& dem = grid_;
  dem.source = file;
  dem.cols = GDALGetRasterXSize(h);
  dem.rows = GDALGetRasterYSize(h);
  if (dem.cols < 2 || dem.rows < 2) throw InputError(file, "", "expected at least 2 x 2 cells");
  std::array<double, 6>& gt = impl_->gt;
  if (GDALGetGeoTransform(h, gt.data()) != CE_None || gt[2] != 0.0 || gt[4] != 0.0) {
    throw InputError(file, "geotransform", "expected a north-up geotransform");
  }
  const OGRSpatialReferenceH srs_h = GDALGetSpatialRef(h);
  if (srs_h == nullptr) throw InputError(file, "CRS", "the DEM has no CRS (expected EPSG:4326)");
  OGRSpatialReference& srs = impl_->srs;
  srs = *OGRSpatialReference::FromHandle(srs_h);
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  if (!srs.IsGeographic() && !(srs.IsCompound() && srs.IsGeographic())) {
    throw InputError(file, "CRS",
                     "expected a geographic DEM on WGS 84 (EPSG:4326); reproject it first, e.g. "
                     "gdalwarp -t_srs EPSG:4326 in.tif out.tif");
  }
  OGRSpatialReference horiz;
  horiz.CopyGeogCSFrom(&srs);
  if (!horiz.IsSameGeogCS(&wgs84)) {
    throw InputError(file, "CRS",
                     fmt::format("expected WGS 84 latitude/longitude, got {}",
                                 srs.GetName() != nullptr ? srs.GetName() : "another datum"));
  }
  // Cell centres.
  dem.lon0_rad = deg_to_rad(gt[0] + 0.5 * gt[1]);
  dem.lat0_rad = deg_to_rad(gt[3] + 0.5 * gt[5]);
  dem.dlon_rad = deg_to_rad(gt[1]);
  dem.dlat_rad = deg_to_rad(gt[5]);

  Impl& im = *impl_;
  im.band = GDALGetRasterBand(h, 1);
  im.nodata = GDALGetRasterNoDataValue(im.band, &im.has_nodata);
  im.scale = GDALGetRasterScale(im.band, &im.has_scale);
  im.offset = GDALGetRasterOffset(im.band, &im.has_offset);
  // Vertical datum: geoid heights to ellipsoidal heights through PROJ
  // (PROJ falls back to a ballpark, no shift, when the geoid grid is
  // missing: the note says whether a height moved).
  if (srs.IsCompound()) {
    OGRSpatialReference ell;
    ell.importFromEPSG(4979);
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    ell.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const char* vname = srs.GetAttrValue("VERT_CS");
    im.vertical = vname != nullptr ? vname : "a vertical datum";
    CPLPushErrorHandler(CPLQuietErrorHandler);
    im.to_ellipsoid.reset(OGRCreateCoordinateTransformation(&srs, &ell));
    CPLPopErrorHandler();
  }
}

EllipsoidalDemFile::~EllipsoidalDemFile() = default;

EllipsoidalDem EllipsoidalDemFile::read(int row0, int rows, int col0, int cols) const {
  const int r0 = std::clamp(row0, 0, grid_.rows), c0 = std::clamp(col0, 0, grid_.cols);
  const int r1 = std::clamp(row0 + std::max(rows, 0), r0, grid_.rows);
  const int c1 = std::clamp(col0 + std::max(cols, 0), c0, grid_.cols);
  EllipsoidalDem dem = grid_;
  dem.row0 = r0;
  dem.col0 = c0;
  dem.rows = r1 - r0;
  dem.cols = c1 - c0;
  dem.grid_rows = grid_.rows;
  dem.grid_cols = grid_.cols;
  if (dem.rows == grid_.rows && dem.cols == grid_.cols) dem.grid_rows = dem.grid_cols = 0;
  Impl::Shift shift;
  const std::vector<double> buf = impl_->heights(dem.source, r0, dem.rows, c0, dem.cols, shift);
  dem.vertical_note = impl_->note(shift, dem.geoid_offset_mean_m);
  dem.height_m.resize(buf.size());
  for (std::size_t i = 0; i < buf.size(); ++i) dem.height_m[i] = static_cast<float>(buf[i]);
  return dem;
}

EllipsoidalDemSummary EllipsoidalDemFile::summarise(int band_rows) const {
  EllipsoidalDemSummary out;
  out.min_m = std::numeric_limits<float>::infinity();
  out.max_m = -out.min_m;
  Impl::Shift shift;
  const int step = std::max(band_rows, 1);
  for (int r0 = 0; r0 < grid_.rows; r0 += step) {
    const int n = std::min(step, grid_.rows - r0);
    for (double v : impl_->heights(grid_.source, r0, n, 0, grid_.cols, shift)) {
      const auto h = static_cast<float>(v);
      if (!std::isfinite(h)) continue;
      out.min_m = std::min(out.min_m, h);
      out.max_m = std::max(out.max_m, h);
    }
  }
  out.vertical_note = impl_->note(shift, out.geoid_offset_mean_m);
  return out;
}

EllipsoidalDem read_ellipsoidal_dem(const std::filesystem::path& path) {
  const EllipsoidalDemFile file(path);
  return file.read(0, file.grid().rows, 0, file.grid().cols);
}

EllipsoidalDem flat_ellipsoidal_dem(double lat_min_rad, double lat_max_rad, double lon_min_rad,
                                    double lon_max_rad, int rows, int cols, double height_m) {
  EllipsoidalDem d;
  d.rows = rows;
  d.cols = cols;
  d.lat0_rad = lat_max_rad;
  d.dlat_rad = (lat_min_rad - lat_max_rad) / (rows - 1);
  d.lon0_rad = lon_min_rad;
  d.dlon_rad = (lon_max_rad - lon_min_rad) / (cols - 1);
  d.height_m.assign(static_cast<std::size_t>(rows) * cols, static_cast<float>(height_m));
  d.source = "flat";
  d.vertical_note = "flat ellipsoidal height";
  return d;
}

}  // namespace ris
