// Sentinel-1 SLC products (SAFE): orbit, radar grid and geolocation grid
// from the annotation XML (ESA S1-RS-MDA-52-7441). Read with GDAL's
// CPLParseXMLFile (already linked; the annotation is plain XML).
//
// The radar grid: slant range of the first sample = slantRangeTime * c / 2,
// spacing c / (2 rangeSamplingRate); lines every azimuthTimeInterval. For
// TOPS (IW/EW) products the image is a stack of bursts whose zero-Doppler
// times overlap; ris reads one burst (its own uniform grid) or the whole
// sub-swath as one uniform "debursted" grid from the first burst's first
// line to the last burst's last line (what ISCE3 and sarsen mosaic into).
// Stripmap products have one grid from productFirstLineUtcTime (as SNAP's
// and OTB's readers take it when there are no bursts).
//
// Only slant-range SLC annotations are read: a GRD product (productType GRD,
// projection "Ground Range") has its pixels on a ground-range grid, mapped
// to slant range by the annotation's coordinateConversionList polynomials,
// which ris's uniform slant-range RadarGrid does not model; it is refused
// naming productType. Every number is checked finite and in its physical
// range where it is read (ris/sensor/product_values.h), the error naming
// the element.
#include <cpl_minixml.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "ris/io/safe_paths.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/product_values.h"
#include "ris/sensor/sentinel1_annotation.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"

namespace ris {
namespace {

struct XmlCloser {
  void operator()(CPLXMLNode* n) const { CPLDestroyXMLNode(n); }
};
using XmlTree = std::unique_ptr<CPLXMLNode, XmlCloser>;

class Annotation {
 public:
  explicit Annotation(const std::filesystem::path& xml) : file_(xml.string()) {
    require_regular_input(file_);  // a FIFO would block the parser forever
    tree_.reset(CPLParseXMLFile(file_.c_str()));
    if (!tree_) throw InputError(file_, "", "cannot parse as XML");
    product_ = CPLGetXMLNode(tree_.get(), "=product");
    if (product_ == nullptr) {
      throw InputError(file_, "product", "no <product> root: not a Sentinel-1 annotation");
    }
  }

  const CPLXMLNode* node(const CPLXMLNode* from, const std::string& path) const {
    const CPLXMLNode* n = CPLGetXMLNode(const_cast<CPLXMLNode*>(from), path.c_str());
    if (n == nullptr) throw InputError(file_, path, "missing from the annotation");
    return n;
  }
  std::string text(const CPLXMLNode* from, const std::string& path) const {
    const char* v = CPLGetXMLValue(const_cast<CPLXMLNode*>(from), path.c_str(), nullptr);
    if (v == nullptr) throw InputError(file_, path, "missing from the annotation");
    return v;
  }
  double number(const CPLXMLNode* from, const std::string& path) const {
    const std::string s = text(from, path);
    try {
      std::size_t used = 0;
      const double v = std::stod(s, &used);
      if (used == s.size() && std::isfinite(v)) return v;
    } catch (const std::exception&) {
    }
    throw InputError(file_, path, fmt::format("expected a finite number, got '{}'", s));
  }
  // A number within r.
  double number(const CPLXMLNode* from, const std::string& path, const ValueRange& r) const {
    return require_in_range(number(from, path), r, file_, path);
  }
  // A whole number in [lo, hi].
  int whole(const CPLXMLNode* from, const std::string& path, std::int64_t lo,
            std::int64_t hi) const {
    return require_whole_number(number(from, path), lo, hi, file_, path);
  }
  UtcTime time(const CPLXMLNode* from, const std::string& path) const {
    const std::string s = text(from, path);
    const auto t = parse_utc(s);
    if (!t) throw InputError(file_, path, fmt::format("expected a UTC date-time, got '{}'", s));
    return *t;
  }
  // The child elements named `name` of a list element.
  std::vector<const CPLXMLNode*> children(const std::string& list, const std::string& name) const {
    std::vector<const CPLXMLNode*> out;
    for (const CPLXMLNode* c = node(product_, list)->psChild; c != nullptr; c = c->psNext) {
      if (c->eType == CXT_Element && name == c->pszValue) out.push_back(c);
    }
    return out;
  }

  const CPLXMLNode* product() const { return product_; }
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  XmlTree tree_;
  const CPLXMLNode* product_ = nullptr;
};

}  // namespace

std::filesystem::path sentinel1_annotation_path(const std::filesystem::path& path,
                                                const std::string& swath) {
  if (!std::filesystem::is_directory(path)) {
    require_regular_input(path.string());  // an annotation XML, not a FIFO or device
    return path;
  }
  const auto dir = path / "annotation";
  if (!std::filesystem::is_directory(dir)) {
    throw InputError(path.string(), "",
                     "expected a Sentinel-1 .SAFE folder (with annotation/) or an annotation XML");
  }
  std::vector<std::filesystem::path> found;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    if (e.is_regular_file() && e.path().extension() == ".xml" &&
        (swath.empty() || name.find(swath) != std::string::npos)) {
      found.push_back(e.path());
    }
  }
  std::sort(found.begin(), found.end());
  if (found.size() == 1) return found.front();
  std::string list;
  for (const auto& f : found) list += "\n  " + f.filename().string();
  throw InputError(path.string(), "--swath",
                   found.empty() ? fmt::format("no annotation XML matches '{}'", swath)
                                 : "several annotations; choose one with --swath:" + list);
}

