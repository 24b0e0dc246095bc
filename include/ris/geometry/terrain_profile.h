// The terrain of one radar line on the curved Earth: a dense profile of DEM
// points in the line's zero-Doppler plane, in ground order from near to far,
// with the cast shadow and layover along it (docs/geometry.md). Shared by
// `ris topo`'s radar pass (its layover/shadow mask) and the acquisition line
// source of the simulation engine (its samples).
//
// Points sit at evenly spaced look angles: each where the ray meets the
// ellipsoid raised to a reference height (ZeroDopplerFrame::
// range_to_ellipsoid), then moved onto the DEM along that surface's normal.
// A point is in shadow when a nearer point is seen at a larger look angle; in
// layover when a nearer point is at a longer slant range or a farther one at
// a shorter (the two scans of SNAP's layover/shadow operator).
//
// Example:
//   ris::TerrainProfile p;
//   ris::trace_terrain_profile(frame, e, dem, {lo_rad, hi_rad, 3000, 240.0}, true, p);
//   ris::mark_shadow_layover(p.points(), p.look_rad.data(), p.range_m.data(), p.flags.data());
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "ris/geometry/zero_doppler.h"
#include "ris/io/ellipsoidal_dem.h"

namespace ris {

enum TopoMask : std::uint8_t { kMaskNone = 0, kMaskShadow = 1, kMaskLayover = 2 };

// Which part of the zero-Doppler plane to trace.
struct ProfileSpan {
  double look_lo_rad = 0.0, look_hi_rad = 0.0;  // ray look angles from the geodetic nadir
  std::size_t points = 0;                       // >= 2, evenly spaced in look angle
  double height_ref_m = 0.0;                    // the raised ellipsoid's height
};

struct TerrainProfile {
  // Per point: the look angle and slant range of the ground point from the
  // sensor (NaN off the DEM) and its TopoMask bits.
  std::vector<double> look_rad, range_m;
  std::vector<std::uint8_t> flags;
  // Kept on request: the ground point (ECEF) and its latitude, longitude and
  // ellipsoidal height (NaN off the DEM).
  std::vector<Vec3> ground_m;
  std::vector<double> lat_rad, lon_rad, height_m;
  std::size_t points() const { return look_rad.size(); }
};

// Traces the profile (flags cleared; mark_shadow_layover sets them). Reuses
// `out`'s storage: no allocation once it has grown to span.points.
void trace_terrain_profile(const ZeroDopplerFrame& f, const Ellipsoid& e, const EllipsoidalDem& dem,
                           const ProfileSpan& span, bool keep_points, TerrainProfile& out);

// Cast shadow and layover along points in ground order (NaN ranges skipped):
// adds kMaskShadow and kMaskLayover to flags.
void mark_shadow_layover(std::size_t n, const double* look_rad, const double* range_m,
                         std::uint8_t* flags);

// The DEM's slope at a point, dh/dE and dh/dN (metres per metre) in the
// local east-north-up frame: central differences one posting either side
// (one-sided next to the DEM's edge or no data; 0 with neither).
struct DemSlope {
  double east = 0.0, north = 0.0;
};
DemSlope dem_slope(const EllipsoidalDem& dem, const Ellipsoid& e, double lat_rad, double lon_rad,
                   double height_m);

// The DEM's unit surface normal (ECEF) from its slope:
// n = (-dh/dE, -dh/dN, 1) / |...| in the local ENU frame.
Vec3 dem_normal(const EllipsoidalDem& dem, const Ellipsoid& e, double lat_rad, double lon_rad,
                double height_m);

}  // namespace ris
