// NISAR / UAVSAR RSLC HDF5 products (NISAR RSLC product specification,
// JPL D-102268; ISCE3's nisar.products.readers.SLC): the orbit under
// science/LSAR/{SLC,RSLC}/metadata/orbit (time, position, velocity; times in
// "seconds since <epoch>"), the grid under .../swaths (zeroDopplerTime,
// zeroDopplerTimeSpacing) and .../swaths/frequency{A,B} (slantRange,
// slantRangeSpacing, processedCenterFrequency, nominalAcquisitionPRF,
// listOfPolarizations), the look side in identification/lookDirection.
// Read through GDAL's multidimensional API (GDAL's HDF5 driver), so no
// second HDF5 binding is needed.
#include <cpl_string.h>
#include <fmt/format.h>
#include <gdal_priv.h>

#include <memory>
#include <string>
#include <vector>

#include "ris/io/gdal_util.h"
#include "ris/sensor/acquisition.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

class H5Reader {
 public:
  explicit H5Reader(const std::filesystem::path& path) : path_(path.string()) {
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

  std::vector<double> doubles(const std::string& name, std::size_t expect_cols = 0) const {
    auto a = array(name);
    std::size_t n = 1;
    std::vector<GUInt64> start;
    std::vector<size_t> count;
    for (const auto& d : a->GetDimensions()) {
      start.push_back(0);
      count.push_back(static_cast<size_t>(d->GetSize()));
      n *= static_cast<std::size_t>(d->GetSize());
    }
    if (expect_cols != 0 && (count.size() != 2 || count[1] != expect_cols)) {
      throw InputError(path_, name, fmt::format("expected an N x {} array", expect_cols));
    }
    std::vector<double> v(n);
    if (!a->Read(start.data(), count.data(), nullptr, nullptr,
                 GDALExtendedDataType::Create(GDT_Float64), v.data())) {
      throw InputError(path_, name, "cannot read: " + last_gdal_error());
    }
    return v;
  }

  double scalar(const std::string& name) const {
    const auto v = doubles(name);
    if (v.size() != 1) throw InputError(path_, name, "expected one number");
    return v[0];
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

  std::vector<std::string> strings(const std::string& name) const {
    auto a = array(name);
    if (a->GetDimensionCount() != 1) throw InputError(path_, name, "expected a list of strings");
    const auto n = static_cast<size_t>(a->GetDimensions()[0]->GetSize());
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

  // Orbit: times relative to the epoch in the time array's units.
  const std::string orbit = base + "/metadata/orbit";
  const UtcTime epoch = h5.epoch_of(orbit + "/time");
  const auto t = h5.doubles(orbit + "/time");
  const auto pos = h5.doubles(orbit + "/position", 3);
  const auto vel = h5.doubles(orbit + "/velocity", 3);
  if (pos.size() != 3 * t.size() || vel.size() != 3 * t.size()) {
    throw InputError(file, orbit, "time, position and velocity differ in length");
  }
  std::vector<StateVector> sv(t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    sv[i] = {t[i],
             {pos[3 * i], pos[3 * i + 1], pos[3 * i + 2]},
             {vel[3 * i], vel[3 * i + 1], vel[3 * i + 2]}};
  }
  acq.orbit = Orbit(epoch, std::move(sv), file);

  // Grid: zero-Doppler times (re-referenced to the orbit's epoch when the
  // product gives them against another), slant ranges.
  const std::string zdt = base + "/swaths/zeroDopplerTime";
  const auto az = h5.doubles(zdt);
  const double shift_s = h5.epoch_of(zdt).seconds_since(epoch);
  RadarGrid& g = acq.grid;
  g.lines = static_cast<int>(az.size());
  g.sensing_start_s = az.front() + shift_s;
  g.line_interval_s = h5.scalar(base + "/swaths/zeroDopplerTimeSpacing");
  const auto sr = h5.doubles(freq + "/slantRange");
  g.bins = static_cast<int>(sr.size());
  g.near_range_m = sr.front();
  g.range_spacing_m = h5.scalar(freq + "/slantRangeSpacing");
  const double f_hz = h5.scalar(freq + "/processedCenterFrequency");
  g.wavelength_m = kSpeedOfLight_m_per_s / f_hz;
  g.prf_hz = h5.has(freq + "/nominalAcquisitionPRF") ? h5.scalar(freq + "/nominalAcquisitionPRF")
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
  if (!(g.line_interval_s > 0.0) || !(g.range_spacing_m > 0.0) || g.lines < 1 || g.bins < 1) {
    throw InputError(file, base + "/swaths", "the radar grid is empty or its spacings not > 0");
  }
  if (h5.has(freq + "/listOfPolarizations")) {
    const auto pols = h5.strings(freq + "/listOfPolarizations");
    if (!pols.empty()) acq.polarisation = pols.front();
  }
  if (!acq.orbit.covers(g.sensing_start_s) || !acq.orbit.covers(g.end_s())) {
    throw InputError(file, orbit + "/time", "the orbit does not cover the image's lines");
  }
  acq.notes.push_back(fmt::format("frequency {}, {} lines x {} bins, zero-Doppler grid",
                                  options.frequency, g.lines, g.bins));
  return acq;
}

}  // namespace ris
