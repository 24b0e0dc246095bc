#include "ris/sensor/radar_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "ris/io/config_table.h"
#include "ris/sensor/geo_track.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

// A value that must be strictly positive and finite.
double positive(ConfigTable& t, const std::string& key, double v, const std::string& unit) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    t.fail(key, fmt::format("expected a positive value, got {} {}", v, unit));
  }
  return v;
}

double get_positive(ConfigTable& t, const std::string& key, Quantity q, const std::string& unit) {
  return positive(t, key, t.get_quantity(key, q), unit);
}

// Bounds past which a radar quantity is no radar's and its products would
// overflow or underflow (a 1e-300 Hz frequency gave an infinite wavelength,
// a 1e300 W transmitter infinite powers blamed on the `reference` key):
// each is refused at its own key. They are wide: every radar ris ships, and
// every real radar from HF over-the-horizon sets to sub-millimetre imagers,
// lies well inside them (docs/limits.md). The frequency's are narrower: the
// imaging radars ris models and its backscatter models' validity, P band
// (BIOMASS, 435 MHz) to W band (94 GHz), inside 100 MHz .. 100 GHz (issue
// 38: a plausibility check, so that `frequency = 8.6` is refused at its key
// and not by the backscatter library later).
struct Bounds {
  double lo, hi;
  const char* unit;
  const char* example;          // how the quantity is usually written
  Quantity quantity;            // for the units a message lists
  const char* range = nullptr;  // the bounds as a reader writes them (else lo .. hi unit)
  const char* why = "the range of any radar (and of what ris's products can hold)";
};
constexpr Bounds kFrequencyHz{1e8,
                              1e11,
                              "Hz",
                              "\"9.6 GHz\"",
                              Quantity::frequency,
                              "100 MHz .. 100 GHz",
                              "the band of the imaging radars ris simulates (P to W band)"};
constexpr Bounds kBandwidthHz{1.0, 1e12, "Hz", "\"150 MHz\"", Quantity::frequency};
constexpr Bounds kPulseWidthS{1e-12, 1.0, "s", "\"50 ns\"", Quantity::time};
constexpr Bounds kTransmitPowerW{1e-6, 1e10, "W", "\"2 kW\"", Quantity::power};
constexpr Bounds kGainDb{-30.0, 80.0, "dB", "35", Quantity::dimensionless};
// sigma0, gains and NESZ written in dB or linearly.
constexpr Bounds kLevelDb{-150.0, 150.0, "dB", "-20 (dB) or 0.01 (linear)",
                          Quantity::dimensionless};

double within(ConfigTable& t, const std::string& key, double v, const Bounds& b) {
  if (!(v >= b.lo && v <= b.hi)) {
    const std::string range = b.range != nullptr
                                  ? std::string(b.range)
                                  : fmt::format("{:g} .. {:g} {}", b.lo, b.hi, b.unit);
    // The units a string may carry, where the quantity has units.
    const std::string units =
        b.quantity == Quantity::dimensionless
            ? std::string()
            : fmt::format("; the units accepted: {}", accepted_units(b.quantity));
    t.fail(key, fmt::format("{:g} {} is outside {}, {}; a bare number is read in {}: is the "
                            "unit right (for example {}{})?",
                            v, b.unit, range, b.why, b.unit, b.example, units));
  }
  return v;
}

double get_within(ConfigTable& t, const std::string& key, Quantity q, const Bounds& b) {
  return within(t, key, get_positive(t, key, q, b.unit), b);
}

// At most one of the keys may be present; returns which one (or "").
std::string one_of(ConfigTable& t, std::initializer_list<const char*> keys, bool required) {
  std::string found;
  std::string all;
  for (const char* k : keys) {
    if (!all.empty()) all += ", ";
    all += k;
    if (!t.has(k)) continue;
    if (!found.empty()) {
      t.fail(k, fmt::format("give only one of {} (both {} and {} are set)", all, found, k));
    }
    found = k;
  }
  if (required && found.empty()) {
    throw InputError(t.file(), t.key_path(*keys.begin()),
                     fmt::format("missing: give one of {}", all));
  }
  return found;
}

// A number that may be written in dB ("<key>_db") or linearly ("<key>").
std::optional<double> linear_or_db(ConfigTable& t, const std::string& key) {
  const std::string db_key = key + "_db";
  const std::string which = one_of(t, {key.c_str(), db_key.c_str()}, false);
  if (which.empty()) return std::nullopt;
  if (which == key) {
    const double v = positive(t, key, t.get_double(key), "");
    within(t, key, 10.0 * std::log10(v), kLevelDb);
    return v;
  }
  const double db = t.get_double(db_key);
  if (!std::isfinite(db)) t.fail(db_key, "expected a finite number of dB");
  return std::pow(10.0, within(t, db_key, db, kLevelDb) / 10.0);
}

