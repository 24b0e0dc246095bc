#include "ris/scene/geo_frame.h"

#include <fmt/format.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>

#include "ris/io/gdal_util.h"
#include "ris/util/error.h"

namespace ris {

struct GeoFrame::Impl {
  std::string source;
  std::string geographic_name;
  std::string scene_name;
  std::unique_ptr<OGRCoordinateTransformation> to_scene;
  std::unique_ptr<OGRCoordinateTransformation> to_geo;
};

GeoFrame::GeoFrame(const std::string& scene_crs_wkt, const std::string& source)
    : impl_(std::make_unique<Impl>()) {
  ensure_gdal_writers_registered();
  impl_->source = source;
  if (scene_crs_wkt.empty()) {
    throw InputError(source, "crs",
                     "the scene has no CRS, so latitude/longitude cannot be placed on it "
                     "(import the DEM with ris scene import, or give --crs)");
  }
  OGRSpatialReference scene_srs;
  if (scene_srs.importFromWkt(scene_crs_wkt.c_str()) != OGRERR_NONE) {
    throw InputError(source, "crs", "the scene's CRS is not readable WKT");
  }
  if (!scene_srs.IsProjected() || std::abs(scene_srs.GetLinearUnits() - 1.0) > 1e-12) {
    throw InputError(source, "crs",
                     fmt::format("the scene's CRS ({}) is not a projected CRS in metres; "
                                 "import the DEM with ris scene import first",
                                 scene_srs.GetName() ? scene_srs.GetName() : "unnamed"));
  }
  // Heights stay in the DEM's vertical datum: transform horizontally only.
  scene_srs.StripVertical();
  OGRSpatialReference geo_srs;
  geo_srs.CopyGeogCSFrom(&scene_srs);
  // Longitude first, whatever the authority's axis order (EPSG:4326 is lat, lon).
  scene_srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  geo_srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  impl_->geographic_name = geo_srs.GetName() ? geo_srs.GetName() : "geographic";
  impl_->scene_name = scene_srs.GetName() ? scene_srs.GetName() : "projected";
  impl_->to_scene.reset(OGRCreateCoordinateTransformation(&geo_srs, &scene_srs));
  impl_->to_geo.reset(OGRCreateCoordinateTransformation(&scene_srs, &geo_srs));
  if (!impl_->to_scene || !impl_->to_geo) {
    throw InputError(
        source, "crs",
        "PROJ cannot transform between the scene CRS and its geographic CRS: " + last_gdal_error());
  }
}

GeoFrame::~GeoFrame() = default;
GeoFrame::GeoFrame(GeoFrame&&) noexcept = default;
GeoFrame& GeoFrame::operator=(GeoFrame&&) noexcept = default;

std::pair<double, double> GeoFrame::scene_from_lonlat(double lon_deg, double lat_deg) const {
  double x = lon_deg, y = lat_deg;
  if (!(std::abs(lat_deg) <= 90.0) || !std::isfinite(lon_deg) ||
      !impl_->to_scene->Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y)) {
    throw InputError(impl_->source, "",
                     fmt::format("latitude {} deg, longitude {} deg cannot be placed in {}",
                                 lat_deg, lon_deg, impl_->scene_name));
  }
  return {x, y};
}

std::pair<double, double> GeoFrame::lonlat_from_scene(double x_m, double y_m) const {
  double x = x_m, y = y_m;
  if (!impl_->to_geo->Transform(1, &x, &y) || !std::isfinite(x) || !std::isfinite(y)) {
    throw InputError(impl_->source, "",
                     fmt::format("scene point ({}, {}) m has no latitude/longitude in {}", x_m, y_m,
                                 impl_->scene_name));
  }
  return {x, y};
}

const std::string& GeoFrame::geographic_crs_name() const {
  return impl_->geographic_name;
}
const std::string& GeoFrame::scene_crs_name() const {
  return impl_->scene_name;
}

std::string utm_wkt_for(double lon_deg, double lat_deg) {
  ensure_gdal_writers_registered();
  double lon = std::fmod(lon_deg + 180.0, 360.0);
  if (lon < 0.0) lon += 360.0;
  const int zone = std::clamp(static_cast<int>(std::floor(lon / 6.0)) + 1, 1, 60);
  OGRSpatialReference srs;
  // EPSG 326zz (north) and 327zz (south): WGS 84 / UTM zone zz.
  srs.importFromEPSG((lat_deg >= 0.0 ? 32600 : 32700) + zone);
  return wkt_of(srs);
}

}  // namespace ris
