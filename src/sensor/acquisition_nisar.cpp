// NISAR / UAVSAR RSLC HDF5 products (NISAR RSLC product specification,
// JPL D-102268; ISCE3's nisar.products.readers.SLC): the orbit under
// science/LSAR/{SLC,RSLC}/metadata/orbit (time, position, velocity; times in
// "seconds since <epoch>"), the grid under .../swaths (zeroDopplerTime,
// zeroDopplerTimeSpacing) and .../swaths/frequency{A,B} (slantRange,
// slantRangeSpacing, processedCenterFrequency, nominalAcquisitionPRF,
// listOfPolarizations), the look side in identification/lookDirection.
// Read through GDAL's multidimensional API (GDAL's HDF5 driver), so no
// second HDF5 binding is needed.
//
// Every value is checked where it is read (ris/sensor/product_values.h):
// a dataset's declared size before anything is allocated, then each time,
// slant range, spacing, frequency and state vector finite and in its
// physical range, the error naming the dataset's path.
#include <cpl_string.h>
#include <fmt/format.h>
#include <gdal_priv.h>

#include <algorithm>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ris/io/gdal_util.h"
#include "ris/io/safe_paths.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/product_values.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"

namespace ris {
namespace {

class H5Reader {
 public:
  explicit H5Reader(const std::filesystem::path& path) : path_(path.string()) {
    require_regular_input(path_);  // a FIFO would block GDAL's open forever
    ensure_gdal_registered();
    ds_.reset(GDALDataset::Open(path_.c_str(), GDAL_OF_MULTIDIM_RASTER | GDAL_OF_READONLY));
    if (!ds_) {
      throw InputError(path_, "", "cannot open as an HDF5 product: " + last_gdal_error());
    }
    root_ = ds_->GetRootGroup();
    if (!root_) throw InputError(path_, "", "the file has no root group");
  }

  bool has(const std::string& name) const {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    const bool ok = root_->OpenMDArrayFromFullname(name) != nullptr;
    CPLPopErrorHandler();
    return ok;
  }

  std::shared_ptr<GDALMDArray> array(const std::string& name) const {
    CPLPushErrorHandler(CPLQuietErrorHandler);
    auto a = root_->OpenMDArrayFromFullname(name);
    CPLPopErrorHandler();
    if (!a) throw InputError(path_, name, "missing from the product (expected a NISAR RSLC)");
    return a;
  }

  // The dataset's values as doubles. Its declared dimensions are checked
  // first (at most max_values elements, N x expect_cols when given, not
  // empty) and the memory asked for against the resource guard, so a small
  // file declaring a huge never-written dataset is refused before anything
  // is allocated.
  std::vector<double> doubles(const std::string& name, std::int64_t max_values,
                              std::size_t expect_cols = 0) const {
    auto a = array(name);
    std::vector<GUInt64> start;
    std::vector<size_t> count;
    double declared = 1.0;  // in floating point: a product of sizes cannot overflow
    std::string shape;
    for (const auto& d : a->GetDimensions()) {
      const GUInt64 size = d->GetSize();
      declared *= static_cast<double>(size);
      shape += (shape.empty() ? "" : " x ") + std::to_string(size);
      start.push_back(0);
      count.push_back(static_cast<size_t>(size));
    }
    if (!(declared >= 1.0 && declared <= static_cast<double>(max_values))) {
      throw InputError(path_, name,
                       fmt::format("declares {:.0f} values ({}); expected 1 to {}", declared,
                                   shape.empty() ? "a scalar" : shape, max_values));
    }
    const auto n = static_cast<std::int64_t>(declared);
    if (expect_cols != 0 && (count.size() != 2 || count[1] != expect_cols)) {
      throw InputError(path_, name,
                       fmt::format("expected an N x {} array, got {}", expect_cols, shape));
    }
    require_memory(checked_mul(n, static_cast<std::int64_t>(sizeof(double)), path_, name), path_,
                   name, "the dataset's values");
    std::vector<double> v(static_cast<std::size_t>(n));
    if (!a->Read(start.data(), count.data(), nullptr, nullptr,
                 GDALExtendedDataType::Create(GDT_Float64), v.data())) {
      throw InputError(path_, name, "cannot read: " + last_gdal_error());
    }
    return v;
  }