namespace {

// Refuses anything but a slant-range SLC (GRD: see the top of this file).
void require_slant_range_slc(const Annotation& a) {
  const CPLXMLNode* p = a.product();
  const std::string type = a.text(p, "adsHeader.productType");
  const std::string mode = a.text(p, "adsHeader.mode");
  const std::string projection = a.text(p, "generalAnnotation.productInformation.projection");
  if (type != "SLC") {
    throw InputError(
        a.file(), "adsHeader.productType",
        fmt::format("a Sentinel-1 {} product ({} mode, {} projection): ris reads SLC annotations "
                    "only, whose pixels lie on a uniform slant-range grid; a GRD's pixels lie on "
                    "a ground-range grid (the annotation's coordinateConversionList), which ris "
                    "does not model: use the SLC product of the same acquisition",
                    type, mode, projection));
  }
  if (projection != "Slant Range") {
    throw InputError(a.file(), "generalAnnotation.productInformation.projection",
                     fmt::format("expected \"Slant Range\" for an SLC, got \"{}\"", projection));
  }
}

// The annotation's state vectors (Earth-fixed), times against midnight of the
// first one's day.
Orbit read_orbit(const Annotation& a) {
  const auto orbits = a.children("generalAnnotation.orbitList", "orbit");
  if (orbits.empty()) throw InputError(a.file(), "generalAnnotation.orbitList", "no orbit");
  if (orbits.size() > static_cast<std::size_t>(kMaxStateVectors)) {
    throw InputError(
        a.file(), "generalAnnotation.orbitList",
        fmt::format("{} state vectors; expected at most {}", orbits.size(), kMaxStateVectors));
  }
  UtcTime epoch = a.time(orbits.front(), "time");
  epoch.seconds_of_day = 0.0;
  std::vector<StateVector> sv;
  for (const CPLXMLNode* o : orbits) {
    sv.push_back(
        {a.time(o, "time").seconds_since(epoch),
         {a.number(o, "position.x"), a.number(o, "position.y"), a.number(o, "position.z")},
         {a.number(o, "velocity.x"), a.number(o, "velocity.y"), a.number(o, "velocity.z")}});
  }
  const std::string list = "generalAnnotation.orbitList.orbit.";
  require_physical_state_vectors(sv, a.file(),
                                 {list + "time", list + "position", list + "velocity"});
  return Orbit(epoch, std::move(sv), a.file());
}

// The ellipsoid the annotation states.
Ellipsoid read_ellipsoid(const Annotation& a) {
  const std::string info = "imageAnnotation.processingInformation.";
  const double major_m =
      a.number(a.product(), info + "ellipsoidSemiMajorAxis", kEllipsoidAxisRange);
  const double minor_m =
      a.number(a.product(), info + "ellipsoidSemiMinorAxis", kEllipsoidAxisRange);
  if (minor_m > major_m) {
    throw InputError(a.file(), info + "ellipsoidSemiMinorAxis",
                     fmt::format("{} m exceeds the semi-major axis {} m", minor_m, major_m));
  }
  return Ellipsoid::from_axes(major_m, minor_m);
}

// The grid's range axis and the radar's constants (the azimuth axis is
// read_azimuth_grid's).
RadarGrid read_range_grid(const Annotation& a) {
  const CPLXMLNode* p = a.product();
  const double c = kSpeedOfLight_m_per_s;
  // The two-way time of kSlantRangeRange.
  const ValueRange range_time{2.0 * kSlantRangeRange.lo / c, 2.0 * kSlantRangeRange.hi / c, "s",
                              "a two-way slant range time"};
  RadarGrid g;
  g.near_range_m =
      a.number(p, "imageAnnotation.imageInformation.slantRangeTime", range_time) * c / 2.0;
  g.range_spacing_m =
      c / (2.0 * a.number(p, "generalAnnotation.productInformation.rangeSamplingRate",
                          kRangeSamplingRateRange));
  g.bins = a.whole(p, "imageAnnotation.imageInformation.numberOfSamples", 1, kMaxGridLines);
  g.wavelength_m =
      c / a.number(p, "generalAnnotation.productInformation.radarFrequency", kRadarFrequencyRange);
  g.look_side = LookSide::right;  // every Sentinel-1 mode looks right
  g.line_interval_s =
      a.number(p, "imageAnnotation.imageInformation.azimuthTimeInterval", kLineIntervalRange);
  g.prf_hz =
      a.number(p, "generalAnnotation.downlinkInformationList.downlinkInformation.prf", kPrfRange);
  return g;
}

// A time of the annotation in seconds since epoch, within kProductTimeRange.
double seconds_since(const Annotation& a, const CPLXMLNode* from, const std::string& path,
                     const UtcTime& epoch) {
  return require_in_range(a.time(from, path).seconds_since(epoch), kProductTimeRange, a.file(),
                          path);
}

// The azimuth axis: one strip, one burst or the debursted sub-swath.
void read_azimuth_grid(const Annotation& a, const AcquisitionOptions& options, Acquisition& acq) {
  const CPLXMLNode* p = a.product();
  const std::string mode = a.text(p, "adsHeader.mode");
  const UtcTime& epoch = acq.orbit.epoch();
  RadarGrid& g = acq.grid;
  const auto bursts = a.children("swathTiming.burstList", "burst");
  if (bursts.empty()) {
    if (options.burst) throw InputError("", "--burst", "the product has no bursts (stripmap)");
    g.sensing_start_s =
        seconds_since(a, p, "imageAnnotation.imageInformation.productFirstLineUtcTime", epoch);
    g.lines = a.whole(p, "imageAnnotation.imageInformation.numberOfLines", 1, kMaxGridLines);
    return;
  }
  // Stripmap annotations give linesPerBurst 0: read only with bursts.
  const int lines_per_burst = a.whole(p, "swathTiming.linesPerBurst", 1, kMaxGridLines);
  std::vector<double> starts_s;
  for (const CPLXMLNode* b : bursts) {
    starts_s.push_back(seconds_since(a, b, "azimuthTime", epoch));
  }
  require_increasing_in_range(starts_s, kProductTimeRange, a.file(),
                              "swathTiming.burstList.burst.azimuthTime");
  if (options.burst) {
    const int b = *options.burst;
    if (b < 0 || b >= static_cast<int>(bursts.size())) {
      throw InputError("", "--burst",
                       fmt::format("expected 0..{} (the product has {} bursts), got {}",
                                   bursts.size() - 1, bursts.size(), b));
    }
    g.sensing_start_s = starts_s[static_cast<std::size_t>(b)];
    g.lines = lines_per_burst;
    acq.notes.push_back(fmt::format("{} burst {} of {}: lines {}..{} of the SLC image", mode, b,
                                    bursts.size(), std::int64_t{b} * lines_per_burst,
                                    (std::int64_t{b} + 1) * lines_per_burst - 1));
    return;
  }
  const double t0 = starts_s.front();
  const double t1 = starts_s.back() + (lines_per_burst - 1) * g.line_interval_s;
  g.sensing_start_s = t0;
  g.lines =
      static_cast<int>(checked_count(std::round((t1 - t0) / g.line_interval_s) + 1.0, kMaxGridLines,
                                     a.file(), "swathTiming.burstList", "debursted lines"));
  acq.notes.push_back(fmt::format(
      "{} sub-swath of {} bursts on one debursted zero-Doppler grid ({} lines; the SLC "
      "image stacks {} lines of overlapping bursts)",
      mode, bursts.size(), g.lines, bursts.size() * static_cast<std::size_t>(lines_per_burst)));
}

}  // namespace

