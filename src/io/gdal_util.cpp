#include "ris/io/gdal_util.h"

#include <cpl_error.h>
#include <spdlog/spdlog.h>

#include <filesystem>
#include <mutex>

#include "ris/util/error.h"

namespace ris {

namespace {
void CPL_STDCALL gdal_error_handler(CPLErr level, CPLErrorNum, const char* message) {
  if (level >= CE_Warning) spdlog::debug("GDAL: {}", message);
}
}  // namespace

void ensure_gdal_registered() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    CPLSetErrorHandler(gdal_error_handler);
  });
}

std::string last_gdal_error() {
  const char* msg = CPLGetLastErrorMsg();
  return (msg != nullptr && *msg != '\0') ? std::string(msg) : std::string("unknown GDAL error");
}

GdalDataset open_raster(const std::string& path) {
  ensure_gdal_registered();
  if (!std::filesystem::exists(path)) throw InputError(path, "", "no such file");
  CPLErrorReset();
  GDALDatasetH ds =
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
  if (ds == nullptr) {
    throw InputError(path, "", "not a readable raster (" + last_gdal_error() + ")");
  }
  if (GDALGetRasterCount(ds) < 1 || GDALGetRasterXSize(ds) < 1 || GDALGetRasterYSize(ds) < 1) {
    GDALClose(ds);
    throw InputError(path, "", "the raster is empty (no bands or no pixels)");
  }
  return GdalDataset(ds);
}

}  // namespace ris
