#include "ris/image/category_palette.h"

#include <array>
#include <cmath>

namespace ris {

namespace {

// HSV (h in turns, s, v in [0, 1]) to 8-bit RGB.
Rgb8 from_hsv(double h, double s, double v) {
  const double h6 = (h - std::floor(h)) * 6.0;
  const int i = static_cast<int>(h6) % 6;
  const double f = h6 - std::floor(h6);
  const double p = v * (1.0 - s);
  const double q = v * (1.0 - s * f);
  const double t = v * (1.0 - s * (1.0 - f));
  double r = v, g = t, b = p;
  switch (i) {
    case 0:
      r = v, g = t, b = p;
      break;
    case 1:
      r = q, g = v, b = p;
      break;
    case 2:
      r = p, g = v, b = t;
      break;
    case 3:
      r = p, g = q, b = v;
      break;
    case 4:
      r = t, g = p, b = v;
      break;
    default:
      r = v, g = p, b = q;
      break;
  }
  auto byte = [](double x) { return static_cast<std::uint8_t>(std::lround(x * 255.0)); };
  return {byte(r), byte(g), byte(b)};
}

}  // namespace

Rgb8 category_colour(std::uint16_t category) {
  // The seed's ten crops, in its Figure 3 order: colours that suggest the
  // crop and stay distinct from their neighbours.
  static constexpr std::array<Rgb8, 11> kCrops{{
      {190, 190, 190},  // 0  unassigned / bare
      {214, 188, 128},  // 1  wheat stubble: straw
      {34, 112, 52},    // 2  tall alfalfa: dark green
      {140, 206, 110},  // 3  short alfalfa: light green
      {236, 214, 72},   // 4  short corn: yellow
      {214, 140, 30},   // 5  tall corn: amber
      {234, 150, 130},  // 6  short milo: salmon
      {160, 52, 44},    // 7  tall milo: brick red
      {150, 196, 234},  // 8  short soybeans: light blue
      {44, 92, 176},    // 9  tall soybeans: blue
      {52, 170, 156},   // 10 green wheat: teal
  }};
  if (category < kCrops.size()) return kCrops[category];
  // Golden-angle hue walk, alternating brightness, for every other id.
  const double h = std::fmod(0.1 + 0.6180339887498949 * category, 1.0);
  const double v = (category % 2 == 0) ? 0.85 : 0.65;
  return from_hsv(h, 0.6, v);
}

}  // namespace ris