// An area: a bare number in m^2, or "<number> m2" / "<number> ft2".
double get_area_m2(ConfigTable& t, const std::string& key) {
  const toml::node* node = t.raw(key);
  if (node->is_integer() || node->is_floating_point()) {
    return positive(t, key, *node->value<double>(), "m2");
  }
  if (auto s = node->as_string()) {
    const std::string text = s->get();
    for (const auto& [unit, scale] :
         {std::pair{"m2", 1.0}, {"ft2", kFeetToMetres * kFeetToMetres}}) {
      const std::string u(unit);
      if (text.size() > u.size() && text.compare(text.size() - u.size(), u.size(), u) == 0) {
        try {
          const double v =
              parse_quantity(text.substr(0, text.size() - u.size()), Quantity::dimensionless);
          return positive(t, key, v * scale, "m2");
        } catch (const std::invalid_argument& e) {
          t.fail(key, e.what());
        }
      }
    }
  }
  t.fail(key, "expected an area: a number (m2) or \"<number> m2\" / \"<number> ft2\"");
}

void parse_track(ConfigTable& t, TrackSpec& spec) {
  spec.altitude_m = get_positive(t, "altitude", Quantity::length, "m");
  spec.look_side = t.get_enum_or<LookSide>(
      "look_side", {{"right", LookSide::right}, {"left", LookSide::left}}, LookSide::right);
  if (parse_geo_track(t, spec)) return;  // latitude/longitude: ris/sensor/geo_track.h
  const bool endpoints = t.has("start") || t.has("end");
  const bool heading = t.has("heading") || t.has("near_edge_distance");
  if (endpoints && heading) {
    t.fail("start",
           "give either start and end, or heading and near_edge_distance, not both kinds of track");
  }
  if (endpoints) {
    spec.kind = TrackSpec::Kind::endpoints;
    auto point = [&](const char* key) {
      std::vector<double> p = t.get_quantity_array(key, Quantity::length);
      if (p.size() != 2) t.fail(key, fmt::format("expected [x, y] (2 values), got {}", p.size()));
      return p;
    };
    const auto a = point("start");
    const auto b = point("end");
    spec.start_x_m = a[0];
    spec.start_y_m = a[1];
    spec.end_x_m = b[0];
    spec.end_y_m = b[1];
    if (a == b) t.fail("end", "track start and end coincide");
  } else {
    spec.kind = TrackSpec::Kind::heading_near_edge;
    spec.heading_rad = t.get_quantity_or("heading", Quantity::angle, 0.0);
    if (!std::isfinite(spec.heading_rad)) t.fail("heading", "expected a finite angle");
    spec.near_edge_ground_m = t.get_quantity("near_edge_distance", Quantity::length);
    if (!(spec.near_edge_ground_m >= 0.0)) {
      t.fail("near_edge_distance",
             fmt::format("expected a ground distance >= 0, got {} m", spec.near_edge_ground_m));
    }
  }
  t.finish();
}

// [sar]: resolutions from the bandwidth and antenna length (or given),
// looks, noise and the coherent switch.
void parse_sar(ConfigTable& t, RadarParams& r) {
  SarParams& p = r.sar;
  if (one_of(t, {"bandwidth", "range_resolution"}, true) == "bandwidth") {
    p.bandwidth_hz = get_within(t, "bandwidth", Quantity::frequency, kBandwidthHz);
    p.range_resolution_m = kSpeedOfLight_m_per_s / (2.0 * p.bandwidth_hz);  // c / (2B)
  } else {
    p.range_resolution_m = get_positive(t, "range_resolution", Quantity::length, "m");
  }
  if (t.has("antenna_length")) {
    p.antenna_length_m = get_positive(t, "antenna_length", Quantity::length, "m");
  }
  if (t.has("azimuth_resolution")) {
    p.azimuth_resolution_m = get_positive(t, "azimuth_resolution", Quantity::length, "m");
  } else if (p.antenna_length_m > 0.0) {
    p.azimuth_resolution_m = 0.5 * p.antenna_length_m;  // stripmap: L / 2
  } else {
    t.fail("antenna_length",
           "missing: give antenna_length (resolution L / 2) or "
           "azimuth_resolution");
  }
  const auto looks = [&](const char* key) {
    const std::int64_t n = t.get_int_or(key, 1);
    if (n < 1 || n > 1000) t.fail(key, fmt::format("expected 1 to 1000 looks, got {}", n));
    return static_cast<int>(n);
  };
  p.range_looks = looks("range_looks");
  p.azimuth_looks = looks("azimuth_looks");
  if (auto nesz = linear_or_db(t, "nesz")) p.nesz = *nesz;
  p.coherent = t.get_bool_or("coherent", false);
  // Quad-pol: single-look complex images of all four polarisations, as a
  // polarimetric SAR's SLC product (NISAR's quad-pol RSLC; multilooking is
  // the covariance's, ris polsar --window, not the SLC's).
  p.quad_pol = t.get_bool_or("quad_pol", false);
  if (p.quad_pol && !p.coherent) {
    t.fail("quad_pol", "a quad-pol SAR forms complex images: set coherent = true as well");
  }
  if (p.quad_pol && (p.range_looks != 1 || p.azimuth_looks != 1)) {
    t.fail("quad_pol",
           fmt::format("quad-pol SLCs are single-look, got range_looks = {} and azimuth_looks = "
                       "{}: set both to 1 (average the covariance with ris polsar --window "
                       "instead)",
                       p.range_looks, p.azimuth_looks));
  }
  t.finish();
}

