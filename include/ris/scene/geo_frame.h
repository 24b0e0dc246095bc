// Latitude/longitude <-> scene coordinates, through PROJ (GDAL's
// OGRCoordinateTransformation).
//
// Geographic coordinates are taken on the geodetic datum of the scene's own
// CRS (its base geographic CRS: WGS 84 for a scene imported from an SRTM-type
// DEM into UTM), so no datum shift is ever applied silently. Longitude and
// latitude are in degrees, longitude first (east positive), whatever axis
// order the CRS's authority declares.
//
// Not thread-safe: use one GeoFrame per thread (construction is cheap).
//
// Example:
//   ris::GeoFrame frame(scene.crs_wkt, "scene.tif");
//   auto [x_m, y_m] = frame.scene_from_lonlat(12.4964, 41.9028);
//   auto [lon, lat] = frame.lonlat_from_scene(x_m, y_m);
#pragma once

#include <memory>
#include <string>
#include <utility>

namespace ris {

class GeoFrame {
 public:
  // scene_crs_wkt: the scene's CRS, which must be projected with metre units
  // (ris scenes are metric). source: the file it came from, for messages.
  // Throws InputError when the CRS is empty, unreadable or not metric.
  GeoFrame(const std::string& scene_crs_wkt, const std::string& source);
  ~GeoFrame();
  GeoFrame(GeoFrame&&) noexcept;
  GeoFrame& operator=(GeoFrame&&) noexcept;

  // Scene (x, y) in metres of a longitude/latitude in degrees. Throws
  // InputError (naming the source) when PROJ cannot transform the point.
  std::pair<double, double> scene_from_lonlat(double lon_deg, double lat_deg) const;
  // Longitude/latitude in degrees of a scene point (x, y) in metres.
  std::pair<double, double> lonlat_from_scene(double x_m, double y_m) const;

  // Name of the geographic CRS latitude/longitude are taken in ("WGS 84").
  const std::string& geographic_crs_name() const;
  // Name of the scene's CRS ("WGS 84 / UTM zone 33N").
  const std::string& scene_crs_name() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// WKT of the WGS 84 / UTM zone holding a longitude/latitude in degrees (plain
// 6-degree zones, north or south by the latitude's sign).
std::string utm_wkt_for(double lon_deg, double lat_deg);

}  // namespace ris
