// Internal: the frame of an acquisition run, what it needs before any line
// is simulated. These are the radar grid's window over the DEM, the DEM's
// height range, the sensor height, and the line spacing on the ground at
// mid-window. The in-memory run (ris/sim/acquisition_simulation.h) builds its
// layout from it. A streamed run needs the same frame in its first pass
// (docs/scale.md), which is why it is a function of its own.
#pragma once

#include <cstddef>
#include <string>

#include "ris/geometry/topo.h"
#include "ris/sensor/acquisition.h"

namespace ris::detail {

struct AcquisitionFrame {
  GridWindow window;                         // lines x bins of the grid simulated
  float dem_min_m = 0.0F, dem_max_m = 0.0F;  // heights with data
  std::string dem_vertical_note;             // the whole DEM's (metadata.json)
  double sensor_height_m = 0.0;              // above the ellipsoid, mid-window
  double ground_azimuth_spacing_m = 0.0;     // line spacing on the terrain
};

struct HeightRange {
  float min_m, max_m;
};

// The lowest and highest DEM height with data. Throws InputError naming the
// DEM when none has data.
HeightRange dem_height_range(const EllipsoidalDem& dem);

// The frame: the whole grid (`full_grid`) or the window the DEM covers.
// Throws InputError naming the DEM when the window is empty.
AcquisitionFrame acquisition_frame(const Acquisition& acq, const EllipsoidalDem& dem,
                                   bool full_grid);
// The same from the file's grid and its summary (EllipsoidalDemFile: its
// heights are never all held).
AcquisitionFrame acquisition_frame(const Acquisition& acq, const EllipsoidalDem& grid,
                                   const EllipsoidalDemSummary& summary, bool full_grid);

// The in-memory run holds its layers and line profiles whole (about 90
// bytes a pixel, as ris topo's layers).
constexpr std::size_t kMaxInMemoryPixels = 50'000'000;

// The in-memory run holds its layers and line profiles whole: refuse a
// window of more than 50 M pixels (as ris topo), naming the acquisition and
// the option that chose the window.
void check_in_memory_window(const GridWindow& w, const std::string& acquisition_source,
                            bool full_grid);

}  // namespace ris::detail