// [site]: the radar's ground position and its antenna height.
void parse_site(ConfigTable& t, PpiParams& p) {
  if (one_of(t, {"position", "latlon"}, true) == "latlon") {
    p.site_latlon_deg = parse_lat_lon(t, "latlon");
  } else {
    std::vector<double> xy = t.get_quantity_array("position", Quantity::length);
    if (xy.size() != 2 || !std::isfinite(xy[0]) || !std::isfinite(xy[1])) {
      t.fail("position", "expected [x, y] in scene metres (2 finite values)");
    }
    p.site_x_m = xy[0];
    p.site_y_m = xy[1];
  }
  if (one_of(t, {"altitude", "height"}, true) == "altitude") {
    p.altitude_m = get_positive(t, "altitude", Quantity::length, "m");
  } else {
    p.height_above_ground_m = get_positive(t, "height", Quantity::length, "m");
  }
  t.finish();
}

// [scan]: sector, ray spacing and the scope's presentation.
void parse_scan(std::optional<ConfigTable>& t, RadarParams& r, const std::string& file) {
  PpiParams& p = r.ppi;
  const double half_beam = 0.5 * r.azimuth_beamwidth_rad;
  p.scan_width_rad = 2.0 * kPi;
  p.ray_spacing_rad = half_beam;
  if (t) {
    p.scan_start_rad = t->get_quantity_or("start", Quantity::angle, 0.0);
    if (!std::isfinite(p.scan_start_rad)) t->fail("start", "expected a finite angle");
    p.scan_width_rad = t->get_quantity_or("width", Quantity::angle, 2.0 * kPi);
    if (!(p.scan_width_rad > 0.0) || !(p.scan_width_rad <= 2.0 * kPi + 1e-9)) {
      t->fail("width", fmt::format("expected a scan sector wider than 0 and at most 360 deg, got "
                                   "{:.3f} deg",
                                   rad_to_deg(p.scan_width_rad)));
    }
    p.ray_spacing_rad = t->get_quantity_or("ray_spacing", Quantity::angle, half_beam);
    if (!(p.ray_spacing_rad > 0.0) || p.ray_spacing_rad > half_beam * (1.0 + 1e-9)) {
      t->fail("ray_spacing",
              fmt::format("expected a ray spacing above 0 and at most half the azimuth "
                          "beamwidth ({:.4f} deg), got {:.4f} deg",
                          rad_to_deg(half_beam), rad_to_deg(p.ray_spacing_rad)));
    }
    if (t->has("range_rings")) {
      p.ring_spacing_m = get_positive(*t, "range_rings", Quantity::length, "m");
    }
    if (t->has("pixel")) p.scope_pixel_m = get_positive(*t, "pixel", Quantity::length, "m");
    p.presentation = t->get_enum_or<PpiPresentation>(
        "presentation", {{"slant", PpiPresentation::slant}, {"ground", PpiPresentation::ground}},
        PpiPresentation::slant);
    t->finish();
  }
  if (p.scope_pixel_m <= 0.0) p.scope_pixel_m = r.range_bin_m;
  // A full circle is split into whole rays; a sector's rays cover it.
  // Counted in floating point and checked before the conversion: a 1e-7 deg
  // spacing is 3.6e9 rays, past int (once printed as -2147483648).
  const double ray_count = std::ceil(p.scan_width_rad / p.ray_spacing_rad - 1e-9);
  if (!(ray_count <= 2000000.0)) {
    throw InputError(file, "scan.ray_spacing",
                     fmt::format("{:.3g} rays over the scan: too many (at most 2,000,000); use a "
                                 "wider ray_spacing",
                                 ray_count));
  }
  const int rays = std::max(1, static_cast<int>(ray_count));
  p.ray_spacing_rad = p.scan_width_rad / rays;
}

