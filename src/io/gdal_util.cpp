#include "ris/io/gdal_util.h"

#include <cpl_error.h>
#include <fmt/format.h>
#include <gdal_frmts.h>
#include <gdal_utils.h>
#include <ogr_spatialref.h>
#include <spdlog/spdlog.h>

#include <sys/resource.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <mutex>
#include <utility>
#include <vector>

#include "ris/io/file_references.h"
#include "ris/io/safe_paths.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris {

namespace {
void CPL_STDCALL gdal_error_handler(CPLErr level, CPLErrorNum, const char* message) {
  if (level >= CE_Warning) spdlog::debug("GDAL: {}", message);
}
}  // namespace

void ensure_gdal_writers_registered() {
  static std::once_flag once;
  std::call_once(once, [] {
    CPLSetErrorHandler(gdal_error_handler);
    GDALRegister_GTiff();
    GDALRegister_PNG();
    GDALRegister_MEM();
  });
}

void ensure_gdal_registered() {
  ensure_gdal_writers_registered();
  // GDALAllRegister skips the drivers already registered.
  static std::once_flag once;
  std::call_once(once, [] { GDALAllRegister(); });
}

std::string last_gdal_error() {
  const char* msg = CPLGetLastErrorMsg();
  return (msg != nullptr && *msg != '\0') ? std::string(msg) : std::string("unknown GDAL error");
}

