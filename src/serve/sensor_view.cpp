#include "ris/serve/sensor_view.h"

#include "ris/io/raster_io.h"
#include "ris/sensors_eo/eo_place.h"
#include "ris/sensors_eo/eo_preview.h"
#include "ris/sensors_eo/eo_render.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"

namespace ris {

std::vector<std::uint8_t> sensor_view_png(const Scene& scene, const std::string& library,
                                          const std::string& kind,
                                          std::optional<int> minute_of_day) {
  if (kind != "optical" && kind != "thermal") {
    throw InputError("request", "kind", "expected optical or thermal, got \"" + kind + "\"");
  }
  if (minute_of_day && (*minute_of_day < 0 || *minute_of_day >= 24 * 60)) {
    throw InputError(
        "request", "minute",
        "expected the UTC minute of the day, 0 to 1439, got " + std::to_string(*minute_of_day));
  }
  EoSensorConfig cfg = load_eo_sensor((data_dir() / "sensors_eo" / (kind + ".toml")).string());
  if (minute_of_day) cfg.when.hour = *minute_of_day / 60.0;
  const EoSurfaceTable table = load_eo_surface_table(eo_surface_table_for_library(library));
  const auto [lat, lon] = eo_place(scene, cfg, "the page's scene");
  const EoImage img = render_eo(scene, cfg, table, lat, lon);
  const EoPreview p = eo_preview(img.band_names, img.bands);
  return encode_png(p.pixels.data(), img.cols, img.rows, p.channels);
}

}  // namespace ris