void parse_pattern(ConfigTable& t, ElevationPattern& p, double default_boresight_rad) {
  using Kind = ElevationPattern::Kind;
  p.kind = t.get_enum_or<Kind>("shape",
                               {{"uniform", Kind::uniform},
                                {"sinc2", Kind::sinc2},
                                {"gaussian", Kind::gaussian},
                                {"table", Kind::table}},
                               Kind::uniform);
  if (p.kind == ElevationPattern::Kind::sinc2 || p.kind == ElevationPattern::Kind::gaussian) {
    p.beamwidth_rad = get_positive(t, "beamwidth", Quantity::angle, "rad");
    if (p.beamwidth_rad >= kPi) t.fail("beamwidth", "expected a beamwidth below 180 deg");
    p.boresight_rad = t.get_quantity_or("boresight", Quantity::angle, default_boresight_rad);
    if (!(p.boresight_rad >= 0.0 && p.boresight_rad <= kPi / 2)) {
      t.fail("boresight", "expected a look angle from nadir between 0 and 90 deg");
    }
  }
  if (p.kind == ElevationPattern::Kind::table) {
    p.table_look_rad = t.get_quantity_array("look_angles", Quantity::angle);
    const std::string which = one_of(t, {"gain", "gain_db"}, true);
    p.table_gain = t.get_double_array(which);
    if (which == "gain_db") {
      for (double& g : p.table_gain) g = std::pow(10.0, g / 10.0);
    }
    if (p.table_look_rad.size() < 2) t.fail("look_angles", "expected at least 2 angles");
    if (p.table_gain.size() != p.table_look_rad.size()) {
      t.fail(which, fmt::format("expected {} values (one per look angle), got {}",
                                p.table_look_rad.size(), p.table_gain.size()));
    }
    for (size_t i = 1; i < p.table_look_rad.size(); ++i) {
      if (!(p.table_look_rad[i] > p.table_look_rad[i - 1])) {
        t.fail("look_angles", fmt::format("angles must increase (entry {} does not)", i));
      }
    }
    for (double g : p.table_gain) {
      if (!(g >= 0.0) || !std::isfinite(g)) t.fail(which, "expected gains >= 0");
    }
  }
  t.finish();
}

void parse_film(ConfigTable& t, FilmParams& f, GreytoneSwitches& sw, FadingLaw& law) {
  f.density_range =
      positive(t, "density_range", t.get_double_or("density_range", f.density_range), "");
  f.gamma = positive(t, "gamma", t.get_double_or("gamma", f.gamma), "");
  f.k1 = positive(t, "k_reference", t.get_double_or("k_reference", f.k1), "");
  f.k2 = positive(t, "k_simulated", t.get_double_or("k_simulated", f.k2), "");
  f.m1 = positive(t, "m_reference", t.get_double_or("m_reference", f.m1), "");
  f.m2 = positive(t, "m_simulated", t.get_double_or("m_simulated", f.m2), "");
  law = t.get_enum_or<FadingLaw>(
      "fading", {{"exact", FadingLaw::exact_gamma}, {"seed", FadingLaw::seed_eq21}},
      FadingLaw::exact_gamma);
  if (auto terms = t.subtable("terms")) {
    sw.transmit_power = terms->get_bool_or("transmit_power", true);
    sw.wavelength = terms->get_bool_or("wavelength", true);
    sw.antenna_gain = terms->get_bool_or("antenna_gain", true);
    sw.backscatter = terms->get_bool_or("backscatter", true);
    sw.area = terms->get_bool_or("area", true);
    sw.range = terms->get_bool_or("range", true);
    sw.film_k = terms->get_bool_or("k", true);
    sw.receiver_m = terms->get_bool_or("m", true);
    sw.fading = terms->get_bool_or("fading", true);
    terms->finish();
  }
  t.finish();
}