std::string write_failure(const std::filesystem::path& out, const std::filesystem::path& written,
                          std::int64_t needed_bytes) {
  const int err = errno;  // of the failed write, when nothing since has set it
  const std::string gdal = last_gdal_error();
  const std::string needs =
      needed_bytes > 0 ? fmt::format("; the file needs up to {}", format_bytes(needed_bytes)) : "";
  // libtiff reports "Write error" whatever the cause: the limit and the
  // room are looked at directly.
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(written, ec);
  rlimit lim{};
  const bool limited = ::getrlimit(RLIMIT_FSIZE, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY;
  const bool at_limit = limited && !ec && size + (1u << 16) >= lim.rlim_cur;
  if (err == EFBIG || at_limit) {
    return fmt::format(
        "write failed: the file-size limit{} was reached ({}){}: raise it (ulimit -f) or write "
        "smaller products",
        limited ? fmt::format(" of {}", format_bytes(static_cast<std::int64_t>(lim.rlim_cur)))
                : std::string(),
        gdal, needs);
  }
  const std::filesystem::path folder = out.parent_path().empty() ? "." : out.parent_path();
  const std::int64_t free_bytes = free_disk_bytes(folder);
  if (err == ENOSPC || gdal.find("No space left") != std::string::npos ||
      free_bytes < (std::int64_t{1} << 20)) {
    return fmt::format(
        "write failed: the disk is full ({}); {} free at {}{}: free some space or write "
        "elsewhere",
        gdal, format_bytes(free_bytes), folder.string(), needs);
  }
  return "write failed: " + gdal;
}

GdalDataset open_raster(const std::string& path) {
  ensure_gdal_registered();
  require_regular_input(path);     // a FIFO would block GDAL forever
  require_safe_vrt_sources(path);  // nor may a file it names (ris/io/file_references.h)
  CPLErrorReset();
  GDALDatasetH ds =
      GDALOpenEx(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
  if (ds == nullptr) {
    throw InputError(path, "", "not a readable raster (" + last_gdal_error() + ")");
  }
  try {
    require_files_beside(ds, path);
  } catch (...) {
    GDALClose(ds);
    throw;
  }
  if (GDALGetRasterCount(ds) < 1 || GDALGetRasterXSize(ds) < 1 || GDALGetRasterYSize(ds) < 1) {
    GDALClose(ds);
    throw InputError(path, "", "the raster is empty (no bands or no pixels)");
  }
  return GdalDataset(ds);
}

std::array<double, 4> raster_outline(const std::array<double, 6>& gt, int cols, int rows) {
  std::array<double, 4> b{1e300, 1e300, -1e300, -1e300};
  for (const auto& [c, r] :
       {std::pair{0, 0}, std::pair{cols, 0}, std::pair{0, rows}, std::pair{cols, rows}}) {
    const double x = gt[0] + c * gt[1] + r * gt[2];
    const double y = gt[3] + c * gt[4] + r * gt[5];
    b[0] = std::min(b[0], x);
    b[1] = std::min(b[1], y);
    b[2] = std::max(b[2], x);
    b[3] = std::max(b[3], y);
  }
  return b;
}

std::string wkt_of(const OGRSpatialReference& srs) {
  char* text = nullptr;
  const char* const options[] = {"FORMAT=WKT2_2019", nullptr};
  srs.exportToWkt(&text, options);
  std::string out = text != nullptr ? text : "";
  CPLFree(text);
  return out;
}

namespace {
// A GDAL utility options list from strings (argv style, null-terminated).
struct Argv {
  std::vector<std::string> args;
  std::vector<char*> ptrs;
  char** get() {
    ptrs.clear();
    for (auto& a : args) ptrs.push_back(a.data());
    ptrs.push_back(nullptr);
    return ptrs.data();
  }
};
}  // namespace

GdalDataset warp_band1(GDALDatasetH src, const std::string& src_wkt, const WarpGrid& grid,
                       const std::string& resampling, const std::string& output_type,
                       const std::string& dst_nodata, const std::string& path) {
  const auto num = [](double v) { return fmt::format("{:.17g}", v); };
  Argv argv;
  argv.args = {"-of", "MEM", "-s_srs", src_wkt, "-t_srs", grid.crs_wkt, "-te", num(grid.min_x),
               num(grid.max_y - grid.rows * grid.cell_y), num(grid.min_x + grid.cols * grid.cell_x),
               num(grid.max_y), "-ts", std::to_string(grid.cols), std::to_string(grid.rows), "-r",
               resampling, "-ot", output_type, "-dstnodata", dst_nodata,
               // Exact PROJ transformation at every cell: the default
               // approximation allows 1/8 cell of error.
               "-et", "0"};
  GDALRasterBandH band = GDALGetRasterBand(src, 1);
  int has_nodata = 0;
  GDALGetRasterNoDataValue(band, &has_nodata);
  const GDALDataType type = GDALGetRasterDataType(band);
  if (has_nodata == 0 && (type == GDT_Float32 || type == GDT_Float64)) {
    argv.args.insert(argv.args.end(), {"-srcnodata", "nan"});
  }
  // Only band 1 (GDAL 3.6's gdalwarp has no band option): select it first.
  GdalDataset band1;
  GDALDatasetH input = src;
  if (GDALGetRasterCount(src) > 1) {
    Argv targv;
    targv.args = {"-of", "VRT", "-b", "1"};
    GDALTranslateOptions* topts = GDALTranslateOptionsNew(targv.get(), nullptr);
    RIS_CHECK(topts != nullptr);
    band1.reset(GDALTranslate("", src, topts, nullptr));
    GDALTranslateOptionsFree(topts);
    if (!band1) throw InputError(path, "", "cannot select band 1: " + last_gdal_error());
    input = handle(band1);
  }
  GDALWarpAppOptions* wopts = GDALWarpAppOptionsNew(argv.get(), nullptr);
  RIS_CHECK(wopts != nullptr);
  int usage_error = 0;
  GDALDatasetH srcs[] = {input};
  CPLErrorReset();
  GDALDatasetH out = GDALWarp("", nullptr, 1, srcs, wopts, &usage_error);
  GDALWarpAppOptionsFree(wopts);
  if (out == nullptr) {
    throw InputError(path, "", "GDAL's warper failed: " + last_gdal_error());
  }
  return GdalDataset(out);
}

}  // namespace ris
