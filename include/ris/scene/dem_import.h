// Importing a digital elevation model (any GDAL raster: GeoTIFF, SRTM .hgt,
// DTED, ASCII grid, ...) as a ris Scene in a metric frame (docs/terrain.md).
//
// - A DEM in a projected CRS with metre units keeps its CRS and grid (or is
//   resampled in that CRS when a cell size is given).
// - A DEM in a geographic CRS (or a projected one in feet) is reprojected
//   once with GDAL's warper (GDALWarp, bilinear) into the UTM zone of its
//   centre, on the DEM's own geodetic datum (WGS 84 for SRTM, Copernicus,
//   ...). The cell size defaults to what gdalwarp would choose (square cells
//   keeping the diagonal's cell count), rounded to two significant digits,
//   and the grid is aligned on multiples of the cell size.
// - Heights are taken as the DEM gives them (scale, offset and foot units
//   applied): the scene's vertical datum is the DEM's (EGM96 geoid heights
//   for SRTM). It is named in the metadata when the file declares it.
// - No-data stays no-data: a scene cell is no-data when the DEM posting
//   nearest its centre is no-data or lies outside the DEM. Such cells are
//   counted (ImportedDem::nodata_cells, metadata RIS_NODATA_CELLS).
// - A DEM with no CRS is refused unless one is supplied (crs option); a grid
//   too large for memory is refused with the estimate.
//
// Example:
//   ris::DemImportOptions opt;
//   opt.cell_size_m = 30.0;
//   ris::ImportedDem dem = ris::import_dem("N41E012.hgt", opt);
//   ris::write_scene_geotiff(dem.scene, "scene.tif", dem.metadata);
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"

namespace ris {

struct DemImportOptions {
  // Output cell size in metres; nullopt: the native posting (projected DEMs)
  // or the posting in metres rounded to two significant digits (geographic).
  std::optional<double> cell_size_m;
  // CRS of the DEM as GDAL reads it ("EPSG:4326", WKT, PROJ string); required
  // when the file has none, and overrides the file's CRS otherwise.
  std::optional<std::string> crs;
  // Category given to every valid cell (land cover comes later, landcover.h).
  std::uint16_t category = kDefaultCategory;
  // Names of the options, for messages (command-line flags or config keys).
  std::string cell_size_key = "--cell-size";
  std::string crs_key = "--crs";
};

struct ImportedDem {
  Scene scene;
  // What was done, for the scene file's metadata: RIS_SOURCE_DEM,
  // RIS_SOURCE_CRS, RIS_FRAME, RIS_VERTICAL_DATUM, RIS_NODATA_CELLS, ...
  RasterMetadata metadata;
  std::size_t nodata_cells = 0;  // scene cells marked no-data
  bool reprojected = false;      // true when the GDAL warper made the grid
  std::string frame;             // "WGS 84 / UTM zone 33N", the scene CRS name
  std::string vertical_datum;    // what the heights are relative to
};

ImportedDem import_dem(const std::filesystem::path& dem_path, const DemImportOptions& options = {});

// True when read_scene cannot use the raster as it stands: it is not a ris
// scene file and its CRS is geographic or not in metres, so it needs
// import_dem. False for rasters without a CRS (read in pixel units).
bool dem_needs_import(const std::filesystem::path& dem_path);

// The UTM zone (1..60) holding a longitude in degrees. Plain 6-degree zones:
// the Norway and Svalbard exceptions are not applied.
int utm_zone_of_longitude(double lon_deg);

// Rounds a positive length to two significant digits (26.93 -> 27, 0.347 ->
// 0.35), for default cell sizes.
double round_two_significant(double value);

}  // namespace ris