  // One number, checked within r.
  double scalar(const std::string& name, const ValueRange& r) const {
    return require_in_range(doubles(name, 1)[0], r, path_, name);
  }

  std::string string(const std::string& name) const {
    auto a = array(name);
    if (a->GetDimensionCount() != 0) throw InputError(path_, name, "expected a scalar string");
    char* s = nullptr;
    if (!a->Read(nullptr, nullptr, nullptr, nullptr, GDALExtendedDataType::CreateString(), &s) ||
        s == nullptr) {
      throw InputError(path_, name, "cannot read the string");
    }
    std::string out(s);
    CPLFree(s);
    return out;
  }

  std::vector<std::string> strings(const std::string& name, std::size_t max_count) const {
    auto a = array(name);
    if (a->GetDimensionCount() != 1) throw InputError(path_, name, "expected a list of strings");
    const GUInt64 declared = a->GetDimensions()[0]->GetSize();
    if (declared > max_count) {
      throw InputError(
          path_, name,
          fmt::format("declares {} strings; expected at most {}", declared, max_count));
    }
    const auto n = static_cast<size_t>(declared);
    std::vector<char*> raw(n, nullptr);
    const GUInt64 start = 0;
    if (!a->Read(&start, &n, nullptr, nullptr, GDALExtendedDataType::CreateString(), raw.data())) {
      throw InputError(path_, name, "cannot read the strings");
    }
    std::vector<std::string> out;
    for (char* s : raw) {
      out.emplace_back(s != nullptr ? s : "");
      CPLFree(s);
    }
    return out;
  }

  // The epoch of a "seconds since <date-time>" units attribute.
  UtcTime epoch_of(const std::string& name) const {
    auto a = array(name);
    auto units = a->GetAttribute("units");
    const char* text = units ? units->ReadAsString() : nullptr;
    const auto e = text != nullptr ? parse_seconds_since(text) : std::nullopt;
    if (!e) {
      throw InputError(path_, name + "@units",
                       fmt::format("expected \"seconds since YYYY-MM-DD HH:MM:SS\", got \"{}\"",
                                   text != nullptr ? text : "(none)"));
    }
    return *e;
  }

