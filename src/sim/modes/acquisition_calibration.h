// The radiometric calibration of an acquisition run's image
// (ris/image/radiometric_calibration.h) on its own geometry: per range bin
// of the window, the reference surface (the ellipsoid raised to the
// ground-range reference height, or the flat Earth with --earth flat) seen
// from the window's middle line, as the lines' elements are (the gain at
// the angle from the sensor's geodetic nadir, the incidence to the
// surface's normal, the azimuth cell as the lines' ground spacing there).
// One line stands for the window: the sensor's height and the ground
// spacing change by parts in 10^4 along an image's few seconds (measured in
// the tests as the calibration's error).
#pragma once

#include "ris/image/radiometric_calibration.h"
#include "ris/sim/acquisition_simulation.h"
#include "sim/sources/acquisition_lines.h"

namespace ris::detail {

SlantCalibration acquisition_calibration(const AcquisitionRun& run, const SlarImagingParams& p,
                                         double line_spacing_m, double reference_height_m);

}  // namespace ris::detail
