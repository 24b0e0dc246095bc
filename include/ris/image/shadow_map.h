// The seed's text shadow map (TR 319 section 3.2; MODEL.md section 3):
// one row per azimuth line (a scene line along track when the line spacing
// is one cell), track start first; one character per slant-range bin, near
// range first:
//   '9'      no data: no scene point with data maps into the bin
//   '0'      shadow: scene points map but none is visible (shadowed or
//            facing away)
//   '1'..'8' the number of that line's visible points summed into the bin
//   '#'      more than 8
// A point maps to the bin holding the slant range of its centre. Layover
// shows as counts above the flat-terrain count.
//
// Example:
//   std::string text = ris::shadow_map_text(img);  // rows end with '\n'
#pragma once

#include <string>

#include "ris/image/slar_image.h"

namespace ris {

char shadow_map_char(int mapped, int visible);
std::string shadow_map_text(const SlarImage& image);

}  // namespace ris
