#include "ris/sensors_eo/eo_preview.h"

#include <algorithm>
#include <cmath>

namespace ris {
namespace {

std::vector<std::uint8_t> stretch(const std::vector<float>& v) {
  std::vector<float> finite;
  for (float x : v) {
    if (std::isfinite(x)) finite.push_back(x);
  }
  std::vector<std::uint8_t> out(v.size(), 0);
  if (finite.empty()) return out;
  std::sort(finite.begin(), finite.end());
  const float lo = finite[finite.size() * 2 / 100];
  const float hi = finite[std::min(finite.size() - 1, finite.size() * 98 / 100)];
  const float span = hi > lo ? hi - lo : 1.0f;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::isfinite(v[i]))
      out[i] =
          static_cast<std::uint8_t>(std::clamp((v[i] - lo) / span, 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  return out;
}

}  // namespace

EoPreview eo_preview(const std::vector<std::string>& names,
                     const std::vector<std::vector<float>>& bands) {
  auto find = [&](const char* n) {
    const auto it = std::find(names.begin(), names.end(), n);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
  };
  const int r = find("red"), g = find("green"), b = find("blue");
  EoPreview p;
  if (r < 0 || g < 0 || b < 0) {
    p.pixels = stretch(bands[0]);
    return p;
  }
  const auto sr = stretch(bands[r]), sg = stretch(bands[g]), sb = stretch(bands[b]);
  p.channels = 3;
  p.pixels.resize(sr.size() * 3);
  for (std::size_t i = 0; i < sr.size(); ++i) {
    p.pixels[3 * i] = sr[i];
    p.pixels[3 * i + 1] = sg[i];
    p.pixels[3 * i + 2] = sb[i];
  }
  return p;
}

}  // namespace ris
