#include "ris/image/scene_preview.h"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "image/cairo_handles.h"
#include "ris/image/category_palette.h"
#include "ris/image/hillshade.h"
#include "ris/io/atomic_file.h"
#include "ris/scene/scene_stats.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {
// A "nice" length (1, 2 or 5 times a power of ten) no longer than max_m.
double nice_length(double max_m) {
  const double p = std::pow(10.0, std::floor(std::log10(max_m)));
  for (double m : {5.0, 2.0, 1.0}) {
    if (m * p <= max_m) return m * p;
  }
  return p;
}
}  // namespace

double preview_contour_interval_m(const ScenePreviewOptions& opt, double min_elevation_m,
                                  double max_elevation_m) {
  if (opt.contour_interval_m > 0.0) return opt.contour_interval_m;
  const double range_m = max_elevation_m - min_elevation_m;
  if (opt.contour_interval_m < 0.0 || !(range_m > 0.0) || !std::isfinite(range_m)) return 0.0;
  // The smallest 1-2-5 interval giving at most 10 levels.
  const double p = std::pow(10.0, std::floor(std::log10(range_m / 10.0)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (range_m / (m * p) <= 10.0) return m * p;
  }
  return 10.0 * p;
}

std::vector<std::uint8_t> shaded_category_rgb(const Scene& scene, const ScenePreviewOptions& opt) {
  const std::vector<float> shade = hillshade(scene, opt.light_azimuth_deg, opt.light_altitude_deg);
  // Flat ground shades to sin(altitude); dividing by it keeps flat cells at
  // their category colour. A floor of 0.25 keeps shaded slopes readable.
  const double flat = std::sin(deg_to_rad(opt.light_altitude_deg));
  std::vector<std::uint8_t> rgb(scene.size() * 3);
  for (std::size_t i = 0; i < scene.size(); ++i) {
    Rgb8 c = kNoDataColour;
    double k = 1.0;
    if (scene.valid[i]) {
      c = category_colour(scene.category[i]);
      k = 0.25 + 0.75 * static_cast<double>(shade[i]) / flat;
    }
    auto scaled = [k](std::uint8_t v) {
      return static_cast<std::uint8_t>(std::clamp(std::lround(v * k), 0L, 255L));
    };
    rgb[3 * i] = scaled(c.r);
    rgb[3 * i + 1] = scaled(c.g);
    rgb[3 * i + 2] = scaled(c.b);
  }
  // Contours: darken the higher cell of each east or south neighbour pair
  // whose elevations lie in different interval bands.
  const SceneStats st = scene_stats(scene);
  const double interval_m = preview_contour_interval_m(opt, st.min_elevation_m, st.max_elevation_m);
  if (interval_m > 0.0) {
    auto band = [&](std::size_t i) { return std::floor(scene.elevation_m[i] / interval_m); };
    std::vector<std::uint8_t> on(scene.size(), 0);
    for (int r = 0; r < scene.rows; ++r) {
      for (int c = 0; c < scene.cols; ++c) {
        const std::size_t i = scene.index(r, c);
        if (!scene.valid[i]) continue;
        for (const auto& [nr, nc] : {std::pair{r, c + 1}, std::pair{r + 1, c}}) {
          if (!scene.contains(nr, nc)) continue;
          const std::size_t j = scene.index(nr, nc);
          if (!scene.valid[j] || band(i) == band(j)) continue;
          on[scene.elevation_m[i] > scene.elevation_m[j] ? i : j] = 1;
        }
      }
    }
    for (std::size_t i = 0; i < scene.size(); ++i) {
      if (!on[i]) continue;
      for (int b = 0; b < 3; ++b) {
        auto& v = rgb[3 * i + static_cast<std::size_t>(b)];
        v = static_cast<std::uint8_t>(v * 0.45);
      }
    }
  }
  return rgb;
}

namespace {

using detail::CairoContext;
using detail::CairoSurface;

void text(cairo_t* cr, double x, double y, double size, const std::string& s, bool bold = false) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
  cairo_move_to(cr, x, y);
  cairo_show_text(cr, s.c_str());
}

// The map: average whole blocks of `down` cells, or repeat each cell `up`
// times, into `map` (map_w x map_h, made here).
void fill_map_surface(const Scene& scene, const std::vector<std::uint8_t>& rgb, int down, int up,
                      int map_w, int map_h, CairoSurface& map) {
  map.s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, map_w, map_h);
  cairo_surface_flush(map.s);
  unsigned char* data = cairo_image_surface_get_data(map.s);
  const int stride = cairo_image_surface_get_stride(map.s);
  const int mc = scene.cols / down;
  const int mr = scene.rows / down;
  for (int r = 0; r < mr; ++r) {
    for (int c = 0; c < mc; ++c) {
      double sum[3] = {0, 0, 0};
      for (int i = 0; i < down; ++i) {
        for (int j = 0; j < down; ++j) {
          const std::size_t k = 3 * scene.index(r * down + i, c * down + j);
          for (int b = 0; b < 3; ++b) sum[b] += rgb[k + static_cast<std::size_t>(b)];
        }
      }
      const double n = double(down) * down;
      const auto px = (static_cast<std::uint32_t>(std::lround(sum[0] / n)) << 16) |
                      (static_cast<std::uint32_t>(std::lround(sum[1] / n)) << 8) |
                      static_cast<std::uint32_t>(std::lround(sum[2] / n));
      for (int i = 0; i < up; ++i) {
        auto* row = reinterpret_cast<std::uint32_t*>(
            data + static_cast<std::ptrdiff_t>(r * up + i) * stride);
        for (int j = 0; j < up; ++j) row[c * up + j] = px;
      }
    }
  }
  cairo_surface_mark_dirty(map.s);
}

