#include "ris/sim/slar_run_setup.h"

#include <tuple>

#include "ris/image/thermal_noise.h"

namespace ris {

void complete_slar_setup(SlarSimulation& sim, RadiometrySetup& rs, const Scene& grid) {
  sim.categories = rs.categories;
  sim.category_names = rs.category_names;
  sim.backscatter_description = rs.backscatter_description;
  // SAR: the multilooked resolution cell's windows, the warnings when it is
  // finer than the scene, and NESZ noise over it (MODEL.md section 3).
  set_sar_windows(sim.radar, sim.geometry.line_spacing_m, rs.imaging);
  sim.warnings = sar_resolution_warnings(grid, sim.geometry, sim.radar);
  sim.noise_power_w = sar_noise_power_w(sim.radar, rs.imaging, sim.geometry.altitude_m);
}

void finish_slar_image(SlarSimulation& sim, SlarImage& image, const SwitchedRadarTerms& terms) {
  std::tie(sim.range_corrected, sim.area_corrected) = apply_switch_corrections(image, terms);
  if (!sim.noise_power_w.empty()) add_noise_power(image, sim.noise_power_w);
}

}  // namespace ris
