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
  // The seed's ten crops (ids 1..10, its Figure 3 order) and the generic
  // land-cover ids 20..27: the same colours as the shipped category
  // libraries data/backscatter/ku-geometric.toml and generic-terrain.toml
  // (a test keeps them in step), so a picture made without a library
  // matches one made with it.
  static constexpr std::array<Rgb8, 28> kKnown{{
      {190, 190, 190},     // 0  unassigned: neutral grey
      {0xc8, 0xb4, 0x6e},  // 1  wheat stubble
      {0x1f, 0x7a, 0x3a},  // 2  tall alfalfa
      {0x6c, 0xc4, 0x6a},  // 3  short alfalfa
      {0xe8, 0xd0, 0x4a},  // 4  short corn
      {0xb0, 0x8a, 0x1a},  // 5  tall corn
      {0xe8, 0x9a, 0x5a},  // 6  short milo
      {0xa8, 0x44, 0x1c},  // 7  tall milo
      {0x9a, 0xc8, 0xe8},  // 8  short soybeans
      {0x2a, 0x6a, 0xb0},  // 9  tall soybeans
      {0x8e, 0xe0, 0x4a},  // 10 green wheat
      {},
      {},
      {},
      {},
      {},
      {},
      {},
      {},
      {},                  // 11..19: generated below
      {0xa0, 0x52, 0x2d},  // 20 bare soil
      {0x7c, 0xfc, 0x00},  // 21 grass
      {0x00, 0x64, 0x00},  // 22 forest
      {0x1e, 0x64, 0xc8},  // 23 water
      {0xb0, 0xb0, 0xb0},  // 24 urban
      {0x40, 0x40, 0x40},  // 25 road
      {0x8c, 0x8c, 0x78},  // 26 rock
      {0xf0, 0xf8, 0xff},  // 27 snow
  }};
  if (category <= 10 || (category >= 20 && category < kKnown.size())) return kKnown[category];
  // Golden-angle hue walk, alternating brightness, for every other id.
  const double h = std::fmod(0.1 + 0.6180339887498949 * category, 1.0);
  const double v = (category % 2 == 0) ? 0.85 : 0.65;
  return from_hsv(h, 0.6, v);
}

}  // namespace ris
