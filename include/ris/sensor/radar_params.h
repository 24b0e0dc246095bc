// The radar, its track and its image chain as checked plain structs: what a
// radar description file (docs/radar-format.md) becomes after parsing. The
// core never sees strings or units; everything here is SI (metres, seconds,
// hertz, watts, radians).
//
// Parsing and validation: ris/sensor/radar_config.h. Derived quantities
// (resolutions, swath, N): ris/sensor/radar_derived.h.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ris/sensor/look_side.h"
#include "ris/sensor/polarisation.h"

namespace ris {

enum class RadarMode { slar, sar, ppi };
// The Earth a run's geometry uses (docs/geometry.md): the flat-Earth frame of
// the seed (a scene run's track), or the WGS 84 ellipsoid (an acquisition's
// orbit and radar grid, ris simulate --acquisition).
enum class EarthModel { flat, ellipsoid };

// One-way elevation antenna power gain G_e(beta) relative to boresight, as a
// function of the look angle beta from nadir (MODEL.md section 3).
struct ElevationPattern {
  enum class Kind { uniform, sinc2, gaussian, table };
  Kind kind = Kind::uniform;
  double beamwidth_rad = 0.0;          // one-way 3 dB beamwidth (sinc2, gaussian)
  double boresight_rad = 0.0;          // look angle from nadir of the beam centre
  std::vector<double> table_look_rad;  // table: look angles from nadir, increasing
  std::vector<double> table_gain;      // table: one-way power gain, linear, relative
};

// A track given in latitude/longitude (degrees), resolved into scene
// coordinates by ris/sensor/geo_track.h (added for geographic tracks;
// TrackSpec::geo is empty for tracks in scene coordinates).
struct GeoTrackSpec {
  enum class Kind { endpoints, heading_near_range_point };
  Kind kind = Kind::endpoints;
  double start_lat_deg = 0.0, start_lon_deg = 0.0, end_lat_deg = 0.0, end_lon_deg = 0.0;
  // heading_near_range_point: true heading (clockwise from geographic north)
  // and the ground point at near slant range.
  double heading_rad = 0.0;
  double point_lat_deg = 0.0, point_lon_deg = 0.0;
  double near_slant_range_m = 0.0;  // the radar's R_near, set by the parser
};

// How the flight track is given in the file; resolved against a scene into
// a Track (ris/sensor/track.h) because "near edge" depends on the scene.
struct TrackSpec {
  enum class Kind { endpoints, heading_near_edge };
  Kind kind = Kind::heading_near_edge;
  // endpoints: ground projection of the track start and end, scene metres.
  double start_x_m = 0.0, start_y_m = 0.0, end_x_m = 0.0, end_y_m = 0.0;
  // heading_near_edge: heading clockwise from north (scene +y), and the ground
  // distance from the track to the scene's nearest edge (the seed's
  // GROUND(1)); the track spans the scene along its heading.
  double heading_rad = 0.0;
  double near_edge_ground_m = 0.0;
  double altitude_m = 0.0;  // above the scene datum
  LookSide look_side = LookSide::right;
  // Set when the file gives the track in latitude/longitude; resolve_track
  // converts it (ris/sensor/geo_track.h) and the fields above then follow.
  std::optional<GeoTrackSpec> geo;
};

// The reference ("calibrator") cell of the seed's equation 15.
//
// After load_radar() every factor below holds a value: keys the file leaves
// out default to this radar's own values at mid-swath over flat ground
// (docs/radar-format.md), so a switched-off term of equation 15 always has a
// reference value to take.
struct ReferenceCell {
  bool automatic = true;  // median pixel power maps to auto_greytone
  double auto_greytone = 128.0;
  double greytone = 128.0;  // G_ref
  // Explicit reference: P_ref = P_T1 sigma0_1 dA_1 G_1^2 lambda_1^2 / ((4 pi)^3 R_1^4)
  double transmit_power_w = 0.0;  // P_T1
  double sigma0 = 0.0;            // sigma0_1 (linear)
  double area_m2 = 0.0;           // dA_1
  double gain = 1.0;              // G_1 (one-way, linear)
  double wavelength_m = 0.0;      // lambda_1
  // The file gave wavelength or frequency: lambda_1 stays when the radar is
  // retuned (radar_at_band); otherwise it is the radar's own wavelength.
  bool wavelength_given = false;
  double range_m = 0.0;  // R_1
  // Added (backward compatible): P_ref given directly instead of through the
  // factors above (the factors still serve switched-off terms).
  std::optional<double> mean_power_w;
  // Added: sigma0_1 given as a category at a local incidence angle; the
  // simulation evaluates it through its Sigma0Lut (include this category when
  // building the LUT) and stores the value in `sigma0` (NaN until then):
  // ris::resolve_reference_sigma0 in ris/image/greytone_terms.h.
  std::optional<std::uint16_t> sigma0_category;
  double sigma0_incidence_rad = 0.0;
};

// Film and receiver constants of equation 15 for the simulated (2) and
// reference (1) systems.
struct FilmParams {
  double density_range = 2.0;  // X, optical density range of the film
  double gamma = 1.0;          // film gamma
  double k1 = 1.0, k2 = 1.0;   // film exposure/processing constants
  double m1 = 1.0, m2 = 1.0;   // receiver power-to-intensity constants
};

// Which factors of equation 15 vary from the reference (the seed's
// PROCES(5..13)); a switched-off factor takes its reference value.
struct GreytoneSwitches {
  bool transmit_power = true;
  bool wavelength = true;
  bool antenna_gain = true;
  bool backscatter = true;
  bool area = true;
  bool range = true;
  bool film_k = true;
  bool receiver_m = true;
  bool fading = true;
};

enum class FadingLaw { exact_gamma, seed_eq21 };

// SAR stripmap (mode = "sar", table [sar]; MODEL.md section 3, "azimuth,
// SAR"). Resolutions are 3 dB widths of the impulse response, single look.
struct SarParams {
  double bandwidth_hz = 0.0;          // chirp bandwidth B (0: range resolution given)
  double range_resolution_m = 0.0;    // rho_r = c / (2 B), or given (slant range)
  double antenna_length_m = 0.0;      // L (0: not given)
  double azimuth_resolution_m = 0.0;  // rho_a = L / 2, or given
  int range_looks = 1;                // L_r: resolution L_r rho_r, N = L_r L_a looks
  int azimuth_looks = 1;              // L_a: resolution L_a rho_a
  std::optional<double> nesz;         // noise-equivalent sigma0 (linear); none: no noise
  bool coherent = false;              // complex reflectivity, sinc impulse responses
  // Quad-pol (HH, HV, VH, VV SLCs from each element's scattering vector;
  // ris/sim/sar_quad_pol.h): coherent, single look, one [radar] polarisation
  // ignored.
  bool quad_pol = false;
  // The multilooked resolutions, what a pixel integrates.
  double range_resolution_looks_m() const { return range_looks * range_resolution_m; }
  double azimuth_resolution_looks_m() const { return azimuth_looks * azimuth_resolution_m; }
};

// PPI (mode = "ppi", tables [site] and [scan]; MODEL.md section 2, "PPI").
enum class PpiPresentation { slant, ground };
struct PpiParams {
  double site_x_m = 0.0, site_y_m = 0.0;  // the radar's ground position, scene metres
  // Or [latitude, longitude] in degrees ([site] latlon), placed on the scene
  // through its CRS when the geometry is computed (ris/scene/geo_frame.h).
  std::optional<std::array<double, 2>> site_latlon_deg;
  std::optional<double> altitude_m;             // antenna above the datum, or
  std::optional<double> height_above_ground_m;  // above the terrain at the site (a mast)
  double scan_start_rad = 0.0;                  // sector start, clockwise from north
  double scan_width_rad = 0.0;                  // sector width (2 pi: all round)
  double ray_spacing_rad = 0.0;                 // at most half the azimuth beamwidth
  double ring_spacing_m = 0.0;                  // range rings on the scope (0: none)
  double scope_pixel_m = 0.0;                   // scope pixel size (default: the range bin)
  PpiPresentation presentation = PpiPresentation::slant;  // scope radius: slant or ground range
  bool full_circle() const { return scan_width_rad >= 2.0 * 3.14159265358979323846 - 1e-9; }
};

struct RadarParams;

// One channel of a multi-channel radar file (`[[channel]]` tables,
// docs/radar-format.md): its name (the suffix of its products), its own
// backscatter source when it has one, and the whole radar it is (the file's
// keys with the channel's frequency, polarisation, power and gain: the radar
// a one-channel file with those keys gives).
struct RadarChannel {
  std::string name;
  std::string backscatter_path;  // "": the run's backscatter source
  std::shared_ptr<const RadarParams> radar;
};

struct RadarParams {
  std::string source_file;  // where it was read from
  std::string name;         // free text

