#include "ris/sensor/radar_json.h"

#include <cmath>

namespace ris {

namespace {
const char* pattern_name(ElevationPattern::Kind k) {
  switch (k) {
    case ElevationPattern::Kind::uniform:
      return "uniform";
    case ElevationPattern::Kind::sinc2:
      return "sinc2";
    case ElevationPattern::Kind::gaussian:
      return "gaussian";
    case ElevationPattern::Kind::table:
      return "table";
  }
  return "?";
}

nlohmann::json finish_common(nlohmann::json& j, const RadarParams& r);

// JSON has no NaN: an unresolved value is written as null.
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}
// The keys every mode shares, after the mode's own.
nlohmann::json finish_common(nlohmann::json& j, const RadarParams& r) {
  using nlohmann::json;
  j["speed_m_per_s"] = r.speed_m_per_s > 0.0 ? json(r.speed_m_per_s) : json(nullptr);
  j["prf_hz"] = r.prf_hz > 0.0 ? json(r.prf_hz) : json(nullptr);
  j["independent_samples"] =
      r.independent_samples ? json(*r.independent_samples) : json("seed equation 16");
  j["azimuth_line_spacing_m"] =
      r.azimuth_line_spacing_m > 0.0 ? json(r.azimuth_line_spacing_m) : json("one scene cell");
  const ReferenceCell& ref = r.reference;
  json reference = {{"auto", ref.automatic},
                    {"greytone", ref.automatic ? ref.auto_greytone : ref.greytone},
                    {"transmit_power_w", ref.transmit_power_w},
                    {"sigma0", number(ref.sigma0)},
                    {"area_m2", ref.area_m2},
                    {"gain", ref.gain},
                    {"wavelength_m", ref.wavelength_m},
                    {"range_m", ref.range_m}};
  if (ref.mean_power_w) reference["mean_power_w"] = *ref.mean_power_w;
  if (ref.sigma0_category) {
    reference["category"] = *ref.sigma0_category;
    reference["incidence_rad"] = ref.sigma0_incidence_rad;
  }
  j["reference"] = reference;
  const FilmParams& f = r.film;
  const GreytoneSwitches& s = r.switches;
  j["film"] = {{"density_range", f.density_range},
               {"gamma", f.gamma},
               {"k_reference", f.k1},
               {"k_simulated", f.k2},
               {"m_reference", f.m1},
               {"m_simulated", f.m2},
               {"fading", r.fading == FadingLaw::exact_gamma ? "exact" : "seed"},
               {"terms",
                {{"transmit_power", s.transmit_power},
                 {"wavelength", s.wavelength},
                 {"antenna_gain", s.antenna_gain},
                 {"backscatter", s.backscatter},
                 {"area", s.area},
                 {"range", s.range},
                 {"k", s.film_k},
                 {"m", s.receiver_m},
                 {"fading", s.fading}}}};
  return j;
}

}  // namespace

