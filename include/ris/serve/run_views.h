// What the page shows of one run, drawn from the kept RunResult: the
// pictures as PNG bytes, the mask overlays, the seed's shadow map text, the
// greytone histogram and the sigma0 curves of the scene's categories.
//
// Views (names in the URLs, docs/serve.md):
//   slant     greytones in slant range (SLAR, SAR: azimuth lines x range
//             bins, track start at the top; PPI: the scope)
//   ground    greytones in ground range (PPI: the B-scope, rays x bins)
//   geocoded  the slant greytones on the scene grid (SLAR, SAR)
//   scene     the scene: category colours over relief, one pixel per cell
//
// Example:
//   std::vector<std::uint8_t> png = ris::view_png(result, "slant");
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/backscatter/sigma0_source.h"
#include "ris/sim/run.h"

namespace ris {

// Greytone (or RGB) pixels of a view, before PNG encoding.
struct ViewPixels {
  int cols = 0;
  int rows = 0;
  int channels = 1;
  std::vector<std::uint8_t> data;
};

// Throws InputError (source "request", key "view") for an unknown view or
// one the run's mode does not have.
ViewPixels view_pixels(const RunResult& run, const std::string& view);
std::vector<std::uint8_t> view_png(const RunResult& run, const std::string& view);

// An RGBA overlay of the masks named in `masks` (comma-separated: shadow,
// layover, backfacing, nodata) on a view's grid: "slant" (the image's pixel
// flags; no back-facing there) or "scene" and "geocoded" (the scene-grid
// flags). Unflagged pixels are transparent.
std::vector<std::uint8_t> overlay_png(const RunResult& run, const std::string& view,
                                      const std::string& masks);

// The seed's shadow map (ris/image/shadow_map.h) of a SLAR or SAR run.
std::string shadow_map(const RunResult& run);

// Counts of each greytone 0..255 over the slant image's pixels with data.
nlohmann::json greytone_histogram(const RunResult& run);

// sigma0 in dB of each category the run used, at local incidence 0..89 deg
// (1 deg steps), at the run's band.
// The page's map furniture for a run: the category legend (every category
// the run's scene uses, with the colour its scene picture paints it,
// ris/image/category_palette.h, and the library's name), the overlay key
// (each mask's RGBA in overlay_png) and the geometry the page draws scale
// bars and orientation labels from (cell size, slant bin and line spacing,
// heading of the track, look side).
nlohmann::json map_furniture(const RunResult& run, const Sigma0Source& sigma0);

nlohmann::json sigma0_curves(const RunResult& run, const Sigma0Source& sigma0);

}  // namespace ris
