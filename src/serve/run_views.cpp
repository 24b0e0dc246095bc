#include "ris/serve/run_views.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "ris/geometry/scene_geometry_maps.h"
#include "ris/image/category_palette.h"
#include "ris/image/geocode.h"
#include "ris/image/scene_preview.h"
#include "ris/image/shadow_map.h"
#include "ris/io/raster_io.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

[[noreturn]] void no_view(const std::string& view, const std::string& why) {
  throw InputError("request", "view", "no view \"" + view + "\": " + why);
}

// The run's in-memory image, or a refusal naming the view.
const SlarRun& slar_of(const RunResult& run, const std::string& view, const char* why) {
  const SlarRun* slar = slar_image_run(run);
  if (slar == nullptr) no_view(view, why);
  return *slar;
}

template <typename Vec>
ViewPixels grey(const Vec& v, int cols, int rows) {
  ViewPixels p;
  p.cols = cols;
  p.rows = rows;
  p.data.assign(v.begin(), v.end());
  return p;
}

// The slant image's pixel flags and the scene grid's flags in one vocabulary.
struct MaskColour {
  const char* name;
  std::uint8_t slant_bit;  // pixel_flag (0: none on that grid)
  std::uint8_t scene_bit;  // scene_flag
  std::array<std::uint8_t, 4> rgba;
};
constexpr std::array<MaskColour, 4> kMasks{{
    {"shadow", pixel_flag::kShadow, scene_flag::kShadow, {40, 90, 255, 150}},
    {"layover", pixel_flag::kLayover, scene_flag::kLayover, {255, 40, 40, 150}},
    {"backfacing", 0, scene_flag::kBackFacing, {255, 200, 0, 150}},
    {"nodata", pixel_flag::kNoData, scene_flag::kNoData, {120, 120, 120, 150}},
}};

}  // namespace

ViewPixels view_pixels(const RunResult& run, const std::string& view) {
  if (!run.in_memory()) no_view(view, "a streamed run keeps no images");
  if (view == "scene") {
    ViewPixels p;
    p.cols = run.scene->cols;
    p.rows = run.scene->rows;
    p.channels = 3;
    p.data = shaded_category_rgb(*run.scene, ScenePreviewOptions{});
    return p;
  }
  if (const auto* ppi = std::get_if<PpiRun>(&run.run)) {
    const PpiPictures& pic = ppi->pictures;
    if (view == "slant") {
      return grey(pic.scope_grey, ppi->sim.scope_grid.size, ppi->sim.scope_grid.size);
    }
    if (view == "ground") return grey(pic.bscope_grey, ppi->sim.bscope.bins, ppi->sim.bscope.lines);
    no_view(view, "a PPI run has the views slant (the scope), ground (the B-scope) and scene");
  }
  const SlarRun& slar = slar_of(run, view, "expected a SLAR, SAR or PPI run");
  const SlarSimulation& sim = slar.sim;
  const SlarPictures& pic = slar.pictures;
  if (view == "slant") return grey(pic.slant_grey, sim.image.bins, sim.image.lines);
  if (view == "ground") return grey(pic.ground_grey, sim.ground_grid.count, sim.image.lines);
  if (view == "geocoded") {
    return grey(geocode_slant_grey(*run.scene, sim.track, sim.image, pic.slant_grey),
                run.scene->cols, run.scene->rows);
  }
  no_view(view, "expected slant, ground, geocoded or scene");
}

std::vector<std::uint8_t> view_png(const RunResult& run, const std::string& view) {
  const ViewPixels p = view_pixels(run, view);
  return encode_png(p.data.data(), p.cols, p.rows, p.channels);
}

std::vector<std::uint8_t> overlay_png(const RunResult& run, const std::string& view,
                                      const std::string& masks) {
  const SlarSimulation& sim =
      slar_of(run, view, "mask overlays are drawn for SLAR and SAR runs").sim;
  const bool slant = view == "slant";
  if (!slant && view != "scene" && view != "geocoded") {
    no_view(view, "overlays exist for slant, scene and geocoded");
  }
  // The masks asked for, each known by name.
  std::vector<const MaskColour*> wanted;
  std::stringstream list(masks);
  for (std::string name; std::getline(list, name, ',');) {
    if (name.empty()) continue;
    const MaskColour* found = nullptr;
    for (const MaskColour& m : kMasks) {
      if (name == m.name) found = &m;
    }
    if (found == nullptr) {
      throw InputError("request", "masks",
                       "unknown mask \"" + name +
                           "\": expected shadow, layover, backfacing or "
                           "nodata, comma-separated");
    }
    wanted.push_back(found);
  }
  const auto& flags = slant ? sim.image.mask : sim.scene_maps.mask;
  const int cols = slant ? sim.image.bins : run.scene->cols;
  const int rows = slant ? sim.image.lines : run.scene->rows;
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(cols) * rows * 4, 0);
  for (std::size_t i = 0; i < flags.size(); ++i) {
    // The first mask listed wins where several apply.
    for (const MaskColour* m : wanted) {
      const std::uint8_t bit = slant ? m->slant_bit : m->scene_bit;
      if (bit != 0 && (flags[i] & bit) != 0) {
        std::copy(m->rgba.begin(), m->rgba.end(),
                  rgba.begin() + static_cast<std::ptrdiff_t>(4 * i));
        break;
      }
    }
  }
  return encode_png(rgba.data(), cols, rows, 4);
}

