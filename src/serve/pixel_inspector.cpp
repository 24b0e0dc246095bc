#include "ris/serve/pixel_inspector.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "ris/geometry/scene_geometry_maps.h"
#include "ris/image/geocode.h"
#include "ris/image/radiometric_calibration.h"
#include "ris/scene/geo_frame.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

void check_inside(int x, int y, int cols, int rows, const std::string& view) {
  if (x < 0 || y < 0 || x >= cols || y >= rows) {
    throw InputError("request", "x, y",
                     fmt::format("pixel ({}, {}) is outside the {} view of {} x {} pixels", x, y,
                                 view, cols, rows));
  }
}

nlohmann::json flags_json(std::uint8_t f, bool scene_grid) {
  nlohmann::json names = nlohmann::json::array();
  if (scene_grid) {
    if (f & scene_flag::kShadow) names.push_back("shadow");
    if (f & scene_flag::kLayover) names.push_back("layover");
    if (f & scene_flag::kNoData) names.push_back("no data");
    if (f & scene_flag::kBackFacing) names.push_back("back-facing");
    if (f & scene_flag::kOutsideSwath) names.push_back("outside swath");
  } else {
    if (f & pixel_flag::kShadow) names.push_back("shadow");
    if (f & pixel_flag::kLayover) names.push_back("layover");
    if (f & pixel_flag::kNoData) names.push_back("no data");
  }
  return names;
}

double db(double power) {
  return power > 0.0 ? 10.0 * std::log10(power) : -INFINITY;
}

// NaN and infinities have no JSON form: null.
nlohmann::json number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nullptr;
}

// Why a run's pixels cannot be calibrated, in the words of the key to change
// (run.cpp refuses --calibrated for the same reasons); empty when they can.
std::string why_not_calibrated(const SlarSimulation& sim) {
  if (sim.range_corrected) {
    return "not calibrated: film.terms.range is false, so the pixels carry the reference "
           "system's R^-4, not this radar's (set it true)";
  }
  if (sim.area_corrected) {
    return "not calibrated: film.terms.area is false, so the pixels carry the reference "
           "cell's area, not this radar's (set it true)";
  }
  if (sim.calibration.empty()) return "not calibrated: this run forms no calibration";
  return "";
}

// The backscatter coefficients of slant pixel i in bin `bin`, as a calibrated
// product carries them (ris/image/radiometric_calibration.h: P / P_1 over flat
// ground at the reference height, MODEL.md section 3): sigma0, beta0 and
// gamma0 in dB of the mean power, sigma0 linear, and the speckled pixel's
// (what sigma0_slant.tif of `ris simulate --calibrated` holds). Or the reason
// there are none.
nlohmann::json calibrated_pixel(const SlarSimulation& sim, const SlarPictures& pic, std::size_t i,
                                int bin) {
  if (const std::string why = why_not_calibrated(sim); !why.empty()) {
    return {{"not_calibrated", why}};
  }
  const SlantCalibration& cal = sim.calibration;
  const auto b = static_cast<std::size_t>(bin);
  if (!std::isfinite(cal.unit_power_w[b])) {
    return {{"not_calibrated",
             "not calibrated: no flat ground at the reference height lies at this range, or the "
             "antenna's gain is 0 there"}};
  }
  const double mean = sim.image.mean_power_w[i];
  const double speckled = pic.speckled_power_w[i];
  const auto coefficient = [&](double power_w, Backscatter k) {
    return power_w * calibration_factor(cal, k, bin);
  };
  return {{"reference_height_m", cal.reference_height_m},
          {"incidence_deg", rad_to_deg(std::atan2(cal.sin_incidence[b], cal.cos_incidence[b]))},
          {"sigma0", number(coefficient(mean, Backscatter::sigma0))},
          {"sigma0_db", number(db(coefficient(mean, Backscatter::sigma0)))},
          {"beta0_db", number(db(coefficient(mean, Backscatter::beta0)))},
          {"gamma0_db", number(db(coefficient(mean, Backscatter::gamma0)))},
          {"speckled_sigma0_db", number(db(coefficient(speckled, Backscatter::sigma0)))},
          {"speckled_beta0_db", number(db(coefficient(speckled, Backscatter::beta0)))},
          {"speckled_gamma0_db", number(db(coefficient(speckled, Backscatter::gamma0)))}};
}

