// Radiance leaving a Lambertian surface lit by the sun and the sky, seen
// through the atmosphere (the standard reflective-band form, e.g. Schott,
// "Remote Sensing: The Image Chain Approach", 2nd ed. 2007, eq. 4.63,
// without adjacency):
//   L = rho (E_sun cos(theta_i) T_down lit + E_sky) / pi * T_up + L_path
// with E_sun the band solar irradiance at the surface-normal-facing top of
// the atmosphere [W m^-2 um^-1], theta_i the sun's incidence angle on the
// facet, lit 0 in a cast shadow, E_sky the diffuse sky irradiance.
// Thermal: L = eps B(T_s) + (1 - eps) L_sky_down (Kirchhoff, opaque surface).
// docs/sensors.md, "Optical" and "Thermal".
#pragma once

namespace ris {

struct Illumination {
  double sun_irradiance_w_m2_um = 0;  // TOA band irradiance at the day's distance
  double cos_incidence = 0;           // max(n . s, 0)
  double transmittance_down = 1;
  double transmittance_up = 1;
  double sky_irradiance_w_m2_um = 0;
  double path_radiance_w_m2_sr_um = 0;
  bool lit = true;  // false in a cast shadow
};

// Band-mean spectral radiance [W m^-2 sr^-1 um^-1].
double lambertian_radiance(double reflectance, const Illumination& e);

// Thermal band radiance [W m^-2 sr^-1] from a blackbody band radiance at the
// surface temperature and the downwelling sky band radiance.
double thermal_leaving_radiance(double emissivity, double blackbody_band_radiance,
                                double sky_band_radiance);

}  // namespace ris
