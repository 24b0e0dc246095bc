// `ris radar info [RADAR.toml]`: the radar's derived quantities over flat
// ground (ris/sensor/radar_derived.h).
#include <fmt/format.h>

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

void print_info(const std::string& path) {
  const RadarParams r = load_radar(path);
  const RadarDerived d = derive(r);
  const auto deg = [](double rad) { return fmt::format("{:.3f} deg", rad_to_deg(rad)); };
  fmt::print("radar {}\n", path);
  if (!r.name.empty()) fmt::print("  name                      {}\n", r.name);
  fmt::print("  mode                      slar, {:.4g} GHz {}, wavelength {:.4f} m\n",
             r.frequency_hz * 1e-9, to_string(r.polarisation), d.wavelength_m);
  fmt::print("  altitude                  {}\n", metres_feet(r.track.altitude_m));
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
  fmt::print("  azimuth footprint R phi   {} / {}\n", metres_feet(d.near_azimuth_footprint_m),
             metres_feet(d.far_azimuth_footprint_m));
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
