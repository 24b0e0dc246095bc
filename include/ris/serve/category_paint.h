// Painting categories on a scene grid from the page (the seed's interactive
// database building, TR 319 section 3.2.1): a brush stroke (cells within a
// radius of any of its centres) or a polygon (cells whose centre is inside).
// Coordinates are grid columns and rows, fractional; cell (r, c) has its
// centre at (c + 0.5, r + 0.5). Cells without data stay as they are.
//
// Example:
//   ris::PaintStroke s = ris::parse_paint_stroke(body_table);  // {"category": 3, "polygon": [...]}
//   std::size_t n = ris::paint_categories(scene, s);
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <toml++/toml.h>

#include "ris/scene/scene.h"

namespace ris {

struct PaintStroke {
  std::uint16_t category = 0;
  std::vector<std::array<double, 2>> polygon;        // [col, row] vertices, >= 3 when given
  std::vector<std::array<double, 2>> brush_centres;  // [col, row]
  double brush_radius_cells = 1.0;
};

// Keys: category (0..65534), and polygon = [[col, row], ...] or brush =
// [[col, row], ...] with radius (cells, default 1). Throws InputError
// (source "request body") naming the key.
PaintStroke parse_paint_stroke(const toml::table& body);

// Sets the category of every cell with data the stroke covers; returns how
// many cells it covered.
std::size_t paint_categories(Scene& scene, const PaintStroke& stroke);

}  // namespace ris