 private:
  std::string path_;
  std::unique_ptr<GDALDataset> ds_;
  std::shared_ptr<GDALGroup> root_;
};

}  // namespace

namespace {

// The orbit under <base>/metadata/orbit: times against the epoch of the time
// array's units, each vector checked finite and of physical size.
Orbit read_orbit(const H5Reader& h5, const std::string& base, const std::string& file) {
  const std::string orbit = base + "/metadata/orbit";
  const StateVectorKeys keys{orbit + "/time", orbit + "/position", orbit + "/velocity"};
  const UtcTime epoch = h5.epoch_of(keys.time);
  const auto t = h5.doubles(keys.time, kMaxStateVectors);
  const auto pos = h5.doubles(keys.position, 3 * kMaxStateVectors, 3);
  const auto vel = h5.doubles(keys.velocity, 3 * kMaxStateVectors, 3);
  if (pos.size() != 3 * t.size() || vel.size() != 3 * t.size()) {
    throw InputError(file, orbit, "time, position and velocity differ in length");
  }
  std::vector<StateVector> sv(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    sv[i] = {t[i],
             {pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]},
             {vel[3 * i], vel[3 * i + 1], vel[3 * i + 2]}};
  }
  require_physical_state_vectors(sv, file, keys);
  return Orbit(epoch, std::move(sv), file);
}

// The radar grid of <base>/swaths and its frequency sub-swath `freq`:
// zero-Doppler times (re-referenced to the orbit's epoch when the product
// gives them against another) and slant ranges, each value checked.
RadarGrid read_grid(const H5Reader& h5, const std::string& base, const std::string& freq,
                    const UtcTime& epoch, const std::string& file) {
  const std::string zdt = base + "/swaths/zeroDopplerTime";
  const auto az = h5.doubles(zdt, kMaxGridLines);
  require_increasing_in_range(az, kProductTimeRange, file, zdt);
  const double shift_s = require_in_range(h5.epoch_of(zdt).seconds_since(epoch), kProductTimeRange,
                                          file, zdt + "@units");
  RadarGrid g;
  g.lines = static_cast<int>(az.size());
  g.sensing_start_s = az.front() + shift_s;
  g.line_interval_s = h5.scalar(base + "/swaths/zeroDopplerTimeSpacing", kLineIntervalRange);
  const std::string sr_name = freq + "/slantRange";
  const auto sr = h5.doubles(sr_name, kMaxGridLines);
  require_increasing_in_range(sr, kSlantRangeRange, file, sr_name);
  g.bins = static_cast<int>(sr.size());
  g.near_range_m = sr.front();
  g.range_spacing_m = h5.scalar(freq + "/slantRangeSpacing", kRangeSpacingRange);
  g.wavelength_m =
      kSpeedOfLight_m_per_s / h5.scalar(freq + "/processedCenterFrequency", kRadarFrequencyRange);
  g.prf_hz = h5.has(freq + "/nominalAcquisitionPRF")
                 ? h5.scalar(freq + "/nominalAcquisitionPRF", kPrfRange)
                 : 1.0 / g.line_interval_s;
  std::string look = h5.string("/science/LSAR/identification/lookDirection");
  for (char& c : look) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (look == "left") {
    g.look_side = LookSide::left;
  } else if (look == "right") {
    g.look_side = LookSide::right;
  } else {
    throw InputError(file, "/science/LSAR/identification/lookDirection",
                     fmt::format("expected left or right, got '{}'", look));
  }
  return g;
}

}  // namespace

Acquisition read_nisar_rslc(const std::filesystem::path& path, const AcquisitionOptions& options) {
  const H5Reader h5(path);
  const std::string file = path.string();
  // Older products (ISCE3's test data) name the group SLC, newer ones RSLC.
  std::string product;
  for (const char* p : {"RSLC", "SLC"}) {
    if (h5.has(fmt::format("/science/LSAR/{}/swaths/zeroDopplerTime", p))) product = p;
  }
  if (product.empty()) {
    throw InputError(file, "/science/LSAR/RSLC/swaths/zeroDopplerTime",
                     "missing: expected a NISAR RSLC product (science/LSAR/RSLC or SLC groups)");
  }
  const std::string base = "/science/LSAR/" + product;
  if (options.frequency != "A" && options.frequency != "B") {
    throw InputError("", "--frequency",
                     fmt::format("expected A or B, got '{}'", options.frequency));
  }
  const std::string freq = base + "/swaths/frequency" + options.frequency;

  Acquisition acq;
  acq.source = file;
  acq.format = "nisar-rslc";
  acq.mission = h5.has("/science/LSAR/identification/missionId")
                    ? h5.string("/science/LSAR/identification/missionId")
                    : "NISAR";
  acq.orbit = read_orbit(h5, base, file);
  acq.grid = read_grid(h5, base, freq, acq.orbit.epoch(), file);
  const RadarGrid& g = acq.grid;
  if (h5.has(freq + "/listOfPolarizations")) {
    // At most the four linear polarisations (and their compact-pol kin).
    const auto pols = h5.strings(freq + "/listOfPolarizations", 16);
    if (!pols.empty()) acq.polarisation = pols.front();
  }
  if (!acq.orbit.covers(g.sensing_start_s) || !acq.orbit.covers(g.end_s())) {
    throw InputError(file, base + "/metadata/orbit/time",
                     "the orbit does not cover the image's lines");
  }
  acq.notes.push_back(fmt::format("frequency {}, {} lines x {} bins, zero-Doppler grid",
                                  options.frequency, g.lines, g.bins));
  return acq;
}

}  // namespace ris