// Scale bar under the map: a round length about a quarter of the width.
void draw_scale_bar(cairo_t* cr, double m_per_px, int margin, int map_w, int map_h) {
  const double bar_m = nice_length(map_w * m_per_px / 4.0);
  const double bar_px = bar_m / m_per_px;
  const double by = margin + map_h + 22;
  cairo_set_line_width(cr, 3.0);
  cairo_move_to(cr, margin, by);
  cairo_line_to(cr, margin + bar_px, by);
  cairo_stroke(cr);
  const std::string bar_label =
      bar_m >= 1000.0 ? fmt::format("{:g} km", bar_m / 1000.0) : fmt::format("{:g} m", bar_m);
  text(cr, margin, by + 18, 12,
       fmt::format("{}  ({:g} ft)", bar_label, std::round(bar_m / kFeetToMetres)));
}

// North arrow at the map's top-right corner (row 0 is north).
void draw_north_arrow(cairo_t* cr, int margin, int map_w) {
  const double ax = margin + map_w - 20;
  const double ay = margin + 14;
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_move_to(cr, ax, ay);
  cairo_line_to(cr, ax - 7, ay + 18);
  cairo_line_to(cr, ax + 7, ay + 18);
  cairo_close_path(cr);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  text(cr, ax - 5, ay + 34, 13, "N", true);
}