// The slant image pixel (line, bin): its own values.
nlohmann::json slant_pixel(const RunResult& run, int line, int bin) {
  const SlarSimulation& sim = slar_image_run(run)->sim;
  const SlarPictures& pic = slar_image_run(run)->pictures;
  const std::size_t i = sim.image.index(line, bin);
  const double R = sim.image.range.centre_m(bin);
  // Incidence at that range over a flat datum: cos(theta) = H / R.
  const double H = sim.track.altitude_m;
  const double incidence = R > H ? std::acos(H / R) : 0.0;
  return {{"line", line},
          {"bin", bin},
          {"slant_range_m", R},
          {"incidence_flat_deg", rad_to_deg(incidence)},
          {"looks", number(pic.looks[static_cast<std::size_t>(bin)])},
          {"mean_power_w", number(sim.image.mean_power_w[i])},
          {"mean_power_dbw", number(db(sim.image.mean_power_w[i]))},
          {"speckled_power_w", number(pic.speckled_power_w[i])},
          {"greytone", pic.slant_grey[i]},
          {"flags", flags_json(sim.image.mask[i], false)},
          {"calibrated", calibrated_pixel(sim, pic, i, bin)}};
}

// A ground-range pixel (line, column j): its ground range over h_ref, its own
// greytone and flags, and the slant pixel at the same range,
// R = sqrt(u^2 + (H - h_ref)^2) (ris/image/ground_range.h).
nlohmann::json ground_pixel(const RunResult& run, int line, int j) {
  const SlarSimulation& sim = slar_image_run(run)->sim;
  const GroundRangeGrid& g = sim.ground_grid;
  const std::size_t i = static_cast<std::size_t>(line) * g.count + j;
  const double u = g.centre_m(j);
  const double R = std::hypot(u, g.altitude_m - g.reference_height_m);
  nlohmann::json out = {{"line", line},
                        {"ground_range_m", u},
                        {"greytone", slar_image_run(run)->pictures.ground_grey[i]},
                        {"flags", flags_json(slar_image_run(run)->pictures.ground_mask[i], false)}};
  const int bin =
      static_cast<int>(std::floor((R - sim.image.range.near_m) / sim.image.range.bin_m));
  if (bin >= 0 && bin < sim.image.bins) out["pixel"] = slant_pixel(run, line, bin);
  return out;
}

// The scene cell a slant pixel (line, bin) images, for the linked cursor:
// the cells whose centres geocode into that pixel (the geometry's own
// mapping, terrain heights included), the one nearest their mean; when none
// does (shadow, no data), the cell geocoding nearest to it. nullopt when no
// cell lies in the image at all.
std::optional<std::pair<int, int>> scene_cell_of_pixel(const RunResult& run, int line, int bin) {
  const Scene& scene = *run.scene;
  const SlarSimulation& sim = slar_image_run(run)->sim;
  std::vector<std::pair<int, int>> exact;
  std::optional<std::pair<int, int>> nearest;
  double best = INFINITY;
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t i = scene.index(r, c);
      int l = 0;
      int b = 0;
      if (!scene.valid[i] ||
          !geocode_pixel(scene, sim.track, sim.image, r, c, scene.elevation_m[i], l, b)) {
        continue;
      }
      const double d = double(l - line) * (l - line) + double(b - bin) * (b - bin);
      if (d == 0.0) exact.emplace_back(r, c);
      if (d < best) {
        best = d;
        nearest = std::pair{r, c};
      }
    }
  }
  if (exact.empty()) return nearest;
  double mr = 0.0;
  double mc = 0.0;
  for (const auto& [r, c] : exact) {
    mr += r;
    mc += c;
  }
  mr /= double(exact.size());
  mc /= double(exact.size());
  return *std::min_element(exact.begin(), exact.end(), [&](const auto& a, const auto& b) {
    return std::hypot(a.first - mr, a.second - mc) < std::hypot(b.first - mr, b.second - mc);
  });
}

// The scene cell a slant pixel images, as {"row", "col", "cells"...} for
// the page's linked cursor.
void add_scene_cell(const RunResult& run, int line, int bin, nlohmann::json& j) {
  if (const auto cell = scene_cell_of_pixel(run, line, bin)) {
    j["scene_row"] = cell->first;
    j["scene_col"] = cell->second;
  }
}