// Fills the reference cell; factors not given take this radar's own values at
// mid-swath over flat ground (so that their ratio is one when switched off).
void parse_reference(std::optional<ConfigTable>& t, const RadarParams& r, ReferenceCell& ref) {
  const double h_m = r.track.altitude_m;
  const double mid_r_m = 0.5 * (r.near_slant_range_m + r.far_slant_range_m);
  const double cos_theta = std::min(1.0, h_m / mid_r_m);
  const double sin_theta = std::sqrt(std::max(0.0, 1.0 - cos_theta * cos_theta));
  // Defaults: transmit power, wavelength and boresight gain of this radar; the
  // mid-swath slant range; the flat-ground resolution cell there,
  // dA = (R phi) (dr / sin theta) (seed equation 2 with theta_A = theta_c = 0).
  ref.transmit_power_w = r.transmit_power_w;
  ref.wavelength_m = r.wavelength_m();
  ref.gain = r.peak_gain;
  ref.range_m = mid_r_m;
  // SAR: the multilooked resolution cell rho_a L_a x rho_r L_r instead.
  const double az_m = r.mode == RadarMode::sar ? r.sar.azimuth_resolution_looks_m()
                                               : mid_r_m * r.azimuth_beamwidth_rad;
  const double rg_m = r.mode == RadarMode::sar ? r.sar.range_resolution_looks_m() : r.range_bin_m;
  ref.area_m2 = az_m * rg_m / std::max(sin_theta, 1e-6);
  ref.sigma0 = 1.0;
  ref.automatic = true;
  ref.greytone = ref.auto_greytone = 128.0;
  if (!t) return;

  ref.automatic = t->get_bool_or("auto", true);
  ref.greytone = t->get_double_or("greytone", 128.0);
  if (!(ref.greytone >= 0.0 && ref.greytone <= 255.0)) {
    t->fail("greytone", fmt::format("expected a greytone in [0, 255], got {}", ref.greytone));
  }
  ref.auto_greytone = ref.greytone;
  if (t->has("mean_power")) {
    ref.mean_power_w = get_positive(*t, "mean_power", Quantity::power, "W");
  }
  if (t->has("transmit_power")) {
    ref.transmit_power_w = get_positive(*t, "transmit_power", Quantity::power, "W");
  }
  const std::string s0 = one_of(*t, {"sigma0", "sigma0_db", "category"}, false);
  if (s0 == "category") {
    const std::int64_t c = t->get_int("category");
    if (c < 0 || c > 0xFFFE) t->fail("category", "expected a category id in 0..65534");
    ref.sigma0_category = static_cast<std::uint16_t>(c);
    ref.sigma0 = std::numeric_limits<double>::quiet_NaN();  // resolve_reference_sigma0()
    ref.sigma0_incidence_rad = t->get_quantity("incidence", Quantity::angle);
    if (!(ref.sigma0_incidence_rad >= 0.0 && ref.sigma0_incidence_rad <= kPi / 2)) {
      t->fail("incidence", "expected a local incidence angle between 0 and 90 deg");
    }
  } else if (!s0.empty()) {
    ref.sigma0 = *linear_or_db(*t, "sigma0");
  } else if (t->has("incidence")) {
    t->fail("incidence", "incidence is used only with category");
  }
  if (t->has("area")) ref.area_m2 = get_area_m2(*t, "area");
  if (auto g = linear_or_db(*t, "gain")) ref.gain = *g;
  const std::string wl = one_of(*t, {"wavelength", "frequency"}, false);
  ref.wavelength_given = !wl.empty();
  if (wl == "wavelength") ref.wavelength_m = get_positive(*t, "wavelength", Quantity::length, "m");
  if (wl == "frequency") {
    ref.wavelength_m =
        kSpeedOfLight_m_per_s / get_positive(*t, "frequency", Quantity::frequency, "Hz");
  }
  if (t->has("range")) ref.range_m = get_positive(*t, "range", Quantity::length, "m");
  if (!ref.automatic && !ref.mean_power_w && s0.empty()) {
    t->fail("sigma0",
            "an explicit reference (auto = false) needs mean_power, or sigma0 / sigma0_db / "
            "category + incidence");
  }
  if (ref.automatic && ref.mean_power_w) {
    t->fail("mean_power", "mean_power is an explicit reference: set auto = false");
  }
  t->finish();
}

}  // namespace