nlohmann::json radar_to_json(const RadarParams& r) {
  using nlohmann::json;
  json j;
  j["source_file"] = r.source_file;
  j["name"] = r.name;
  j["mode"] = r.mode == RadarMode::slar ? "slar" : (r.mode == RadarMode::sar ? "sar" : "ppi");
  j["frequency_hz"] = r.frequency_hz;
  j["wavelength_m"] = r.wavelength_m();
  j["polarisation"] = std::string(to_string(r.polarisation));
  j["pulse_width_s"] = r.pulse_width_s;
  j["near_slant_range_m"] = r.near_slant_range_m;
  j["far_slant_range_m"] = r.far_slant_range_m;
  j["range_bin_m"] = r.range_bin_m;
  j["range_bins"] = r.range_bins;
  j["azimuth_beamwidth_rad"] = r.azimuth_beamwidth_rad;
  j["transmit_power_w"] = r.transmit_power_w;
  j["peak_gain"] = r.peak_gain;
  const ElevationPattern& p = r.elevation_pattern;
  j["elevation_pattern"] = {{"shape", pattern_name(p.kind)},
                            {"beamwidth_rad", p.beamwidth_rad},
                            {"boresight_rad", p.boresight_rad},
                            {"table_look_rad", p.table_look_rad},
                            {"table_gain", p.table_gain}};
  if (r.mode == RadarMode::sar) {
    const SarParams& s = r.sar;
    j["sar"] = {
        {"bandwidth_hz", s.bandwidth_hz > 0.0 ? json(s.bandwidth_hz) : json(nullptr)},
        {"range_resolution_m", s.range_resolution_m},
        {"antenna_length_m", s.antenna_length_m > 0.0 ? json(s.antenna_length_m) : json(nullptr)},
        {"azimuth_resolution_m", s.azimuth_resolution_m},
        {"range_looks", s.range_looks},
        {"azimuth_looks", s.azimuth_looks},
        {"nesz", s.nesz ? json(*s.nesz) : json(nullptr)},
        {"nesz_db", s.nesz ? json(10.0 * std::log10(*s.nesz)) : json(nullptr)},
        {"coherent", s.coherent}};
  }
  if (r.mode == RadarMode::ppi) {
    const PpiParams& pp = r.ppi;
    json site = pp.site_latlon_deg
                    ? json{{"latlon_deg", {(*pp.site_latlon_deg)[0], (*pp.site_latlon_deg)[1]}}}
                    : json{{"position_m", {pp.site_x_m, pp.site_y_m}}};
    if (pp.altitude_m) site["altitude_m"] = *pp.altitude_m;
    if (pp.height_above_ground_m) site["height_above_ground_m"] = *pp.height_above_ground_m;
    j["site"] = site;
    j["scan"] = {
        {"start_rad", pp.scan_start_rad},
        {"width_rad", pp.scan_width_rad},
        {"ray_spacing_rad", pp.ray_spacing_rad},
        {"range_rings_m", pp.ring_spacing_m > 0.0 ? json(pp.ring_spacing_m) : json(nullptr)},
        {"pixel_m", pp.scope_pixel_m},
        {"presentation", pp.presentation == PpiPresentation::slant ? "slant" : "ground"}};
    j["altitude_m"] = r.track.altitude_m;
    return finish_common(j, r);
  }
  const TrackSpec& t = r.track;
  json track = {{"altitude_m", t.altitude_m},
                {"look_side", t.look_side == LookSide::right ? "right" : "left"}};
  if (t.kind == TrackSpec::Kind::endpoints) {
    track["start_m"] = {t.start_x_m, t.start_y_m};
    track["end_m"] = {t.end_x_m, t.end_y_m};
  } else {
    track["heading_rad"] = t.heading_rad;
    track["near_edge_distance_m"] = t.near_edge_ground_m;
  }
  j["track"] = track;
  // A multi-channel radar: each channel's own keys (a one-channel radar has
  // none, and its JSON is as it always was).
  if (!r.channels.empty()) {
    json channels = json::array();
    for (const RadarChannel& c : r.channels) {
      channels.push_back({{"name", c.name},
                          {"frequency_hz", c.radar->frequency_hz},
                          {"polarisation", std::string(to_string(c.radar->polarisation))},
                          {"transmit_power_w", c.radar->transmit_power_w},
                          {"peak_gain", c.radar->peak_gain},
                          {"backscatter", c.backscatter_path}});
    }
    j["channels"] = channels;
  }
  return finish_common(j, r);
}

nlohmann::json derived_to_json(const RadarDerived& d) {
  return {{"wavelength_m", d.wavelength_m},
          {"range_resolution_m", d.range_resolution_m},
          {"range_bin_m", d.range_bin_m},
          {"range_bins", d.range_bins},
          {"near_slant_range_m", d.near_slant_range_m},
          {"far_slant_range_m", d.far_slant_range_m},
          {"near_ground_range_m", d.near_ground_range_m},
          {"far_ground_range_m", d.far_ground_range_m},
          {"swath_ground_m", d.swath_ground_m},
          {"near_depression_rad", d.near_depression_rad},
          {"far_depression_rad", d.far_depression_rad},
          {"near_incidence_rad", d.near_incidence_rad},
          {"far_incidence_rad", d.far_incidence_rad},
          {"near_azimuth_footprint_m", d.near_azimuth_footprint_m},
          {"far_azimuth_footprint_m", d.far_azimuth_footprint_m},
          {"near_independent_samples_eq16", d.near_samples_eq16},
          {"far_independent_samples_eq16", d.far_samples_eq16},
          {"near_independent_samples", d.near_samples},
          {"far_independent_samples", d.far_samples},
          {"independent_samples_from_eq16", d.samples_from_eq16},
          {"near_pulses_per_footprint", d.near_pulses_per_footprint},
          {"far_pulses_per_footprint", d.far_pulses_per_footprint}};
}

}  // namespace ris
