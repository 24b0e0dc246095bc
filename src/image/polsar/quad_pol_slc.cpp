// Reading a quad-pol SLC set and its covariance images
// (ris/image/polsar/quad_pol_slc.h).
#include "ris/image/polsar/quad_pol_slc.h"

#include <fmt/format.h>
#include <gdal.h>
#include <gdal_priv.h>

#include <cmath>
#include <cstdint>
#include <memory>

#include "ris/io/gdal_util.h"
#include "ris/io/safe_paths.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris {

namespace {

constexpr std::array<const char*, 4> kPols = {"HH", "HV", "VH", "VV"};

struct OneChannel {
  int cols = 0, rows = 0;
  std::vector<std::complex<float>> data;
  bool has_geotransform = false;
  std::array<double, 6> gt{};
  std::string wkt;
};

// Band 1 of a raster (a path or a GDAL subdataset name) as complex samples;
// `label` names it in messages (the file, or the file and its layer).
OneChannel read_channel(const std::string& name, bool subdataset, const std::string& label,
                        const char* pol) {
  const GdalDataset ds =
      subdataset ? GdalDataset(GDALOpenEx(name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr,
                                          nullptr, nullptr))
                 : open_raster(name);
  if (!ds) throw InputError(label, "", "GDAL cannot open it: " + last_gdal_error());
  if (GDALGetRasterCount(handle(ds)) < 1) throw InputError(label, "", "the raster has no band");
  GDALRasterBandH b = GDALGetRasterBand(handle(ds), 1);
  if (!GDALDataTypeIsComplex(GDALGetRasterDataType(b))) {
    throw InputError(label, pol,
                     fmt::format("expected a complex SLC band ({}), got {}: a quad-pol set is "
                                 "four single-look complex images",
                                 pol, GDALGetDataTypeName(GDALGetRasterDataType(b))));
  }
  OneChannel c;
  c.cols = GDALGetRasterXSize(handle(ds));
  c.rows = GDALGetRasterYSize(handle(ds));
  const std::int64_t pixels = checked_mul(c.cols, c.rows, label, pol);
  require_memory(checked_mul(pixels, 8, label, pol), label, pol,
                 fmt::format("reading the {} x {} {} image", c.cols, c.rows, pol));
  c.data.resize(static_cast<std::size_t>(pixels));
  if (GDALRasterIO(b, GF_Read, 0, 0, c.cols, c.rows, c.data.data(), c.cols, c.rows, GDT_CFloat32, 0,
                   0) != CE_None) {
    throw InputError(label, pol, "cannot read the image: " + last_gdal_error());
  }
  double gt[6];
  if (GDALGetGeoTransform(handle(ds), gt) == CE_None) {
    c.has_geotransform = true;
    for (int k = 0; k < 6; ++k) c.gt[static_cast<std::size_t>(k)] = gt[k];
    const char* wkt = GDALGetProjectionRef(handle(ds));
    c.wkt = wkt != nullptr ? wkt : "";
  }
  return c;
}

// The four channels into one set, refusing a channel whose size or grid is
// not the first's (naming both).
QuadPolSlc assemble(std::array<OneChannel, 4>& ch, const std::array<std::string, 4>& labels) {
  QuadPolSlc s;
  s.cols = ch[0].cols;
  s.rows = ch[0].rows;
  for (std::size_t i = 1; i < 4; ++i) {
    if (ch[i].cols != s.cols || ch[i].rows != s.rows) {
      throw InputError(
          labels[i], kPols[i],
          fmt::format("{} is {} x {} pixels but {} ({}) is {} x {}: the four "
                      "channels of a quad-pol set must share one grid",
                      kPols[i], ch[i].cols, ch[i].rows, kPols[0], labels[0], s.cols, s.rows));
    }
    if (ch[i].has_geotransform != ch[0].has_geotransform ||
        (ch[i].has_geotransform && ch[i].gt != ch[0].gt)) {
      throw InputError(labels[i], kPols[i],
                       fmt::format("{} is not on the grid of {} ({}): their geotransforms "
                                   "differ; resample the channels onto one grid first",
                                   kPols[i], kPols[0], labels[0]));
    }
  }
  s.has_geotransform = ch[0].has_geotransform;
  s.georef = Georef(ch[0].gt, ch[0].wkt);
  s.sources = labels;
  s.hh = std::move(ch[0].data);
  s.hv = std::move(ch[1].data);
  s.vh = std::move(ch[2].data);
  s.vv = std::move(ch[3].data);
  return s;
}

// The product's listOfPolarizations in `group` ("/science/LSAR/SLC/swaths/
// frequencyA"), comma separated, or "" when it has none or it cannot be read.
std::string listed_polarisations(const std::string& path, const std::string& group) {
  const std::unique_ptr<GDALDataset> ds(
      GDALDataset::Open(path.c_str(), GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY));
  if (!ds) return "";
  const auto root = ds->GetRootGroup();
  const auto a = root ? root->OpenMDArrayFromFullname(group + "/listOfPolarizations") : nullptr;
  if (!a || a->GetDimensionCount() != 1) return "";
  const std::size_t n = static_cast<std::size_t>(a->GetDimensions()[0]->GetSize());
  if (n == 0 || n > 16) return "";
  std::vector<char*> v(n, nullptr);
  const GUInt64 start = 0;
  const std::size_t count = n;
  std::string out;
  if (a->Read(&start, &count, nullptr, nullptr, GDALExtendedDataType::CreateString(), v.data())) {
    for (char* p : v) {
      if (p != nullptr) out += (out.empty() ? "" : ", ") + std::string(p);
    }
  }
  for (char* p : v) CPLFree(p);
  return out;
}

}  // namespace

