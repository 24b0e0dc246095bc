// Raster files that name other files: which ris opens, and which it refuses.
//
// A GDAL VRT (and other formats with side files) is a text that names the
// files holding its pixels, and GDAL follows any path it names: an untrusted
// VRT whose raw band is /etc/passwd reads that file, one whose source is a
// FIFO hangs the reader, one with a /vsicurl/ or "HDF5:" source reaches
// wherever it points. ris writes VRTs of its own (a scene's two bands beside
// it: docs/scene-format.md), so VRTs are not refused as such. Instead, by
// default (as GDAL's own GDAL_VRT_ENABLE_RAWRASTERBAND and the sarsen/ISCE
// practice of opening only what the product lists):
//   - a VRT's sources, read from its XML before GDAL opens it, must be plain
//     paths to regular files inside the VRT's own folder (or below it),
//     themselves checked the same way when they are VRTs (at most 8 deep);
//   - no raw raster bands (a VRTRawRasterBand reads any file's bytes as
//     pixels) and no Python pixel functions;
//   - every file GDAL lists for an opened raster (GDALGetFileList: side
//     files, overviews, a VRT's sources) lies in that folder too.
// RIS_ALLOW_FILE_REFERENCES=1 lifts these checks for inputs the user trusts
// (docs/limits.md).
#pragma once

#include <gdal.h>

#include <string>

namespace ris {

// Whether $RIS_ALLOW_FILE_REFERENCES is set.
bool file_references_allowed();

// Before GDAL opens `path`: when it is a VRT (by its content, whatever its
// name), InputError naming the VRT and the source unless every source obeys
// the rules above.
void require_safe_vrt_sources(const std::string& path);

// After GDAL opened `path` as `ds`: InputError naming the file unless every
// file GDAL lists for it lies in the folder of `path`.
void require_files_beside(GDALDatasetH ds, const std::string& path);

}  // namespace ris
