// A calibrated image's pixels with their local incidence and category on
// an acquisition's grid (see the header for the geometry and the area
// normalisation).
#include "ris/analysis/calibration_samples.h"

#include <fmt/format.h>
#include <omp.h>

#include <cmath>
#include <optional>

#include "ris/scene/geo_frame.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

// The radar pass of ris topo over the window, line-parallel.
void radar_pass(const Acquisition& acq, const EllipsoidalDem& dem, const GridWindow& w, int threads,
                std::vector<double>& lat, std::vector<double>& lon, std::vector<float>& incidence,
                std::vector<float>& local, std::vector<std::uint8_t>& mask) {
  const std::size_t np = w.size();
  lat.assign(np, 0.0);
  lon.assign(np, 0.0);
  incidence.assign(np, 0.0f);
  local.assign(np, 0.0f);
  mask.assign(np, 0);
  std::vector<float> height(np), geocentric(np), look(np), heading(np);
#pragma omp parallel num_threads(threads)
  {
    TopoLineScratch sc;
#pragma omp for schedule(dynamic, 1)
    for (int l = 0; l < w.lines; ++l) {
      const std::size_t o = static_cast<std::size_t>(l) * w.bins;
      const TopoLineView v{lat.data() + o,       lon.data() + o,        height.data() + o,
                           incidence.data() + o, geocentric.data() + o, local.data() + o,
                           look.data() + o,      heading.data() + o,    mask.data() + o};
      topo_radar_line(acq, dem, w, w.line0 + l, v, sc);
    }
  }
}

// The image's value at window pixel (l, b): the image is the window itself
// or the whole grid.
float image_value(const CalibrationImage& img, const GridWindow& w, bool full, int l, int b) {
  const int row = full ? w.line0 + l : l, col = full ? w.bin0 + b : b;
  return img.values[static_cast<std::size_t>(row) * img.cols + col];
}

// Category of the DEM posting nearest (lat, lon) (radians), read from the
// land cover at that posting; fallback outside the land cover or the DEM.
class CategoryLookup {
 public:
  CategoryLookup(const EllipsoidalDem& dem, const CalibrationSampleOptions& o) : dem_(dem), o_(o) {
    if (o.land_cover == nullptr) return;
    if (o.land_cover->crs_wkt.empty())
      throw InputError(o.land_cover_source, "--land-cover",
                       "the land cover has no CRS: expected a georeferenced scene or raster");
    frame_.emplace(o.land_cover->crs_wkt, o.land_cover_source);
  }
  std::uint16_t at(double lat_deg, double lon_deg) const {
    if (!frame_) return o_.fallback;
    const double r = std::round((deg_to_rad(lat_deg) - dem_.lat0_rad) / dem_.dlat_rad);
    const double c = std::round((deg_to_rad(lon_deg) - dem_.lon0_rad) / dem_.dlon_rad);
    if (!(r >= 0 && c >= 0 && r < dem_.all_rows() && c < dem_.all_cols())) return o_.fallback;
    const auto [x, y] = frame_->scene_from_lonlat(rad_to_deg(dem_.lon0_rad + c * dem_.dlon_rad),
                                                  rad_to_deg(dem_.lat0_rad + r * dem_.dlat_rad));
    const Scene& s = *o_.land_cover;
    const auto [col_f, row_f] = s.grid_from_world(x, y);
    const int sr = static_cast<int>(std::floor(row_f)), sc = static_cast<int>(std::floor(col_f));
    if (!s.contains(sr, sc) || s.valid[s.index(sr, sc)] == 0) return o_.fallback;
    return s.category[s.index(sr, sc)];
  }

 private:
  const EllipsoidalDem& dem_;
  const CalibrationSampleOptions& o_;
  std::optional<GeoFrame> frame_;
};