// The slant-range window: near and far range and the number of whole bins
// (r.range_bin_m set before).
void parse_range_window(ConfigTable& t, RadarParams& r) {
  const bool ppi = r.mode == RadarMode::ppi;
  // Near range: R_near = c t_delay / 2 (MODEL.md section 2), or given.
  // A PPI sweep may start at zero range (a ground radar sees from its mast).
  const auto non_negative = [&](const char* key, Quantity q) {
    const double v = t.get_quantity(key, q);
    if (!(v >= 0.0) || !std::isfinite(v))
      t.fail(key, fmt::format("expected a value >= 0, got {}", v));
    return v;
  };
  if (one_of(t, {"sweep_delay", "near_range"}, true) == "sweep_delay") {
    r.near_slant_range_m = kSpeedOfLight_m_per_s *
                           (ppi ? non_negative("sweep_delay", Quantity::time)
                                : get_positive(t, "sweep_delay", Quantity::time, "s")) /
                           2.0;
  } else {
    r.near_slant_range_m = ppi ? non_negative("near_range", Quantity::length)
                               : get_positive(t, "near_range", Quantity::length, "m");
  }
  // Far range: R_far = R_near + c t_sweep / 2, or given, or a number of bins.
  const std::string far_key = one_of(t, {"sweep_length", "far_range", "range_bins"}, true);
  if (far_key == "range_bins") {
    const std::int64_t n = t.get_int("range_bins");
    if (n < 1 || n > 1000000) {
      t.fail("range_bins", fmt::format("expected 1 to 1000000 range bins, got {}", n));
    }
    r.range_bins = static_cast<int>(n);
    r.far_slant_range_m = r.near_slant_range_m + static_cast<double>(n) * r.range_bin_m;
  } else {
    if (far_key == "sweep_length") {
      r.far_slant_range_m =
          r.near_slant_range_m +
          kSpeedOfLight_m_per_s * t.get_quantity("sweep_length", Quantity::time) / 2.0;
    } else {
      r.far_slant_range_m = t.get_quantity("far_range", Quantity::length);
    }
    if (!(r.far_slant_range_m > r.near_slant_range_m)) {
      t.fail(far_key, fmt::format("near range ({:.1f} m) is beyond far range ({:.1f} m)",
                                  r.near_slant_range_m, r.far_slant_range_m));
    }
    // Whole bins only, as the seed's GROUND(13) = RADAR(7) / RADAR(8); the
    // 1e-9 guards against a sweep that is an exact multiple of the bin.
    const double bins =
        std::floor((r.far_slant_range_m - r.near_slant_range_m) / r.range_bin_m + 1e-9);
    if (bins < 1.0) {
      t.fail(far_key, fmt::format("the swath ({:.1f} m of slant range) is shorter than one range "
                                  "bin ({:.1f} m)",
                                  r.far_slant_range_m - r.near_slant_range_m, r.range_bin_m));
    }
    if (bins > 1e6) t.fail(far_key, "more than 1000000 range bins");
    r.range_bins = static_cast<int>(bins);
  }
}