  RadarMode mode = RadarMode::slar;
  double frequency_hz = 0.0;
  Polarisation polarisation = Polarisation::HH;
  double pulse_width_s = 0.0;          // tau (SAR: optional, 0 when not given)
  double near_slant_range_m = 0.0;     // c t_delay / 2
  double far_slant_range_m = 0.0;      // near + c t_sweep / 2
  double range_bin_m = 0.0;            // dr, default c tau / 2
  int range_bins = 0;                  // floor((far - near) / dr): whole bins only
  double azimuth_beamwidth_rad = 0.0;  // phi
  // SAR without azimuth_beamwidth: phi = lambda / this length (the antenna
  // length, or 2 rho_a), recomputed by radar_at_band; 0 when phi was given.
  double beamwidth_antenna_length_m = 0.0;
  ElevationPattern elevation_pattern;
  double transmit_power_w = 0.0;  // P_t
  double peak_gain = 1.0;         // boresight one-way gain (linear), scales G_e

  TrackSpec track;             // SLAR, SAR; PPI: only altitude_m, the antenna height as given
  SarParams sar;               // mode sar
  PpiParams ppi;               // mode ppi
  double speed_m_per_s = 0.0;  // 0: not given (used only for reporting)
  double prf_hz = 0.0;         // 0: not given (used only for reporting)
  std::optional<double> independent_samples;  // nullopt: the seed's equation 16
                                              // (ris/sensor/radar_derived.h)
  double azimuth_line_spacing_m = 0.0;        // 0: one scene cell
  // `earth = "flat" | "ellipsoid"`; nullopt: the run's default (flat for a
  // scene run, the ellipsoid for an acquisition).
  std::optional<EarthModel> earth;

  ReferenceCell reference;
  FilmParams film;
  GreytoneSwitches switches;
  FadingLaw fading = FadingLaw::exact_gamma;

  // A multi-channel radar file's channels, in the file's order; this radar
  // is then the first channel's. Empty: one channel, this radar (the file
  // lists no [[channel]]).
  std::vector<RadarChannel> channels;

  double wavelength_m() const;
};

// The radar at another frequency and polarisation, as if its file said so:
// the defaults that follow the wavelength (the reference cell's lambda_1, a
// SAR's real-antenna beamwidth lambda / L) follow it, everything the file
// gave stays. Throws InputError (naming the radar file) when the retuned
// beamwidth reaches 180 deg. The frequency/polarisation study runs each band
// through this (ris/analysis/study.h).
RadarParams radar_at_band(const RadarParams& radar, double frequency_hz, Polarisation polarisation);

}  // namespace ris
