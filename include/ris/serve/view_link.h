// Linked zoom between the scene view and the slant view (docs/serve.md,
// "Linked views"): the region of one view that a region of the other shows,
// through the slant image's own (line, range) mapping, terrain heights
// included (geocode_pixel, ris/image/geocode.h, MODEL.md section 2: a cell at
// along-track s and cross-track u, height h, lies in line s / line spacing and
// in the bin of R = sqrt(u^2 + (H - h)^2)).
//
// From the scene (x: column, y: row): the bounding box of the (bin, line)
// pixels of the cells in the region (sampled on at most 65 x 65 cells). From
// the slant view (x: bin, y: line): the bounding box of the scene cells whose
// pixels fall in the region (the scene sampled on at most 257 x 257 cells, the
// box widened by the sampling step). Regions are in the view's pixels,
// fractional, [x0, x1) x [y0, y1).
//
// Example:
//   nlohmann::json r = ris::linked_region(result, "scene", 100, 50, 300, 200);
//   // {"view": "slant", "x0": bin0, "y0": line0, "x1": bin1, "y1": line1}
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "ris/sim/run.h"

namespace ris {

// InputError (source "request") for another view than "scene" or "slant", a
// PPI run, a region that is empty or not finite, or one that images nothing
// in the other view.
nlohmann::json linked_region(const RunResult& run, const std::string& from, double x0, double y0,
                             double x1, double y1);

}  // namespace ris
