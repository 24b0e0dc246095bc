// Sharpness of an image across the edges of a mask (docs/quality.md): the
// seed's interpreters judged how crisply a radar shadow starts; here the
// 10-90% width of the mean intensity profile across every lit-to-shadow edge.
//
// Along each row (range), an edge is where the mask's bit turns on (lit ->
// shadow) or off (shadow -> lit, taken mirrored so that the lit side comes
// first). The intensity profiles over [-half, half) pixels around the edges
// (all pixels finite) are averaged; from the lit level L (mean of the profile
// over its first quarter) and the dark level D (its last quarter) the width
// is the distance between the points where the profile falls through
// D + 0.9 (L - D) and D + 0.1 (L - D), linear between pixel centres. An ideal
// step gives 0.8 pixels; blur widens it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace ris {

struct EdgeSharpness {
  int edges = 0;
  double width_px = 0.0;  // 10-90% width of the mean profile
  double lit_level = 0.0, dark_level = 0.0;
  std::vector<double> mean_profile;  // [-half, half)
};

// intensity, mask: rows x cols. Edges of (mask & bit). Throws InputError when
// no edge has a whole profile.
EdgeSharpness edge_sharpness(std::span<const float> intensity, std::span<const std::uint8_t> mask,
                             int cols, int rows, std::uint8_t bit, int half_px = 8);

}  // namespace ris
