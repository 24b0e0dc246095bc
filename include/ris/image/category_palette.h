// The category colours every ris picture uses (scene previews, legends,
// overlays), so one category has one colour everywhere.
//
// Ids 1..10 are the seed's ten crops (Figure 3 of its Appendix B: wheat
// stubble, tall alfalfa, short alfalfa, short corn, tall corn, short milo,
// tall milo, short soybeans, tall soybeans, green wheat) and 20..27 the
// generic land covers (bare soil, grass, forest, water, urban, road, rock,
// snow): they get the colours of the shipped category libraries
// (data/backscatter/*.toml). 0 is neutral grey; any other id gets a colour
// from a golden-angle walk round the hue circle, so it is stable and
// neighbouring ids differ. A picture made with a category library should
// prefer the library's colour (Sigma0Source::category_colour) and fall back
// to this one.
//
// Example:
//   ris::Rgb8 c = ris::category_colour(scene.category[i]);
#pragma once

#include <cstdint>

namespace ris {

struct Rgb8 {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
};

// Colour of no-data cells in pictures.
inline constexpr Rgb8 kNoDataColour{24, 24, 32};

Rgb8 category_colour(std::uint16_t category);

}  // namespace ris
