// The stages every SLAR / SAR run shares around image formation, whatever
// its line source or sink (in memory: ris/sim/slar_simulation.h; streamed:
// ris/sim/slar_stream.h): before the lines, the radiometric set-up completed
// for the layout (SAR windows, resolution warnings, thermal noise), and
// after them, each block of image lines finished (switch corrections,
// noise). One copy, so the drivers cannot drift apart.
//
// Example:
//   ris::RadiometrySetup rs = ris::prepare_radiometry(scene, sim.radar, sim.derived, sigma0, file);
//   ris::complete_slar_setup(sim, rs, scene);   // sim.geometry: the layout
//   ... form the image lines ...
//   ris::finish_slar_image(sim, image, rs.terms);
#pragma once

#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

// Records the set-up's categories and backscatter description in sim, sets
// the SAR windows in rs.imaging (for sim.geometry's line spacing), sim's
// resolution warnings and thermal noise per bin. grid: the scene's grid.
void complete_slar_setup(SlarSimulation& sim, RadiometrySetup& rs, const Scene& grid);

// Image lines after image formation (the whole image, or a block of lines
// of it): the range and area switch corrections (recorded in sim) and the
// thermal noise power of sim.noise_power_w.
void finish_slar_image(SlarSimulation& sim, SlarImage& image, const SwitchedRadarTerms& terms);

}  // namespace ris
