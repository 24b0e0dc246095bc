// Reading and writing scenes through GDAL.
//
// A ris scene file is a GeoTIFF with two Float32 bands: band 1 elevation
// (metres, description "elevation_m"), band 2 category id (description
// "category"; Float32 holds every uint16 id exactly, and GeoTIFF requires one
// sample type for all bands). No-data is NaN in both bands. The geotransform
// and CRS are kept; metadata item RIS_SCENE=1 marks the file.
//
// Any other GDAL raster is read as an elevation model (band 1) with every
// cell of category 0, or with categories from a second raster on exactly the
// same grid. A DEM in a geographic CRS (or in feet) is imported on the fly
// with import_dem (ris/scene/dem_import.h): reprojected into the UTM zone of its
// centre at the default cell size.
//
// Example:
//   ris::Scene s = ris::read_scene("scene.tif");
//   ris::write_scene_geotiff(s, "copy.tif");
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ris/io/geotiff_block_writer.h"
#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"

namespace ris {

// extra_metadata: items added to the file's metadata (provenance such as
// RIS_SOURCE_DEM, RIS_FRAME; see ris/scene/dem_import.h).
void write_scene_geotiff(const Scene& scene, const std::filesystem::path& path,
                         const RasterMetadata& extra_metadata = {});

// A scene GeoTIFF written in blocks of rows (ris/io/geotiff_block_writer.h),
// for scenes larger than memory; write_scene_geotiff uses it, so the bytes
// are the same. grid: rows, cols, cell size, origin, CRS (arrays unused).
class SceneGeoTiffWriter {
 public:
  SceneGeoTiffWriter(const std::filesystem::path& path, const Scene& grid,
                     const RasterMetadata& extra_metadata = {},
                     const GeoTiffCompression& compression = {});
  ~SceneGeoTiffWriter();
  SceneGeoTiffWriter(const SceneGeoTiffWriter&) = delete;
  SceneGeoTiffWriter& operator=(const SceneGeoTiffWriter&) = delete;
  // The next `count` rows (count x cols each); cells with valid == 0 are
  // written as no-data.
  void write_rows(const float* elevation_m, const std::uint16_t* category,
                  const std::uint8_t* valid, int count);
  // Completes the file and renames it into place.
  void close();

 private:
  std::unique_ptr<GeoTiffBlockWriter<float>> writer_;
  int cols_ = 0;
  std::vector<float> elevation_, category_;
};

// Reads a ris scene file or an elevation raster (any GDAL format). With
// category_path, categories come from band 1 of that raster, which must have
// the same size and geotransform; its no-data cells become no-data.
// Elevation no-data and NaN cells are marked invalid. Throws InputError for
// unreadable, empty or mismatched inputs.
Scene read_scene(const std::filesystem::path& path,
                 const std::optional<std::filesystem::path>& category_path = std::nullopt);

// Number of cells marked no-data.
std::size_t count_nodata(const Scene& scene);

}  // namespace ris
