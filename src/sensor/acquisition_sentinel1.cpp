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
// Stripmap products have one grid from productFirstLineUtcTime.
#include <cpl_minixml.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ris/sensor/acquisition.h"
#include "ris/sensor/sentinel1_annotation.h"
#include "ris/util/error.h"
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
    throw InputError(file_, path, fmt::format("expected a number, got '{}'", s));
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
  if (std::filesystem::is_regular_file(path)) return path;
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

Acquisition read_sentinel1(const std::filesystem::path& path, const AcquisitionOptions& options) {
  const Annotation a(sentinel1_annotation_path(path, options.swath));
  const CPLXMLNode* p = a.product();

  Acquisition acq;
  acq.source = a.file();
  acq.format = "sentinel-1-safe";
  acq.mission = a.text(p, "adsHeader.missionId");
  acq.polarisation = a.text(p, "adsHeader.polarisation");
  const std::string mode = a.text(p, "adsHeader.mode");

  // Orbit: the annotation's state vectors (Earth-fixed), times against the
  // first one's date.
  const auto orbits = a.children("generalAnnotation.orbitList", "orbit");
  if (orbits.empty()) throw InputError(a.file(), "generalAnnotation.orbitList", "no orbit");
  UtcTime epoch = a.time(orbits.front(), "time");
  epoch.seconds_of_day = 0.0;  // midnight of the first vector's day
  std::vector<StateVector> sv;
  for (const CPLXMLNode* o : orbits) {
    sv.push_back(
        {a.time(o, "time").seconds_since(epoch),
         {a.number(o, "position.x"), a.number(o, "position.y"), a.number(o, "position.z")},
         {a.number(o, "velocity.x"), a.number(o, "velocity.y"), a.number(o, "velocity.z")}});
  }
  acq.orbit = Orbit(epoch, std::move(sv), a.file());

  // Earth model and range grid.
  acq.ellipsoid = Ellipsoid::from_axes(
      a.number(p, "imageAnnotation.processingInformation.ellipsoidSemiMajorAxis"),
      a.number(p, "imageAnnotation.processingInformation.ellipsoidSemiMinorAxis"));
  RadarGrid& g = acq.grid;
  const double c = kSpeedOfLight_m_per_s;
  g.near_range_m = a.number(p, "imageAnnotation.imageInformation.slantRangeTime") * c / 2.0;
  g.range_spacing_m =
      c / (2.0 * a.number(p, "generalAnnotation.productInformation.rangeSamplingRate"));
  g.bins = static_cast<int>(a.number(p, "imageAnnotation.imageInformation.numberOfSamples"));
  g.wavelength_m = c / a.number(p, "generalAnnotation.productInformation.radarFrequency");
  g.look_side = LookSide::right;  // every Sentinel-1 mode looks right
  g.line_interval_s = a.number(p, "imageAnnotation.imageInformation.azimuthTimeInterval");
  g.prf_hz = a.number(p, "generalAnnotation.downlinkInformationList.downlinkInformation.prf");

  // Azimuth grid: bursts (TOPS) or one strip.
  const auto bursts = a.children("swathTiming.burstList", "burst");
  const int lines_per_burst = static_cast<int>(a.number(p, "swathTiming.linesPerBurst"));
  if (bursts.empty()) {
    if (options.burst) throw InputError("", "--burst", "the product has no bursts (stripmap)");
    g.sensing_start_s =
        a.time(p, "imageAnnotation.imageInformation.productFirstLineUtcTime").seconds_since(epoch);
    g.lines = static_cast<int>(a.number(p, "imageAnnotation.imageInformation.numberOfLines"));
  } else if (options.burst) {
    const int b = *options.burst;
    if (b < 0 || b >= static_cast<int>(bursts.size())) {
      throw InputError("", "--burst",
                       fmt::format("expected 0..{} (the product has {} bursts), got {}",
                                   bursts.size() - 1, bursts.size(), b));
    }
    g.sensing_start_s = a.time(bursts[b], "azimuthTime").seconds_since(epoch);
    g.lines = lines_per_burst;
    acq.notes.push_back(fmt::format("{} burst {} of {}: lines {}..{} of the SLC image", mode, b,
                                    bursts.size(), b * lines_per_burst,
                                    (b + 1) * lines_per_burst - 1));
  } else {
    const double t0 = a.time(bursts.front(), "azimuthTime").seconds_since(epoch);
    const double t1 = a.time(bursts.back(), "azimuthTime").seconds_since(epoch) +
                      (lines_per_burst - 1) * g.line_interval_s;
    g.sensing_start_s = t0;
    g.lines = static_cast<int>(std::lround((t1 - t0) / g.line_interval_s)) + 1;
    acq.notes.push_back(fmt::format(
        "{} sub-swath of {} bursts on one debursted zero-Doppler grid ({} lines; the SLC "
        "image stacks {} lines of overlapping bursts)",
        mode, bursts.size(), g.lines, bursts.size() * static_cast<std::size_t>(lines_per_burst)));
  }
  if (!acq.orbit.covers(g.sensing_start_s) || !acq.orbit.covers(g.end_s())) {
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
    t.line = static_cast<int>(a.number(n, "line"));
    t.pixel = static_cast<int>(a.number(n, "pixel"));
    t.lat_deg = a.number(n, "latitude");
    t.lon_deg = a.number(n, "longitude");
    t.height_m = a.number(n, "height");
    t.incidence_deg = a.number(n, "incidenceAngle");
    t.elevation_deg = a.number(n, "elevationAngle");
    out.push_back(t);
  }
  return out;
}

}  // namespace ris
