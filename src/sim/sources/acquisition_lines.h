// Internal: the line source (and radar-grid sink) of the line engine
// (sim/engine/slar_line_engine.h) for an acquisition's own radar grid
// (ris/sim/acquisition_simulation.h). Each engine line is one azimuth line
// of the grid's window: its terrain is the DEM's profile in the line's
// zero-Doppler plane (ris/geometry/terrain_profile.h, the profile ris topo's
// mask comes from), so every sample's zero-Doppler time is the line's. The
// source computes the samples' look geometry itself (kMakesGeometry), on the
// ellipsoid or on the flat Earth tangent at the line's nadir:
//
//   ellipsoid: R = |X - p|, look angle acos(n_p . l) from the geodetic nadir
//              n_p, local incidence acos(n . l) with n the DEM's facet
//              normal in the target's own east-north-up frame;
//   flat:      the target at ground distance u from the nadir (along the
//              ellipsoid) and height h, the sensor at its height H:
//              R = sqrt(u^2 + (H - h)^2), look angle atan2(u, H - h), the
//              facet normal taken in the nadir's frame (the flat-Earth model
//              of docs/model.md on the line's plane).
//
// Area of a sample: its ground length along the profile (half the distance
// to its neighbours) x the ground azimuth spacing |v| dt |X| / |p| x the
// slope factor sqrt(1 + (dh/dE)^2 + (dh/dN)^2) (the true area, as the
// flat engine's element |n|). Shadow and layover: the profile's scans on the
// model's look angle and slant range.
//
// The sink: per (line, bin) of the window, the local incidence of the sample
// nearest the bin's centre and the layover/shadow mask as ris topo makes it
// (layover when any of the bin's samples is, shadow when all are).
#pragma once

#include <cstdint>
#include <variant>
#include <vector>

#include "ris/geometry/terrain_profile.h"
#include "ris/geometry/topo.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/radar_params.h"
#include "sim/engine/slar_line_engine.h"

namespace ris::detail {

// What every thread's source reads, and the radar-grid layers it fills.
struct AcquisitionRun {
  const Acquisition& acq;
  const EllipsoidalDem& dem;
  GridWindow window;
  EarthModel earth = EarthModel::ellipsoid;
  std::uint16_t category = 0;
  // Land cover on the DEM's postings (rows x cols), or null: `category`.
  const std::uint16_t* dem_category = nullptr;
  double dem_min_m = 0.0, dem_max_m = 0.0;  // the DEM's height range
  int samples_per_bin = 3;                  // profile points per range bin
  std::size_t max_points = 0;               // the scratch's capacity
  const SlarGeometry* layout = nullptr;     // the engine's layout (capacity)
  // The radar-grid layers, lines [maps_line0, ...) x bins of the window:
  // the whole window in memory, a block's lines when streamed.
  float* local_incidence_deg = nullptr;
  std::uint8_t* mask = nullptr;  // TopoMask bits
  int maps_line0 = 0;

  // The category at a latitude/longitude (radians): the nearest posting's.
  std::uint16_t category_at(double lat_rad, double lon_rad) const;
  // The profile's ray look angles for a line and its point count: at least
  // the ground whose slant range can fall in the window's bins at some
  // height in [dem_min_m, dem_max_m], at most max_points (when set) and
  // kMaxItems points.
  ProfileSpan span_of_line(const ZeroDopplerFrame& f) const;
};

// The points a line's profile needs at most (the scratch's size): the
// span's count at the window's first, middle and last lines, plus a margin.
// InputError naming the DEM (what to check) when that count, or each
// thread's scratch for it, is more than ris allows (ris/util/resource_guard.h).
std::size_t acquisition_max_points(AcquisitionRun& run);

// A rectangle of postings of the DEM's file grid.
struct DemRect {
  int row0 = 0, rows = 0, col0 = 0, cols = 0;
};

// The postings lines [line0, line1) of the window read (a streamed block's
// DEM window): around every profile point's latitude/longitude (sampled
// along each line's span; the margin covers the gaps between samples, the
// slope's neighbours and the bilinear cell), on run.dem's file grid (its
// heights are not read). Empty when no line meets the ellipsoid.
DemRect dem_rect_of_lines(const AcquisitionRun& run, int line0, int line1);

// One line's terrain and look geometry into the engine's scratch.
struct AcquisitionLineSource {
  static constexpr bool kMakesGeometry = true;
  const AcquisitionRun& run;
  TerrainProfile& profile;
  std::vector<double>& look_rad;  // the model's look angle and range per point
  std::vector<double>& range_m;
  std::vector<double>& ground_u_m;
  std::vector<int>& bin_count;  // the sink's per-bin scratch
  std::vector<int>& bin_shadow;
  std::vector<int>& bin_layover;
  std::vector<float>& bin_best;

  LineSpan load(int line, LineScratch& s);
  void store_maps(int line, const LineSpan& span, const LineScratch& s);
  void finish_block() const {}
};

// One thread's scratch for the acquisition source.
struct AcquisitionThreadSource {
  const AcquisitionRun& run;
  TerrainProfile profile;
  std::vector<double> look_rad, range_m, ground_u_m;
  std::vector<int> bin_count, bin_shadow, bin_layover;
  std::vector<float> bin_best;

  std::variant<AcquisitionLineSource> block(int, int) {
    return AcquisitionLineSource{run,       profile,    look_rad,    range_m, ground_u_m,
                                 bin_count, bin_shadow, bin_layover, bin_best};
  }
};

// Where trace_terrain_profile puts the ground at ray look angle th and
// height h: the ray met on the ellipsoid raised to h_ref (the profile's
// reference), then moved along that surface's normal to h (out). False when
// the ray misses it.
bool ground_at(const ZeroDopplerFrame& f, const Ellipsoid& e, double h_ref, double th, double h,
               Vec3& out);

// The profile's ray look angle (from the geodetic nadir) of the ground at
// height h and slant range r (bisection); 0 when r is shorter than the
// range straight down to h.
double ray_look_of_range(const ZeroDopplerFrame& f, const Ellipsoid& e, double h_ref, double h,
                         double r);

}  // namespace ris::detail