namespace {

// A radar file without [[channel]] tables (or one channel's view of one).
RadarParams single_radar_from_toml(const toml::table& doc, const std::string& source_file) {
  ConfigTable t(doc, source_file, "");
  RadarParams r;
  r.source_file = source_file;
  r.name = t.get_string_or("name", "");

  r.mode = t.get_enum<RadarMode>(
      "mode", {{"slar", RadarMode::slar}, {"sar", RadarMode::sar}, {"ppi", RadarMode::ppi}});
  const bool sar = r.mode == RadarMode::sar;
  const bool ppi = r.mode == RadarMode::ppi;
  if (t.has("earth")) {
    r.earth = t.get_enum<EarthModel>(
        "earth", {{"flat", EarthModel::flat}, {"ellipsoid", EarthModel::ellipsoid}});
  }

  r.frequency_hz = get_within(t, "frequency", Quantity::frequency, kFrequencyHz);
  try {
    r.polarisation = parse_polarisation(t.get_string("polarisation"));
  } catch (const std::invalid_argument& e) {
    t.fail("polarisation", e.what());
  }
  // SAR: the range resolution comes from the chirp bandwidth, so the pulse
  // width is optional; the [sar] table is read first for the default bin.
  if (sar) {
    if (t.has("pulse_width"))
      r.pulse_width_s = get_within(t, "pulse_width", Quantity::time, kPulseWidthS);
    auto st = t.subtable("sar");
    if (!st) t.fail("sar", "mode = \"sar\" needs a [sar] table (bandwidth, antenna_length, ...)");
    parse_sar(*st, r);
  } else {
    if (t.has("sar")) t.fail("sar", "a [sar] table needs mode = \"sar\"");
    r.pulse_width_s = get_within(t, "pulse_width", Quantity::time, kPulseWidthS);
  }
  const double default_bin_m =
      sar ? r.sar.range_resolution_m : kSpeedOfLight_m_per_s * r.pulse_width_s / 2.0;
  r.range_bin_m = t.get_quantity_or("range_bin", Quantity::length, default_bin_m);
  positive(t, "range_bin", r.range_bin_m, "m");

  parse_range_window(t, r);

  // SAR: the real antenna's beamwidth defaults to lambda / L (lambda / (2
  // rho_a) when only the resolution is given); it sets the elevation-free
  // reference cell only, never the SAR's azimuth resolution.
  if (sar && !t.has("azimuth_beamwidth")) {
    const double length_m =
        r.sar.antenna_length_m > 0.0 ? r.sar.antenna_length_m : 2.0 * r.sar.azimuth_resolution_m;
    r.beamwidth_antenna_length_m = length_m;  // followed by radar_at_band
    r.azimuth_beamwidth_rad = r.wavelength_m() / length_m;
  } else {
    r.azimuth_beamwidth_rad = get_positive(t, "azimuth_beamwidth", Quantity::angle, "rad");
  }
  if (r.azimuth_beamwidth_rad >= kPi) {
    t.fail("azimuth_beamwidth", "expected a beamwidth below 180 deg");
  }
  r.transmit_power_w =
      within(t, "transmit_power",
             positive(t, "transmit_power",
                      t.get_quantity_or("transmit_power", Quantity::power, 1000.0), "W"),
             kTransmitPowerW);
  const double gain_db = t.get_double_or("antenna_gain_db", 0.0);
  if (!std::isfinite(gain_db)) t.fail("antenna_gain_db", "expected a finite number of dB");
  within(t, "antenna_gain_db", gain_db, kGainDb);
  r.peak_gain = std::pow(10.0, gain_db / 10.0);

  // Track (with altitude and look side); PPI: the site and the scan.
  if (ppi) {
    if (t.has("track")) t.fail("track", "a PPI radar has [site] and [scan], not [track]");
    auto site = t.subtable("site");
    if (!site) t.fail("site", "mode = \"ppi\" needs a [site] table (x, y, altitude or height)");
    parse_site(*site, r.ppi);
    r.track.altitude_m = r.ppi.altitude_m ? *r.ppi.altitude_m : *r.ppi.height_above_ground_m;
    auto scan = t.subtable("scan");
    std::optional<ConfigTable> none;
    parse_scan(scan ? scan : none, r, t.file());
  } else {
    for (const char* k : {"site", "scan"}) {
      if (t.has(k)) t.fail(k, fmt::format("a [{}] table needs mode = \"ppi\"", k));
    }
    auto track = t.subtable("track");
    if (!track) t.fail("track", "missing required table [track]");
    parse_track(*track, r.track);
    if (r.track.geo) r.track.geo->near_slant_range_m = r.near_slant_range_m;
  }
  const double h_m = r.track.altitude_m;
  if (!ppi && r.near_slant_range_m < h_m) {
    t.fail(t.has("sweep_delay") ? "sweep_delay" : "near_range",
           fmt::format("near slant range {:.1f} m is shorter than the altitude {:.1f} m: the sweep "
                       "would start before the ground return",
                       r.near_slant_range_m, h_m));
  }

  if (t.has("speed")) r.speed_m_per_s = get_positive(t, "speed", Quantity::speed, "m/s");
  if (t.has("prf")) r.prf_hz = get_positive(t, "prf", Quantity::frequency, "Hz");
  if (t.has("azimuth_line_spacing")) {
    r.azimuth_line_spacing_m = get_positive(t, "azimuth_line_spacing", Quantity::length, "m");
  }
  if (t.has("independent_samples")) {
    const toml::node* n = t.raw("independent_samples");
    if (auto s = n->as_string()) {
      if (s->get() != "seed") {
        t.fail(
            "independent_samples",
            fmt::format("expected \"seed\" (equation 16) or a number >= 1, got \"{}\"", s->get()));
      }
    } else if (n->is_integer() || n->is_floating_point()) {
      const double v = *n->value<double>();
      if (!(v >= 1.0) || !std::isfinite(v)) {
        t.fail("independent_samples", fmt::format("expected a number >= 1, got {}", v));
      }
      r.independent_samples = v;
    } else {
      t.fail("independent_samples", "expected \"seed\" or a number >= 1");
    }
  }

  // SAR: a pixel averages L_r L_a independent looks (unless given).
  if (sar && !r.independent_samples) {
    r.independent_samples = double(r.sar.range_looks) * double(r.sar.azimuth_looks);
  }

  // Elevation pattern; the default boresight points at mid-swath (flat ground).
  {
    const double mid_r_m = 0.5 * (r.near_slant_range_m + r.far_slant_range_m);
    const double mid_look_rad = std::acos(std::min(1.0, h_m / mid_r_m));
    if (auto p = t.subtable("elevation_pattern")) {
      parse_pattern(*p, r.elevation_pattern, mid_look_rad);
    } else {
      r.elevation_pattern.boresight_rad = mid_look_rad;
    }
  }

  auto ref = t.subtable("reference");
  parse_reference(ref, r, r.reference);
  if (auto film = t.subtable("film")) parse_film(*film, r.film, r.switches, r.fading);
  t.finish();
  return r;
}

// The keys a [[channel]] table may set: the file's own keys of the same
// name, for that channel (frequency and polarisation required).
constexpr std::array<const char*, 4> kChannelRadarKeys{"frequency", "polarisation",
                                                       "transmit_power", "antenna_gain_db"};

// A channel's name, the suffix of its products' file names: letters, digits,
// '-' and '_' (default: its polarisation in lower case, "hh").
std::string channel_name(ConfigTable& c, Polarisation pol) {
  std::string name = c.get_string_or("name", "");
  if (!c.has("name")) {
    name = std::string(to_string(pol));
    for (char& ch : name) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    return name;
  }
  const bool ok = !name.empty() && std::all_of(name.begin(), name.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '_';
  });
  if (!ok) {
    c.fail("name", fmt::format("\"{}\" cannot be a file-name suffix: expected letters, digits, "
                               "'-' or '_' (e.g. \"c_hh\")",
                               name));
  }
  return name;
}

