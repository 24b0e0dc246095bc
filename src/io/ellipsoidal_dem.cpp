#include "ris/io/ellipsoidal_dem.h"

#include <fmt/format.h>
#include <gdal_priv.h>
#include <ogr_spatialref.h>

#include <memory>

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

EllipsoidalDem read_ellipsoidal_dem(const std::filesystem::path& path) {
  const std::string file = path.string();
  const GdalDataset ds = open_raster(file);
  GDALDatasetH h = handle(ds);
  EllipsoidalDem dem;
  dem.source = file;
  dem.cols = GDALGetRasterXSize(h);
  dem.rows = GDALGetRasterYSize(h);
  if (dem.cols < 2 || dem.rows < 2) throw InputError(file, "", "expected at least 2 x 2 cells");
  std::array<double, 6> gt{};
  if (GDALGetGeoTransform(h, gt.data()) != CE_None || gt[2] != 0.0 || gt[4] != 0.0) {
    throw InputError(file, "geotransform", "expected a north-up geotransform");
  }
  const OGRSpatialReferenceH srs_h = GDALGetSpatialRef(h);
  if (srs_h == nullptr) throw InputError(file, "CRS", "the DEM has no CRS (expected EPSG:4326)");
  OGRSpatialReference srs(*OGRSpatialReference::FromHandle(srs_h));
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

  GDALRasterBandH band = GDALGetRasterBand(h, 1);
  const std::size_t n = static_cast<std::size_t>(dem.cols) * dem.rows;
  std::vector<double> buf(n);
  if (GDALRasterIO(band, GF_Read, 0, 0, dem.cols, dem.rows, buf.data(), dem.cols, dem.rows,
                   GDT_Float64, 0, 0) != CE_None) {
    throw InputError(file, "", "cannot read band 1: " + last_gdal_error());
  }
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  int has_scale = 0, has_offset = 0;
  const double scale = GDALGetRasterScale(band, &has_scale);
  const double offset = GDALGetRasterOffset(band, &has_offset);
  for (double& v : buf) {
    if ((has_nodata != 0 && v == nodata) || !std::isfinite(v)) {
      v = std::nan("");
    } else {
      v = v * (has_scale != 0 ? scale : 1.0) + (has_offset != 0 ? offset : 0.0);
    }
  }

  // Vertical datum: geoid heights to ellipsoidal heights through PROJ.
  if (srs.IsCompound()) {
    OGRSpatialReference ell;
    ell.importFromEPSG(4979);
    srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    ell.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    const char* vname = srs.GetAttrValue("VERT_CS");
    const std::string vert = vname != nullptr ? vname : "a vertical datum";
    CPLPushErrorHandler(CPLQuietErrorHandler);
    std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&srs, &ell));
    // PROJ falls back to a ballpark (no shift) when the geoid grid is
    // missing: check it moved a height at the DEM's centre.
    bool shifted = false;
    std::vector<double> x(static_cast<std::size_t>(dem.cols)), y(x.size()), z(x.size());
    double sum_offset = 0.0;
    std::size_t n_offset = 0;
    if (ct) {
      for (int r = 0; r < dem.rows; ++r) {
        for (int c = 0; c < dem.cols; ++c) {
          x[c] = gt[0] + (c + 0.5) * gt[1];
          y[c] = gt[3] + (r + 0.5) * gt[5];
          z[c] = 0.0;
        }
        if (!ct->Transform(dem.cols, x.data(), y.data(), z.data())) break;
        for (int c = 0; c < dem.cols; ++c) {
          double& v = buf[static_cast<std::size_t>(r) * dem.cols + c];
          if (z[c] != 0.0) shifted = true;
          if (std::isfinite(v)) {
            v += z[c];
            sum_offset += z[c];
            ++n_offset;
          }
        }
      }
    }
    CPLPopErrorHandler();
    if (shifted) {
      dem.geoid_offset_mean_m = n_offset > 0 ? sum_offset / static_cast<double>(n_offset) : 0.0;
      dem.vertical_note = fmt::format(
          "heights above {} converted to WGS 84 ellipsoidal heights with PROJ (mean geoid "
          "undulation {:.2f} m)",
          vert, dem.geoid_offset_mean_m);
    } else {
      dem.vertical_note = fmt::format(
          "heights above {} used as ellipsoidal heights: PROJ has no geoid grid for it here "
          "(install proj-data, or set PROJ_NETWORK=ON); expect errors of the geoid undulation",
          vert);
    }
  } else {
    dem.vertical_note =
        "the DEM declares no vertical datum: heights taken as above the WGS 84 ellipsoid";
  }
  dem.height_m.resize(n);
  for (std::size_t i = 0; i < n; ++i) dem.height_m[i] = static_cast<float>(buf[i]);
  return dem;
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