// The legend from (x, y): title, grid, elevations, lighting, contours, no
// data, then the categories (at most 24) with their share of the cells.
void draw_legend(cairo_t* cr, const Scene& scene, const SceneStats& st,
                 const ScenePreviewOptions& opt, double x, double y, int line_h) {
  cairo_set_source_rgb(cr, 0, 0, 0);
  text(cr, x, y, 16, opt.title.empty() ? "scene" : opt.title, true);
  y += line_h + 4;
  const double ft = kFeetToMetres;
  text(cr, x, y, 12, fmt::format("{} columns x {} rows", scene.cols, scene.rows));
  y += line_h;
  text(cr, x, y, 12,
       fmt::format("cell {:g} m ({:g} ft)", scene.dx_m, std::round(scene.dx_m / ft * 100) / 100));
  y += line_h;
  text(cr, x, y, 12,
       fmt::format("elevation {:.0f} .. {:.0f} m ({:.0f} .. {:.0f} ft)", st.min_elevation_m,
                   st.max_elevation_m, st.min_elevation_m / ft, st.max_elevation_m / ft));
  y += line_h;
  text(cr, x, y, 12,
       fmt::format("relief lit from {:g} deg, {:g} deg high", opt.light_azimuth_deg,
                   opt.light_altitude_deg));
  y += line_h;
  const double interval_m = preview_contour_interval_m(opt, st.min_elevation_m, st.max_elevation_m);
  if (interval_m > 0.0) {
    text(cr, x, y, 12,
         fmt::format("contours every {:g} m ({:.4g} ft)", interval_m, interval_m / ft));
    y += line_h;
  }
  if (st.nodata_cells > 0) {
    text(cr, x, y, 12, fmt::format("no data: {} cells", st.nodata_cells));
    y += line_h;
  }
  y += 6;
  text(cr, x, y, 13, "category (share of cells)", true);
  y += line_h;
  std::size_t shown = 0;
  for (const auto& [id, n] : st.category_counts) {
    if (shown == 24) {
      text(cr, x, y, 12, fmt::format("... and {} more", st.category_counts.size() - shown));
      break;
    }
    const Rgb8 c = category_colour(id);
    cairo_set_source_rgb(cr, c.r / 255.0, c.g / 255.0, c.b / 255.0);
    cairo_rectangle(cr, x, y - 12, 22, 14);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
    cairo_stroke(cr);
    const auto name = opt.category_names.find(id);
    const std::string label = name != opt.category_names.end()
                                  ? fmt::format("{} {}", id, name->second)
                                  : fmt::format("{}", id);
    text(cr, x + 30, y, 12,
         fmt::format("{}  ({:.1f}%)", label,
                     100.0 * static_cast<double>(n) / static_cast<double>(st.valid_cells)));
    y += line_h;
    ++shown;
  }
}

}  // namespace

void write_scene_preview(const Scene& scene, const std::filesystem::path& path,
                         const ScenePreviewOptions& opt) {
  scene.validate(path.string());
  const std::vector<std::uint8_t> rgb = shaded_category_rgb(scene, opt);

  // Map size: average whole blocks of `down` cells, or repeat each cell `up` times.
  const int longer = std::max(scene.cols, scene.rows);
  const int down = std::max(1, (longer + opt.max_map_px - 1) / std::max(1, opt.max_map_px));
  const int up = down > 1 ? 1 : std::max(1, opt.min_map_px / longer);
  const int map_w = (scene.cols / down) * up;
  const int map_h = (scene.rows / down) * up;
  RIS_CHECK(map_w > 0 && map_h > 0);

  const SceneStats st = scene_stats(scene);
  const int margin = 16;
  const int legend_w = 300;
  const int line_h = 20;
  const int legend_lines =
      9 + static_cast<int>(std::min<std::size_t>(st.category_counts.size(), 24));
  const int width = margin + map_w + margin + legend_w;
  const int height = std::max(margin + map_h + 56, margin + legend_lines * line_h + margin);

  CairoSurface map;
  fill_map_surface(scene, rgb, down, up, map_w, map_h, map);

  CairoSurface page;
  page.s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  CairoContext ctx;
  ctx.c = cairo_create(page.s);
  cairo_t* cr = ctx.c;
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_surface(cr, map.s, margin, margin);
  cairo_paint(cr);
  cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, margin - 0.5, margin - 0.5, map_w + 1, map_h + 1);
  cairo_stroke(cr);

  draw_scale_bar(cr, scene.dx_m * down / up, margin, map_w, map_h);
  draw_north_arrow(cr, margin, map_w);
  draw_legend(cr, scene, st, opt, margin + map_w + margin, margin + 14, line_h);
  cairo_surface_flush(page.s);

  AtomicPath out(path);
  if (cairo_surface_write_to_png(page.s, out.temp_path().c_str()) != CAIRO_STATUS_SUCCESS) {
    throw InputError(path.string(), "", "cannot write the PNG (is the folder writable?)");
  }
  out.commit();
}

}  // namespace ris