// A radar file with [[channel]] tables: each channel is the radar the file
// gives with the channel's keys at its top level, checked as one; the
// channel's own keys are checked first so that a message names them
// ("channel[1].frequency"). The result is the first channel's radar with
// `channels` filled.
RadarParams radar_with_channels(const toml::table& doc, const std::string& source_file) {
  ConfigTable top(doc, source_file, "");
  for (const char* k : {"frequency", "polarisation"}) {
    if (top.has(k)) {
      top.fail(k, fmt::format("a radar with [[channel]] tables gives each channel its {0}: move "
                              "the top-level {0} into the [[channel]] tables (or drop the "
                              "[[channel]] tables for a one-channel radar)",
                              k));
    }
  }
  std::vector<ConfigTable> tables = top.table_array("channel");
  if (tables.empty()) top.fail("channel", "expected one or more [[channel]] tables");
  const toml::array* array = doc["channel"].as_array();
  RIS_CHECK(array != nullptr);  // table_array refused anything else
  toml::table base = doc;
  base.erase("channel");
  const std::filesystem::path folder = std::filesystem::path(source_file).parent_path();
  std::vector<RadarChannel> channels;
  for (std::size_t i = 0; i < tables.size(); ++i) {
    ConfigTable& c = tables[i];
    within(c, "frequency", get_positive(c, "frequency", Quantity::frequency, "Hz"), kFrequencyHz);
    Polarisation pol = Polarisation::HH;
    try {
      pol = parse_polarisation(c.get_string("polarisation"));
    } catch (const std::invalid_argument& e) {
      c.fail("polarisation", e.what());
    }
    if (c.has("transmit_power")) {
      within(c, "transmit_power", get_positive(c, "transmit_power", Quantity::power, "W"),
             kTransmitPowerW);
    }
    if (c.has("antenna_gain_db")) {
      const double gain_db = c.get_double("antenna_gain_db");
      if (!std::isfinite(gain_db)) c.fail("antenna_gain_db", "expected a finite number of dB");
      within(c, "antenna_gain_db", gain_db, kGainDb);
    }
    RadarChannel ch;
    ch.name = channel_name(c, pol);
    for (const RadarChannel& other : channels) {
      if (other.name == ch.name) {
        c.fail(c.has("name") ? "name" : "polarisation",
               fmt::format("two channels are named \"{}\" (a channel's name defaults to its "
                           "polarisation): give each a name of its own, e.g. name = \"l_{}\"",
                           ch.name, ch.name));
      }
    }
    if (auto bs = c.get_string_opt("backscatter")) {
      if (bs->empty()) c.fail("backscatter", "expected the path of a backscatter library or table");
      const std::filesystem::path p(*bs);
      ch.backscatter_path = p.is_absolute() ? p.string() : (folder / p).string();
    }
    c.finish();
    // The channel's radar: the file's keys, the channel's at the top level.
    toml::table one = base;
    const toml::node* element = array->get(i);
    const toml::table* own = element != nullptr ? element->as_table() : nullptr;
    RIS_CHECK(own != nullptr);  // table_array checked every element
    for (const char* k : kChannelRadarKeys) {
      if (const toml::node* n = own->get(k)) one.insert_or_assign(k, *n);
    }
    ch.radar = std::make_shared<const RadarParams>(single_radar_from_toml(one, source_file));
    channels.push_back(std::move(ch));
  }
  RadarParams r = *channels.front().radar;
  r.channels = std::move(channels);
  return r;
}

}  // namespace

RadarParams radar_from_toml(const toml::table& doc, const std::string& source_file) {
  if (doc.contains("channel")) return radar_with_channels(doc, source_file);
  return single_radar_from_toml(doc, source_file);
}

RadarParams load_radar(const std::string& path) {
  const toml::table doc = parse_toml_file(path);
  return radar_from_toml(doc, path);
}

}  // namespace ris