Acquisition read_sentinel1(const std::filesystem::path& path, const AcquisitionOptions& options) {
  const Annotation a(sentinel1_annotation_path(path, options.swath));
  const CPLXMLNode* p = a.product();
  require_slant_range_slc(a);

  Acquisition acq;
  acq.source = a.file();
  acq.format = "sentinel-1-safe";
  acq.mission = a.text(p, "adsHeader.missionId");
  acq.polarisation = a.text(p, "adsHeader.polarisation");
  acq.orbit = read_orbit(a);
  acq.ellipsoid = read_ellipsoid(a);
  acq.grid = read_range_grid(a);
  read_azimuth_grid(a, options, acq);
  if (!acq.orbit.covers(acq.grid.sensing_start_s) || !acq.orbit.covers(acq.grid.end_s())) {
    throw InputError(a.file(), "generalAnnotation.orbitList",
                     "the orbit does not cover the image's lines");
  }
  return acq;
}

std::vector<Sentinel1TiePoint> read_sentinel1_tie_points(const std::filesystem::path& path,
                                                         const std::string& swath) {
  const Annotation a(sentinel1_annotation_path(path, swath));
  std::vector<Sentinel1TiePoint> out;
  for (const CPLXMLNode* n :
       a.children("geolocationGrid.geolocationGridPointList", "geolocationGridPoint")) {
    Sentinel1TiePoint t;
    t.azimuth_time = a.time(n, "azimuthTime");
    t.slant_range_time_s = a.number(n, "slantRangeTime");
    t.line = a.whole(n, "line", 0, kMaxGridLines);
    t.pixel = a.whole(n, "pixel", 0, kMaxGridLines);
    t.lat_deg = a.number(n, "latitude", kLatitudeRange);
    t.lon_deg = a.number(n, "longitude", kLongitudeRange);
    t.height_m = a.number(n, "height", kGroundHeightRange);
    t.incidence_deg = a.number(n, "incidenceAngle");
    t.elevation_deg = a.number(n, "elevationAngle");
    out.push_back(t);
  }
  return out;
}

}  // namespace ris
