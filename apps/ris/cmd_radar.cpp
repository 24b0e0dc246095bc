// `ris radar info [RADAR.toml]`: the radar's derived quantities over flat
// ground (ris/sensor/radar_derived.h), with the SAR's resolutions, looks and
// noise, or the PPI's site and scan (docs/modes.md).
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "command_registry.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/radar_derived.h"
#include "ris/util/units.h"

namespace ris::app {
namespace {

std::string metres_feet(double m) {
  return fmt::format("{:.1f} m ({:.0f} ft)", m, m / kFeetToMetres);
}

void print_sar(const SarParams& s) {
  fmt::print("  SAR range resolution      {}{}\n", metres_feet(s.range_resolution_m),
             s.bandwidth_hz > 0.0 ? fmt::format(" (c / 2B, B = {:.1f} MHz)", s.bandwidth_hz * 1e-6)
                                  : std::string(" (given)"));
  fmt::print(
      "  SAR azimuth resolution    {}{}\n", metres_feet(s.azimuth_resolution_m),
      s.antenna_length_m > 0.0
          ? fmt::format(" (L / 2, L = {:.2f} m; the same at every range)", s.antenna_length_m)
          : std::string(" (given; the same at every range)"));
  fmt::print("  looks range x azimuth     {} x {}: pixel resolution {:.2f} m x {:.2f} m\n",
             s.range_looks, s.azimuth_looks, s.range_resolution_looks_m(),
             s.azimuth_resolution_looks_m());
  fmt::print("  NESZ                      {}\n",
             s.nesz ? fmt::format("{:.1f} dB", 10.0 * std::log10(*s.nesz)) : std::string("none"));
  fmt::print("  speckle                   {}\n",
             s.coherent ? "coherent (random-phase scatterers, sinc impulse responses)"
                        : "fading law, N = looks");
}

void print_ppi(const RadarParams& r) {
  const PpiParams& p = r.ppi;
  if (p.site_latlon_deg) {
    fmt::print("  site                      lat {:.6f} deg, lon {:.6f} deg\n",
               (*p.site_latlon_deg)[0], (*p.site_latlon_deg)[1]);
  } else {
    fmt::print("  site                      x {:.1f} m, y {:.1f} m (scene)\n", p.site_x_m,
               p.site_y_m);
  }
  const double spacing_deg = rad_to_deg(p.ray_spacing_rad);
  fmt::print(
      "  scan                      {:.1f} deg from {:.1f} deg (clockwise from north), rays "
      "every {:.3f} deg ({:.0f} rays), beam {:.2f} deg\n",
      rad_to_deg(p.scan_width_rad), rad_to_deg(p.scan_start_rad), spacing_deg,
      std::round(p.scan_width_rad / p.ray_spacing_rad), rad_to_deg(r.azimuth_beamwidth_rad));
  fmt::print(
      "  scope                     {} range{}\n",
      p.presentation == PpiPresentation::slant ? "slant" : "ground",
      p.ring_spacing_m > 0.0 ? ", rings every " + metres_feet(p.ring_spacing_m) : std::string());
}

void print_info(const std::string& path) {
  const RadarParams r = load_radar(path);
  const RadarDerived d = derive(r);
  const auto deg = [](double rad) { return fmt::format("{:.3f} deg", rad_to_deg(rad)); };
  fmt::print("radar {}\n", path);
  if (!r.name.empty()) fmt::print("  name                      {}\n", r.name);
  const char* mode =
      r.mode == RadarMode::slar ? "slar" : (r.mode == RadarMode::sar ? "sar" : "ppi");
  fmt::print("  mode                      {}, {:.4g} GHz {}, wavelength {:.4f} m\n", mode,
             r.frequency_hz * 1e-9, to_string(r.polarisation), d.wavelength_m);
  if (r.channels.size() > 1) {
    // A multi-channel file: the figures below are its first channel's.
    fmt::print("  channels                  {} (the figures below are the first's):\n",
               r.channels.size());
    for (const RadarChannel& c : r.channels) {
      fmt::print(
          "    {:<23} {:.4g} GHz {}{}\n", c.name, c.radar->frequency_hz * 1e-9,
          to_string(c.radar->polarisation),
          c.backscatter_path.empty() ? std::string() : ", backscatter " + c.backscatter_path);
    }
  }
  if (r.mode == RadarMode::ppi) print_ppi(r);
  if (r.mode == RadarMode::ppi && r.ppi.height_above_ground_m) {
    fmt::print(
        "  antenna height            {} above the terrain at the site (the figures\n"
        "                            below: over flat ground at the site's height)\n",
        metres_feet(*r.ppi.height_above_ground_m));
  } else {
    fmt::print("  altitude                  {}\n", metres_feet(r.track.altitude_m));
  }
  fmt::print("  range resolution c tau/2  {}\n", metres_feet(d.range_resolution_m));
  fmt::print("  range bin                 {}\n", metres_feet(d.range_bin_m));
  fmt::print("  range bins                {}\n", d.range_bins);
  fmt::print("  slant range near / far    {} / {}\n", metres_feet(d.near_slant_range_m),
             metres_feet(d.far_slant_range_m));
  fmt::print("  ground range near / far   {} / {}\n", metres_feet(d.near_ground_range_m),
             metres_feet(d.far_ground_range_m));
  fmt::print("  swath (ground)            {}\n", metres_feet(d.swath_ground_m));
  fmt::print("  depression near / far     {} / {}\n", deg(d.near_depression_rad),
             deg(d.far_depression_rad));
  fmt::print("  incidence near / far      {} / {}\n", deg(d.near_incidence_rad),
             deg(d.far_incidence_rad));
  if (r.mode == RadarMode::sar) {
    print_sar(r.sar);
  } else {
    fmt::print("  azimuth footprint R phi   {} / {}\n", metres_feet(d.near_azimuth_footprint_m),
               metres_feet(d.far_azimuth_footprint_m));
  }
  fmt::print("  N, equation 16 near / far {:.3f} / {:.3f}\n", d.near_samples_eq16,
             d.far_samples_eq16);
  fmt::print("  N used for fading         {:.3f} / {:.3f} ({})\n", d.near_samples, d.far_samples,
             d.samples_from_eq16 ? "equation 16, at least 1" : "given");
  if (d.near_pulses_per_footprint > 0.0) {
    fmt::print("  pulses per footprint      {:.1f} / {:.1f}\n", d.near_pulses_per_footprint,
               d.far_pulses_per_footprint);
  }
  fmt::print("  fading law                {}\n",
             r.fading == FadingLaw::exact_gamma ? "exact Gamma(N, 1/N)" : "seed equation 21");
  if (r.reference.automatic) {
    fmt::print("  reference                 auto: median mean power -> greytone {:.0f}\n",
               r.reference.auto_greytone);
  } else {
    fmt::print("  reference                 greytone {:.0f}\n", r.reference.greytone);
  }
  fmt::print("  film                      X = {:g}, gamma = {:g}: {:.1f} greytones per decade\n",
             r.film.density_range, r.film.gamma, 255.0 * r.film.gamma / r.film.density_range);
}

void add_radar(CLI::App& app) {
  auto* radar = app.add_subcommand("radar", "Radar descriptions");
  radar->require_subcommand(1);
  auto* info = radar->add_subcommand("info", "Print a radar's derived quantities");
  auto path = std::make_shared<std::string>(default_radar_path());
  info->add_option("radar", *path, "Radar description (TOML)")->capture_default_str();
  info->callback([path] { print_info(*path); });
}

const Registration reg{"radar", add_radar};

}  // namespace
}  // namespace ris::app
