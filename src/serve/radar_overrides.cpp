#include "ris/serve/radar_overrides.h"

#include <fmt/format.h>

#include <cmath>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

void set_near_range_depression(toml::table& doc, const RadarParams& radar, double depression_rad) {
  if (!(depression_rad > 0.0 && depression_rad < 0.5 * kPi)) {
    throw InputError("request body", "depression",
                     fmt::format("expected an angle between 0 and 90 deg, got {:.3f} deg",
                                 rad_to_deg(depression_rad)));
  }
  const double altitude_m = radar.track.altitude_m;
  const double near_m = altitude_m / std::sin(depression_rad);
  if (doc.contains("far_range")) {
    const double far_m = near_m + (radar.far_slant_range_m - radar.near_slant_range_m);
    doc.insert_or_assign("far_range", fmt::format("{:.6f} m", far_m));
  }
  doc.erase("sweep_delay");
  doc.insert_or_assign("near_range", fmt::format("{:.6f} m", near_m));
  toml::table* track = doc["track"].as_table();
  if (track != nullptr && track->contains("near_edge_distance")) {
    track->insert_or_assign("near_edge_distance",
                            fmt::format("{:.6f} m", altitude_m / std::tan(depression_rad)));
  }
}

void set_slant_swath(toml::table& doc, const RadarParams& radar, double swath_m) {
  if (!(swath_m > 0.0 && std::isfinite(swath_m))) {
    throw InputError("request body", "swath",
                     fmt::format("expected a positive length, got {} m", swath_m));
  }
  doc.erase("sweep_length");
  doc.erase("range_bins");
  doc.insert_or_assign("far_range", fmt::format("{:.6f} m", radar.near_slant_range_m + swath_m));
}

namespace {

bool same_switches_but_fading(const GreytoneSwitches& a, const GreytoneSwitches& b) {
  return a.transmit_power == b.transmit_power && a.wavelength == b.wavelength &&
         a.antenna_gain == b.antenna_gain && a.backscatter == b.backscatter && a.area == b.area &&
         a.range == b.range && a.film_k == b.film_k && a.receiver_m == b.receiver_m;
}

toml::table without_film(toml::table doc) {
  doc.erase("film");
  return doc;
}

}  // namespace

bool film_only_change(const toml::table& before_doc, const toml::table& after_doc,
                      const RadarParams& before, const RadarParams& after) {
  return without_film(before_doc) == without_film(after_doc) &&
         same_switches_but_fading(before.switches, after.switches);
}

}  // namespace ris
