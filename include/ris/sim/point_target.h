// Point scatterers added to a scene (corner reflectors, masts, vehicles): the
// seed's "hard (cultural) targets" (section 3.2.9), each a single scatterer
// of radar cross-section sigma (m^2) at a ground position and a height above
// the terrain. It returns P = P_t G^2 lambda^2 sigma / ((4 pi)^3 R^4) (the
// radar equation with sigma in place of sigma0 A), unless the terrain between
// it and the radar hides it (the cast-shadow test of MODEL.md section 2 at
// the target's own height).
//
// File format (TOML, docs/modes.md "Point targets"), passed with --targets:
//   [[target]]
//   name = "corner reflector 1"     # optional
//   position = [1200.0, 800.0]      # scene x, y (metres or "<n> ft")
//   height = "2 m"                  # above the terrain there (default 0)
//   rcs = 1000.0                    # m^2, or rcs_db = 30 (dBsm)
//
// Example:
//   std::vector<ris::PointTarget> t = ris::load_point_targets("targets.toml");
//   ris::check_point_targets_on_scene(t, scene);
//   std::vector<ris::PointReturn> r = ris::point_returns_on_lines(t, scene, geometry);
#pragma once

#include <array>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"

namespace ris {

struct PointTarget {
  std::string name;
  double x_m = 0.0, y_m = 0.0;  // scene coordinates
  double height_m = 0.0;        // above the terrain at (x, y)
  double rcs_m2 = 0.0;          // radar cross-section sigma
  std::string source_file;      // for messages
  int index = 0;                // position in its file ([[target]] number, from 0)
  // A scattering centre of a scene object (ris/sim/object_centres.h), not a
  // target of the user's: imaged alike, not measured (point_target_irf.h).
  bool from_object = false;
  // Its Sinclair matrix (HH, HV, VH, VV: receive-transmit; |S_pq|^2 in m^2)
  // for a quad-pol run (ris/sim/sar_quad_pol.h); none: a trihedral's,
  // sqrt(rcs) on the diagonal. A scene object's centre carries its traced S.
  std::optional<std::array<std::complex<double>, 4>> sinclair;
};

std::vector<PointTarget> load_point_targets(const std::string& path);
std::vector<PointTarget> point_targets_from_toml(const toml::table& doc,
                                                 const std::string& source_file);

// Throws InputError (file, "target[i].position") for a target outside the
// scene or on a no-data cell.
void check_point_targets_on_scene(const std::vector<PointTarget>& targets, const Scene& scene);

// The same checks and messages for one target, given the scene's grid and
// its terrain height there (NaN on no data), however it was read (in
// memory, or from the file by a streamed run).
void check_point_target_on_scene(const PointTarget& t, const Scene& grid, double terrain_height_m);

// The target's base: terrain height at (x, y) (bilinear), NaN off the scene.
double terrain_height_at(const Scene& scene, double x_m, double y_m);

// Whether a point at ground distance u_m and height h_m on geometry line
// `line` is lit: no sample of that line nearer than u has a larger
// t = u / (H - h) (MODEL.md section 2, "Cast shadow").
bool point_lit_on_line(const SlarGeometry& g, int line, double u_m, double h_m);
// The same test on samples [first, first + n) of the line (flags and
// heights of those samples; the samples outside are unseen): what the line
// engine holds of a line (ris/sim/slar_line_blocks.h). u is layout g's.
bool point_lit_on_samples(const SlarGeometry& g, int first, int n, const std::uint8_t* flags,
                          const float* height_m, double u_m, double h_m);

// A target placed on its line before the line's geometry is known: on a
// line of the layout, in front of the track (u > 0) and below the sensor.
// Whether the terrain hides it is decided on its line (point_lit_on_line or
// point_lit_on_samples).
struct PointCandidate {
  std::size_t target = 0;  // index in the targets
  PointReturn ret;         // line, along-track position, slant range, look angle, rcs
  double u_m = 0.0;        // ground distance across the track
  double h_m = 0.0;        // height above the datum
};
// Target `target` (rcs_m2) on line `line` at along-track position along_m (a
// ray's azimuth for a PPI), ground distance u_m across the track and height
// h_m, seen from altitude_m: its slant range and look angle.
PointCandidate point_candidate(std::size_t target, int line, double along_m, double u_m, double h_m,
                               double altitude_m, double rcs_m2);
// The candidates among the targets, in target order. g: the layout.
std::vector<PointCandidate> point_candidates(const std::vector<PointTarget>& targets,
                                             const Scene& scene, const SlarGeometry& g);
// The returns of the candidates found lit (lit[c] for candidates[c]), in
// target order; `hidden` (optional) receives the names of the others.
std::vector<PointReturn> seen_point_returns(const std::vector<PointTarget>& targets,
                                            const std::vector<PointCandidate>& candidates,
                                            const std::vector<std::uint8_t>& lit,
                                            std::vector<std::string>* hidden);

// The targets as seen from a SLAR/SAR track: line by along-track position,
// slant range from the zero-Doppler point. Targets beyond the track's ends,
// behind it (u <= 0) or in shadow are left out; `hidden` (optional) receives
// their names.
std::vector<PointReturn> point_returns_on_lines(const std::vector<PointTarget>& targets,
                                                const Scene& scene, const SlarGeometry& g,
                                                std::vector<std::string>* hidden = nullptr);

}  // namespace ris
