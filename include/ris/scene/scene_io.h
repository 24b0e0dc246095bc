// Reading and writing scenes through GDAL.
//
// A ris scene file is a GeoTIFF with two Float32 bands: band 1 elevation
// (metres, description "elevation_m"), band 2 category id (description
// "category"; Float32 holds every uint16 id exactly, and GDAL's GeoTIFF holds
// one sample type for all bands). No-data is NaN in both bands. The
// geotransform and CRS are kept; metadata item RIS_SCENE=1 marks the file.
//
// A scene written to a path ending in ".vrt" (scene_is_vrt) keeps its
// categories as an integer band instead: three files, <stem>_elevation.tif
// (Float32, NaN no-data), <stem>_category.tif (UInt16, no-data 65535 =
// kNoDataCategory) and the GDAL VRT <stem>.vrt that binds them, by relative
// paths, into the same two-band scene (band 2 UInt16). GDAL, QGIS and every
// ris command open the VRT as one raster; the folder can be moved whole.
// This is how GIS users get an integer class band (for a palette or an
// attribute table) beside a float elevation: GDAL's formats that take mixed
// band types (VRT, KEA, netCDF) are either not a single file or not what a
// GIS opens by default, and the VRT is GDAL's own answer (gdalbuildvrt
// -separate).
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

// Whether a scene written to `path` is the VRT form (the extension is
// ".vrt", any case).
bool scene_is_vrt(const std::filesystem::path& path);

// The files a scene written to `path` consists of: the path itself, and for
// the VRT form its two GeoTIFF parts (first), in the VRT's folder.
std::vector<std::filesystem::path> scene_files(const std::filesystem::path& path);

// extra_metadata: items added to the file's metadata (provenance such as
// RIS_SOURCE_DEM, RIS_FRAME; see ris/scene/dem_import.h). A ".vrt" path
// writes the VRT form (above).
void write_scene_geotiff(const Scene& scene, const std::filesystem::path& path,
                         const RasterMetadata& extra_metadata = {});

// A scene GeoTIFF written in blocks of rows (ris/io/geotiff_block_writer.h),
// for scenes larger than memory; write_scene_geotiff uses it, so the bytes
// are the same. grid: rows, cols, cell size, origin, CRS (arrays unused).
// A ".vrt" path writes the VRT form; its parts are renamed into place by
// close(), the VRT last (a failure before it removes them again).
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
  // Completes the file (or files) and renames it into place.
  void close();

 private:
  // The whole scene (.tif) or, for the VRT form, its elevation part.
  std::unique_ptr<GeoTiffBlockWriter<float>> writer_;
  // The VRT form's category part.
  std::unique_ptr<GeoTiffBlockWriter<std::uint16_t>> category_writer_;
  std::filesystem::path path_;
  RasterMetadata metadata_;
  int cols_ = 0;
  std::vector<float> elevation_, category_;
  std::vector<std::uint16_t> category_id_;
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