std::string shadow_map(const RunResult& run) {
  const SlarRun* slar = slar_image_run(run);
  if (slar == nullptr) {
    throw InputError("request", "", "the shadow map is made for SLAR and SAR runs");
  }
  return shadow_map_text(slar->sim.image);
}

nlohmann::json greytone_histogram(const RunResult& run) {
  std::vector<std::int64_t> counts(256, 0);
  if (const SlarRun* slar = slar_image_run(run)) {
    const auto& grey = slar->pictures.slant_grey;
    const auto& mask = slar->sim.image.mask;
    for (std::size_t i = 0; i < grey.size(); ++i) {
      if ((mask[i] & pixel_flag::kNoData) == 0) ++counts[grey[i]];
    }
  } else if (const auto* ppi = std::get_if<PpiRun>(&run.run)) {
    const PpiPictures& pic = ppi->pictures;
    for (std::size_t i = 0; i < pic.scope_grey.size(); ++i) {
      if ((pic.scope_mask[i] & pixel_flag::kNoData) == 0) ++counts[pic.scope_grey[i]];
    }
  }
  return nlohmann::json{{"counts", counts}};
}

nlohmann::json map_furniture(const RunResult& run, const Sigma0Source& sigma0) {
  nlohmann::json out;
  const Scene& scene = *run.scene;
  out["cell_m"] = scene.dx_m;
  out["georeferenced"] = !scene.crs_wkt.empty();
  nlohmann::json key = nlohmann::json::array();
  for (const MaskColour& m : kMasks) {
    key.push_back({{"mask", m.name}, {"rgba", m.rgba}});
  }
  out["overlay_key"] = key;
  if (!run.in_memory()) return out;
  const auto* ppi = std::get_if<PpiRun>(&run.run);
  const SlarRun* slar = slar_image_run(run);
  nlohmann::json legend = nlohmann::json::array();
  for (const std::uint16_t c : ppi != nullptr ? ppi->sim.categories : slar->sim.categories) {
    const Rgb8 rgb = category_colour(c);
    legend.push_back({{"id", c},
                      {"name", sigma0.has_category(c) ? sigma0.category_name(c) : ""},
                      {"rgb", {rgb.r, rgb.g, rgb.b}}});
  }
  out["legend"] = legend;
  if (ppi != nullptr) return out;
  const SlarSimulation& sim = slar->sim;
  out["range_bin_m"] = sim.image.range.bin_m;
  out["line_spacing_m"] = sim.image.line_spacing_m;
  // Heading of the flight, clockwise from north (scene y): lines run along it.
  double heading = rad_to_deg(std::atan2(sim.track.along_x, sim.track.along_y));
  if (heading < 0.0) heading += 360.0;
  out["heading_deg"] = heading;
  out["look_side"] = sim.track.look_side == LookSide::right ? "right" : "left";
  return out;
}

nlohmann::json sigma0_curves(const RunResult& run, const Sigma0Source& sigma0) {
  const auto* ppi = std::get_if<PpiRun>(&run.run);
  const SlarRun* slar = slar_image_run(run);
  if (ppi == nullptr && slar == nullptr) {
    throw InputError("request", "", "a streamed run keeps no categories in memory");
  }
  const std::vector<std::uint16_t>& categories =
      ppi != nullptr ? ppi->sim.categories : slar->sim.categories;
  const RadarBand band{run.radar.frequency_hz, run.radar.polarisation};
  std::vector<double> angles_deg(90);
  std::vector<double> angles_rad(90);
  for (int i = 0; i < 90; ++i) {
    angles_deg[i] = i;
    angles_rad[i] = i * kPi / 180.0;
  }
  nlohmann::json curves = nlohmann::json::array();
  for (const std::uint16_t c : categories) {
    if (!sigma0.has_category(c)) continue;
    std::vector<double> s(angles_rad.size());
    sigma0.sigma0_curve(c, angles_rad.data(), angles_rad.size(), band, s.data());
    nlohmann::json db = nlohmann::json::array();
    // sigma0 = 0 (no return) has no dB value: null, a gap in the chart.
    for (const double v : s) db.push_back(v > 0.0 ? nlohmann::json(10.0 * std::log10(v)) : nullptr);
    curves.push_back({{"category", c}, {"name", sigma0.category_name(c)}, {"sigma0_db", db}});
  }
  return {{"frequency_hz", band.frequency_hz}, {"angles_deg", angles_deg}, {"curves", curves}};
}

}  // namespace ris
