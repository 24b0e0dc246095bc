// The quad-pol coherent SAR (radar [sar] quad_pol = true; issue 33,
// docs/polarimetry.md "Simulated quad-pol images"): HH, HV, VH and VV
// single-look complex images over one geometry.
//
// Each visible ground element i (one per geometry sample, as the coherent SAR
// of ris/sim/sar_coherent.h) is a scatterer whose reciprocal scattering
// vector k_L = [S_HH, sqrt2 S_HV, S_VV] has the covariance C3_i of its
// category at its local incidence, scaled by its radar-equation factor:
//   C11 = P_HH,i, C22 = 2 P_HV,i, C33 = P_VV,i (the element powers the line
//   engine forms for each channel; channels over one geometry,
//   ris/sim/slar_channels.h), C13 = rho_c sqrt(C11 C33), C12 = C23 = 0
//   (reflection symmetry), rho_c and the shape from the category's model
//   family (ris/backscatter/category_covariance.h: default_polarimetry).
// k_i = L_i z_i with L_i L_i^H = C3_i (the Cholesky factor, in closed form
// for a reflection-symmetric C3) and z_i a unit complex Gaussian vector
// keyed by (seed, sample, line) (CounterRng stream kQuadPolStream), so the
// image never depends on thread count. Every channel is compressed through
// the same sinc impulse responses as the single-pol coherent SAR
// (sar_coherent_parts.h), so a pixel's expected covariance is the
// |h|^2-weighted sum of its elements' C3: the channels' correlation survives
// the compression exactly. HV and VH are one reciprocal image (S_HV = S_VH)
// plus independent thermal noise when the radar gives an NESZ.
//
// Point targets carry a Sinclair matrix: a scene object's scattering centre
// its traced S (ris/sim/object_centres.h), a user's target a trihedral's
// (S_HH = S_VV = sqrt(rcs), S_HV = 0: the usual calibrator), at phase 0 plus
// the two-way phase, scaled by the radar equation of its own position.
//
// Units: |z|^2 is the pixel's power in watts, as the single-pol coherent
// SAR's intensity (the range and area switches applied to the amplitude as
// sqrt of the intensity's factor); no-data pixels are NaN.
//
// Example:
//   std::vector<ris::SlarSimulation> s = ris::simulate_quad_pol_channels(scene, radar, *lib, o);
//   ris::QuadPolImages q = ris::form_quad_pol({&s[0], &s[1], &s[2]},
//                                             ris::scene_polarimetry(scene, *lib, radar),
//                                             o.targets, 42);
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <vector>

#include "ris/backscatter/category_covariance.h"
#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/point_target.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

// The four images' order, and their product suffixes.
inline constexpr std::array<Polarisation, 4> kQuadPolOrder = {Polarisation::HH, Polarisation::HV,
                                                              Polarisation::VH, Polarisation::VV};

struct QuadPolImages {
  int lines = 0, bins = 0;
  // S_HH, S_HV, S_VH, S_VV as imaged (kQuadPolOrder), lines x bins each.
  std::array<std::vector<std::complex<float>>, 4> slc;
  // |z|^2 of each (W), NaN for no data: the channels' pictures' input.
  std::array<std::vector<float>, 4> intensity;
};

// A category's shape in the per-element factor: the model family's
// (default_polarimetry), indexed by category id.
struct ElementPolarimetry {
  CovarianceShape shape = CovarianceShape::correlated;
  std::complex<double> rho_hhvv = 0.0;
};
using CategoryShapes = std::vector<ElementPolarimetry>;  // 65536 entries

// The shapes of the scene's categories in the radar's backscatter source at
// its frequency; InputError (the library, category and key) for a |rho| > 1.
CategoryShapes scene_polarimetry(const Scene& scene, const Sigma0Source& sigma0,
                                 const RadarParams& radar);

// L with L L^H = C3 of an element: C3 from its channel powers and its
// category's shape (lower triangle; L21 = L32 = 0 by reflection symmetry).
struct ElementFactor {
  double l11 = 0.0, l22 = 0.0, l33 = 0.0;
  std::complex<double> l31 = 0.0;
};
ElementFactor element_factor(double p_hh_w, double p_hv_w, double p_vv_w,
                             const ElementPolarimetry& shape);

// The radar of one channel of a quad-pol radar: the same radar, one
// polarisation, quad_pol off.
RadarParams quad_pol_channel(const RadarParams& radar, Polarisation polarisation);

// The HH, HV and VV channels over one geometry (simulate_slar_channels with
// polarimetric_channels), each keeping its element powers; options.targets
// are placed once. radar: sar.quad_pol.
std::vector<SlarSimulation> simulate_quad_pol_channels(const Scene& scene, const RadarParams& radar,
                                                       const Sigma0Source& sigma0,
                                                       const SlarOptions& options);

// What a quad-pol run keeps to form its images again (another seed): the
// categories' shapes, the run's point targets, and the images.
struct QuadPolRun {
  CategoryShapes shapes;
  std::vector<PointTarget> targets;
  QuadPolImages images;
};

// The four images from the three channels' simulations (HH, HV, VV in that
// order), the categories' shapes and the run's point targets (the returns in
// sims[0].point_returns index them).
QuadPolImages form_quad_pol(const std::array<const SlarSimulation*, 3>& hh_hv_vv,
                            const CategoryShapes& shapes, const std::vector<PointTarget>& targets,
                            std::uint64_t seed);

}  // namespace ris
