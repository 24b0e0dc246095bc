// A picture of a scene for people: shaded relief blended with the category
// colours (category_palette.h), elevation contours, a legend (categories
// present with their share, elevation range, grid size), a scale bar and a
// north arrow; the seed's Appendix B figures 1-3 (relief, heights, category
// map) in one PNG.
//
// The map is drawn at one pixel per cell, averaged down in whole blocks for
// grids larger than max_map_px and enlarged by whole pixels for small ones.
// The file is written atomically.
//
// Example:
//   ris::ScenePreviewOptions opt;
//   opt.title = "ku-geometric";
//   ris::write_scene_preview(scene, "out/scene-preview.png", opt);
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "ris/scene/scene.h"

namespace ris {

struct ScenePreviewOptions {
  std::string title;                                    // top of the legend
  std::map<std::uint16_t, std::string> category_names;  // legend labels; ids if absent
  int max_map_px = 1000;  // the map's longer side at most this many pixels
  int min_map_px = 400;   // small grids are enlarged (whole pixels) up to this
  // Light from west-north-west rather than the cartographers' 315 deg, so the
  // four faces of an axis-aligned pyramid all shade differently.
  double light_azimuth_deg = 300.0;
  double light_altitude_deg = 45.0;
  // Elevation contours (darkened cells where the elevation crosses a
  // multiple of the interval), the seed's figure 2 heights in the same
  // picture. 0: automatic (a 1-2-5 interval giving at most 10 levels over
  // the scene's range); < 0: none.
  double contour_interval_m = 0.0;
};

// The contour interval actually drawn for a scene with this elevation
// range: opt.contour_interval_m when > 0, the automatic choice when 0, and 0
// (no contours) when < 0 or the scene is flat.
double preview_contour_interval_m(const ScenePreviewOptions& opt, double min_elevation_m,
                                  double max_elevation_m);

// The map alone as interleaved RGB (cols*rows*3), one pixel per cell: the
// category colour times the relief shading, normalised so flat ground keeps
// its category colour, with contours darkened.
std::vector<std::uint8_t> shaded_category_rgb(const Scene& scene, const ScenePreviewOptions& opt);

void write_scene_preview(const Scene& scene, const std::filesystem::path& path,
                         const ScenePreviewOptions& opt = {});

}  // namespace ris