QuadPolSlc read_quad_pol_rasters(const std::array<std::string, 4>& paths) {
  ensure_gdal_registered();
  std::array<OneChannel, 4> ch;
  for (std::size_t i = 0; i < 4; ++i) {
    require_regular_input(paths[i], kPols[i]);
    ch[i] = read_channel(paths[i], false, paths[i], kPols[i]);
  }
  QuadPolSlc s = assemble(ch, paths);
  s.format = "rasters";
  return s;
}

QuadPolSlc read_quad_pol_nisar(const std::string& path, const std::string& frequency) {
  ensure_gdal_registered();
  require_regular_input(path);
  if (frequency != "A" && frequency != "B") {
    throw InputError(path, "--frequency", fmt::format("expected A or B, got '{}'", frequency));
  }
  const GdalDataset ds(GDALOpenEx(path.c_str(), GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!ds) throw InputError(path, "", "GDAL cannot open it: " + last_gdal_error());
  // The SLC layers under swaths/frequency<F>/ by polarisation.
  std::array<std::string, 4> names;
  std::string held, group;
  char** subs = GDALGetMetadata(handle(ds), "SUBDATASETS");
  const std::string folder = "/swaths/frequency" + frequency + "/";
  for (int i = 0; subs != nullptr && subs[i] != nullptr; ++i) {
    const std::string item = subs[i];
    const auto eq = item.find('=');
    if (eq == std::string::npos || item.find("_NAME=") == std::string::npos) continue;
    const std::string name = item.substr(eq + 1);
    const auto at = name.find(folder);
    if (at == std::string::npos || name.find("SLC/swaths") == std::string::npos) continue;
    const std::string leaf = name.substr(at + folder.size());
    const auto root = name.find("://");
    if (group.empty() && root != std::string::npos) {
      group = name.substr(root + 2, at + folder.size() - 1 - (root + 2));
    }
    for (std::size_t p = 0; p < 4; ++p) {
      if (leaf == kPols[p]) {
        names[p] = name;
        held += (held.empty() ? "" : ", ") + leaf;
      }
    }
  }
  std::string missing;
  for (std::size_t p = 0; p < 4; ++p)
    if (names[p].empty()) missing += (missing.empty() ? "" : ", ") + std::string(kPols[p]);
  if (!missing.empty()) {
    const std::string listed = group.empty() ? "" : listed_polarisations(path, group);
    throw InputError(
        path, "frequency" + frequency,
        fmt::format("not a quad-pol product: no SLC layer {} under science/*/SLC/swaths/"
                    "frequency{} (the file holds {}{}); give four single-polarisation rasters "
                    "instead",
                    missing, frequency, held.empty() ? std::string("none") : held,
                    listed.empty()
                        ? std::string()
                        : "; its listOfPolarizations names " + listed + ", more than it stores"));
  }
  std::array<OneChannel, 4> ch;
  std::array<std::string, 4> labels;
  for (std::size_t p = 0; p < 4; ++p) {
    labels[p] = path + " (frequency" + frequency + "/" + kPols[p] + ")";
    ch[p] = read_channel(names[p], true, labels[p], kPols[p]);
  }
  QuadPolSlc s = assemble(ch, labels);
  s.format = "nisar-rslc";
  return s;
}

CovarianceImage single_look_c3(const QuadPolSlc& s) {
  CovarianceImage c;
  c.cols = s.cols;
  c.rows = s.rows;
  c.m.resize(s.hh.size());
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < s.hh.size(); ++i) {
    const Sinclair sm{Complex(s.hh[i]), Complex(s.hv[i]), Complex(s.vh[i]), Complex(s.vv[i])};
    c.m[i] = outer(lexicographic_vector(sm));
  }
  return c;
}

