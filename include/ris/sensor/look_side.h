// Which side of its track a side-looking radar looks, for a scene run's
// track (ris/sensor/radar_params.h) and an acquisition's radar grid
// (ris/sensor/radar_grid.h) alike. The values are ISCE3's convention:
// left = +1, right = -1, the sign of the look direction relative to
// velocity x (-nadir) (ZeroDopplerFrame uses it as that sign).
#pragma once

namespace ris {

enum class LookSide : int { left = 1, right = -1 };

}  // namespace ris
