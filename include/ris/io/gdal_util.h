// Small helpers around GDAL's C API: one-time driver registration, an owning
// dataset handle, and errors turned into InputError.
#pragma once

#include <gdal.h>

#include <memory>
#include <string>

namespace ris {

// Registers GDAL's drivers once (thread-safe) and routes GDAL's own error
// messages to spdlog at debug level (ris reports errors itself).
void ensure_gdal_registered();

struct GdalCloser {
  void operator()(void* ds) const {
    if (ds != nullptr) GDALClose(static_cast<GDALDatasetH>(ds));
  }
};
using GdalDataset = std::unique_ptr<void, GdalCloser>;

inline GDALDatasetH handle(const GdalDataset& ds) {
  return static_cast<GDALDatasetH>(ds.get());
}

// Opens a raster for reading; throws InputError naming the file when it is
// missing, unreadable or not a raster.
GdalDataset open_raster(const std::string& path);

// The last GDAL error message, or "unknown GDAL error".
std::string last_gdal_error();

}  // namespace ris