CovarianceImage boxcar_average(const CovarianceImage& c, int window_rows, int window_cols) {
  RIS_CHECK(window_rows >= 1 && window_cols >= 1 && window_rows % 2 == 1 && window_cols % 2 == 1);
  const int hr = window_rows / 2, hc = window_cols / 2;
  const auto at = [&](int r, int col) {
    return static_cast<std::size_t>(r) * static_cast<std::size_t>(c.cols) +
           static_cast<std::size_t>(col);
  };
  // Along rows (each line's running sum), then along columns.
  // Each output pixel is summed in the same order on any thread.
  CovarianceImage across = c;
#pragma omp parallel for schedule(static)
  for (int r = 0; r < c.rows; ++r) {
    for (int col = 0; col < c.cols; ++col) {
      const int c0 = std::max(0, col - hc), c1 = std::min(c.cols - 1, col + hc);
      Hermitian3 sum;
      for (int k = c0; k <= c1; ++k) sum = sum + c.m[at(r, k)];
      across.m[at(r, col)] = (1.0 / (c1 - c0 + 1)) * sum;
    }
  }
  CovarianceImage out = c;
#pragma omp parallel for schedule(static)
  for (int col = 0; col < c.cols; ++col) {
    for (int r = 0; r < c.rows; ++r) {
      const int r0 = std::max(0, r - hr), r1 = std::min(c.rows - 1, r + hr);
      Hermitian3 sum;
      for (int k = r0; k <= r1; ++k) sum = sum + across.m[at(k, col)];
      out.m[at(r, col)] = (1.0 / (r1 - r0 + 1)) * sum;
    }
  }
  return out;
}

CovarianceImage multilook(const CovarianceImage& c, int looks_rows, int looks_cols) {
  RIS_CHECK(looks_rows >= 1 && looks_cols >= 1);
  CovarianceImage out;
  out.is_t3 = c.is_t3;
  out.rows = c.rows / looks_rows;
  out.cols = c.cols / looks_cols;
  out.m.resize(static_cast<std::size_t>(out.rows) * static_cast<std::size_t>(out.cols));
  const double w = 1.0 / (looks_rows * looks_cols);
  for (int r = 0; r < out.rows; ++r) {
    for (int col = 0; col < out.cols; ++col) {
      Hermitian3 sum;
      for (int i = 0; i < looks_rows; ++i)
        for (int j = 0; j < looks_cols; ++j)
          sum = sum + c.m[static_cast<std::size_t>(r * looks_rows + i) * c.cols +
                          static_cast<std::size_t>(col * looks_cols + j)];
      out.m[static_cast<std::size_t>(r) * out.cols + col] = w * sum;
    }
  }
  return out;
}

CovarianceImage to_t3(const CovarianceImage& c3) {
  RIS_CHECK(!c3.is_t3);
  CovarianceImage t = c3;
  t.is_t3 = true;
  for (Hermitian3& m : t.m) m = t3_from_c3(m);
  return t;
}

CovarianceImage to_c3(const CovarianceImage& t3) {
  RIS_CHECK(t3.is_t3);
  CovarianceImage c = t3;
  c.is_t3 = false;
  for (Hermitian3& m : c.m) m = c3_from_t3(m);
  return c;
}

}  // namespace ris