// Pixels within edge_px of a pixel of another category (or of one without
// a ground point) are mixed: category -1.
std::int64_t erode_boundaries(const GridWindow& w, int edge_px,
                              const std::vector<std::int32_t>& raw,
                              std::vector<std::int32_t>& out) {
  std::int64_t n = 0;
  for (int l = 0; l < w.lines; ++l) {
    for (int b = 0; b < w.bins; ++b) {
      const std::size_t i = static_cast<std::size_t>(l) * w.bins + b;
      if (out[i] < 0) continue;
      bool mixed = false;
      for (int dl = -edge_px; dl <= edge_px && !mixed; ++dl) {
        for (int db = -edge_px; db <= edge_px && !mixed; ++db) {
          const int ll = l + dl, bb = b + db;
          if (ll < 0 || bb < 0 || ll >= w.lines || bb >= w.bins) continue;
          const std::int32_t c = raw[static_cast<std::size_t>(ll) * w.bins + bb];
          mixed = c != raw[i];
        }
      }
      if (mixed) out[i] = -1, ++n;
    }
  }
  return n;
}

}  // namespace

CalibrationSamples acquisition_calibration_samples(const Acquisition& acq,
                                                   const EllipsoidalDem& dem,
                                                   const CalibrationImage& image,
                                                   const CalibrationSampleOptions& options) {
  CalibrationSamples s;
  const GridWindow w = dem_window(acq, dem);
  if (w.lines == 0 || w.bins == 0)
    throw InputError(dem.source, "--dem", "the DEM does not cover the acquisition's radar grid");
  s.window = w;
  const RadarGrid& g = acq.grid;
  if (image.cols == w.bins && image.rows == w.lines) {
    s.image_was_full_grid = false;
  } else if (image.cols == g.bins && image.rows == g.lines) {
    s.image_was_full_grid = true;
  } else {
    throw InputError(
        image.source, "",
        fmt::format("the image is {} x {} pixels (bins x lines); expected the DEM's window of the "
                    "acquisition's grid, {} x {} (lines {}.., bins {}.., as ris simulate "
                    "--acquisition writes it), or the whole grid, {} x {}",
                    image.cols, image.rows, w.bins, w.lines, w.line0, w.bin0, g.bins, g.lines));
  }
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
  std::vector<double> lat, lon;
  std::vector<float> incidence;
  std::vector<std::uint8_t> mask;
  radar_pass(acq, dem, w, threads, lat, lon, incidence, s.local_incidence_deg, mask);

  const CategoryLookup lookup(dem, options);
  const std::size_t np = w.size();
  s.sigma0.assign(np, std::nanf(""));
  s.category.assign(np, -1);
  std::vector<std::int32_t> raw(np, -1);
  for (int l = 0; l < w.lines; ++l) {
    for (int b = 0; b < w.bins; ++b) {
      const std::size_t i = static_cast<std::size_t>(l) * w.bins + b;
      const double tl = s.local_incidence_deg[i], te = incidence[i];
      if (!std::isfinite(tl) || !std::isfinite(te) || !std::isfinite(lat[i])) {
        ++s.no_ground;
        continue;
      }
      raw[i] = lookup.at(lat[i], lon[i]);
      if (mask[i] != kMaskNone) {
        ++s.layover_shadow;
        continue;
      }
      const float v = image_value(image, w, s.image_was_full_grid, l, b);
      if (!(v > 0.0f) || !std::isfinite(v)) {
        ++s.no_image_data;
        continue;
      }
      // sigma0 per unit true area (header): beta0 sin(theta_l), or the
      // ellipsoid-referenced sigma0 times sin(theta_l) / sin(theta_e).
      const double sl = std::sin(deg_to_rad(tl));
      const double f =
          image.quantity == CalibratedQuantity::beta0 ? sl : sl / std::sin(deg_to_rad(te));
      s.sigma0[i] = static_cast<float>(v * f);
      s.category[i] = raw[i];
    }
  }
  s.boundary = erode_boundaries(w, options.edge_px, raw, s.category);
  return s;
}

}  // namespace ris
