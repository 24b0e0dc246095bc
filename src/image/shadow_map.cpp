#include "ris/image/shadow_map.h"

namespace ris {

char shadow_map_char(int mapped, int visible) {
  if (mapped == 0) return '9';
  if (visible == 0) return '0';
  if (visible > 8) return '#';
  return static_cast<char>('0' + visible);
}

std::string shadow_map_text(const SlarImage& image) {
  std::string text;
  text.reserve(static_cast<std::size_t>(image.lines) * static_cast<std::size_t>(image.bins + 1));
  for (int line = 0; line < image.lines; ++line) {
    for (int b = 0; b < image.bins; ++b) {
      const std::size_t i = image.index(line, b);
      text.push_back(shadow_map_char(image.mapped_count[i], image.visible_count[i]));
    }
    text.push_back('\n');
  }
  return text;
}

}  // namespace ris