// Map coordinates of a cell centre: the scene's x, y in metres, and
// latitude/longitude on its CRS's datum when it has one.
void add_map_position(const Scene& scene, int row, int col, nlohmann::json& j) {
  const auto [x_m, y_m] = scene.cell_centre(row, col);
  j["x_m"] = x_m;
  j["y_m"] = y_m;
  if (scene.crs_wkt.empty()) return;
  try {
    const GeoFrame frame(scene.crs_wkt, "scene");
    const auto [lon, lat] = frame.lonlat_from_scene(x_m, y_m);
    j["lat_deg"] = lat;
    j["lon_deg"] = lon;
    j["datum"] = frame.geographic_crs_name();
  } catch (const InputError&) {
    // A CRS PROJ cannot invert here: the position in metres only.
  }
}

nlohmann::json scene_cell(const RunResult& run, const Sigma0Source& sigma0, int col, int row) {
  const Scene& scene = *run.scene;
  const SlarSimulation& sim = slar_image_run(run)->sim;
  const std::size_t i = scene.index(row, col);
  nlohmann::json j = {{"row", row}, {"col", col}};
  add_map_position(scene, row, col, j);
  if (!scene.valid[i]) {
    j["flags"] = flags_json(scene_flag::kNoData, true);
    return j;
  }
  const std::uint16_t c = scene.category[i];
  const float h = scene.elevation_m[i];
  j["elevation_m"] = h;
  j["category"] = c;
  j["category_name"] = sigma0.has_category(c) ? sigma0.category_name(c) : std::to_string(c);
  j["flags"] = flags_json(sim.scene_maps.mask[i], true);
  const double li_deg = sim.scene_maps.local_incidence_deg[i];
  j["local_incidence_deg"] = number(li_deg);
  if (std::isfinite(li_deg) && sigma0.has_category(c)) {
    const RadarBand band{run.radar.frequency_hz, run.radar.polarisation};
    j["sigma0_db"] = number(db(sigma0.sigma0(c, deg_to_rad(li_deg), band)));
  }
  // From the track: u across, H - h down (MODEL.md section 2).
  const auto [x_m, y_m] = scene.cell_centre(row, col);
  const double u = sim.track.along_cross(x_m, y_m).second;
  const double down = sim.track.altitude_m - h;
  j["slant_range_m"] = std::hypot(u, down);
  j["incidence_deg"] = rad_to_deg(std::atan2(u, down));
  int line = 0;
  int bin = 0;
  if (geocode_pixel(scene, sim.track, sim.image, row, col, h, line, bin)) {
    j["pixel"] = slant_pixel(run, line, bin);
  }
  return j;
}

}  // namespace

nlohmann::json inspect_pixel(const RunResult& run, const Sigma0Source& sigma0,
                             const std::string& view, int x, int y) {
  if (!run.in_memory()) {
    throw InputError("request", "view", "a streamed run keeps no images");
  }
  if (const auto* ppi = std::get_if<PpiRun>(&run.run)) {
    const PpiScopeGrid& g = ppi->sim.scope_grid;
    if (view != "slant") throw InputError("request", "view", "a PPI run is inspected on its scope");
    check_inside(x, y, g.size, g.size, view);
    const std::size_t i = static_cast<std::size_t>(y) * g.size + x;
    return {{"view", view},
            {"x", x},
            {"y", y},
            {"east_m", g.east_m(x)},
            {"north_m", g.north_m(y)},
            {"speckled_power_w", number(ppi->pictures.scope_power_w[i])},
            {"greytone", ppi->pictures.scope_grey[i]},
            {"flags", flags_json(ppi->pictures.scope_mask[i], false)},
            {"calibrated",
             {{"not_calibrated",
               "not calibrated: a PPI scope has no calibration convention (use mode = "
               "\"slar\" or \"sar\")"}}}};
  }
  const SlarRun* slar = slar_image_run(run);
  if (slar == nullptr) throw InputError("request", "view", "expected a SLAR, SAR or PPI run");
  nlohmann::json j;
  if (view == "slant") {
    check_inside(x, y, slar->sim.image.bins, slar->sim.image.lines, view);
    j = slant_pixel(run, y, x);
    add_scene_cell(run, y, x, j);
  } else if (view == "ground") {
    check_inside(x, y, slar->sim.ground_grid.count, slar->sim.image.lines, view);
    j = ground_pixel(run, y, x);
    if (j.contains("pixel")) add_scene_cell(run, y, j["pixel"]["bin"].get<int>(), j);
  } else if (view == "scene" || view == "geocoded") {
    check_inside(x, y, run.scene->cols, run.scene->rows, view);
    j = scene_cell(run, sigma0, x, y);
  } else {
    throw InputError(
        "request", "view",
        "the inspector reads the slant, scene and geocoded views, not \"" + view + "\"");
  }
  j["view"] = view;
  return j;
}

}  // namespace ris
