#include "ris/image/line_chart.h"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "image/cairo_handles.h"
#include "ris/io/atomic_file.h"
#include "ris/util/error.h"

namespace ris {

std::vector<double> nice_ticks(double lo, double hi, int target) {
  std::vector<double> ticks;
  if (!(hi > lo) || target < 1) return ticks;
  const double raw = (hi - lo) / target;
  const double mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * mag;
    if (step >= raw) break;
  }
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double t = first; t <= hi + 1e-9 * step; t += step) {
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  }
  return ticks;
}

namespace {

using Surface = detail::CairoSurface;
using Context = detail::CairoContext;

void font(cairo_t* cr, double size, bool bold = false) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size);
}

// Draws text with its reference point aligned: ax, ay in {0, 0.5, 1} of its
// extent (0, 0 = left baseline-top corner).
void text_at(cairo_t* cr, double x, double y, const std::string& s, double ax, double ay) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, x - e.x_bearing - ax * e.width, y - e.y_bearing - ay * e.height);
  cairo_show_text(cr, s.c_str());
}

std::string tick_label(double v, double step) {
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  return fmt::format("{:.{}f}", v, decimals);
}

void set_dash(cairo_t* cr, int dash) {
  static const double dashed[] = {9.0, 5.0};
  static const double dotted[] = {2.0, 4.0};
  static const double dash_dot[] = {9.0, 4.0, 2.0, 4.0};
  switch (dash % 4) {
    case 1:
      cairo_set_dash(cr, dashed, 2, 0.0);
      break;
    case 2:
      cairo_set_dash(cr, dotted, 2, 0.0);
      break;
    case 3:
      cairo_set_dash(cr, dash_dot, 4, 0.0);
      break;
    default:
      cairo_set_dash(cr, nullptr, 0, 0.0);
      break;
  }
}

}  // namespace

void write_line_chart_png(const std::filesystem::path& path, const ChartSpec& spec,
                          const std::vector<ChartSeries>& series) {
  // Data range (missing values excluded), then padded to whole ticks.
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const ChartSeries& s : series) {
    RIS_CHECK(s.x.size() == s.y.size());
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i]) || s.y[i] <= spec.y_floor) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  }
  if (x0 > x1) {
    throw InputError(path.string(), "",
                     "nothing to plot: every value is missing or below the floor");
  }
  x0 = spec.x_min.value_or(x0);
  x1 = spec.x_max.value_or(x1);
  y0 = spec.y_min.value_or(y0);
  y1 = spec.y_max.value_or(y1);
  if (x1 <= x0) x1 = x0 + 1.0;
  if (y1 <= y0) {
    y0 -= 1.0;
    y1 += 1.0;
  }
  std::vector<double> yt = nice_ticks(y0, y1, 8);
  const double ystep = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  if (!spec.y_min) y0 = std::floor(y0 / ystep) * ystep;
  if (!spec.y_max) y1 = std::ceil(y1 / ystep) * ystep;
  yt = nice_ticks(y0, y1, 8);
  const std::vector<double> xt = nice_ticks(x0, x1, 9);
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1.0;

  // Layout: the plot area on the left, the legend in a column on the right.
  const double W = spec.width_px, H = spec.height_px;
  const double legend_w = 250.0;
  const double left = 78.0, right = W - legend_w - 20.0, top = 52.0, bottom = H - 62.0;
  const auto px = [&](double x) { return left + (x - x0) / (x1 - x0) * (right - left); };
  const auto py = [&](double y) { return bottom - (y - y0) / (y1 - y0) * (bottom - top); };

  Surface surf;
  surf.s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, spec.width_px, spec.height_px);
  Context ctx;
  ctx.c = cairo_create(surf.s);
  cairo_t* cr = ctx.c;
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);

  // Grid and ticks.
  cairo_set_line_width(cr, 1.0);
  font(cr, 13);
  for (double t : xt) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, std::round(px(t)) + 0.5, top);
    cairo_line_to(cr, std::round(px(t)) + 0.5, bottom);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, std::round(px(t)) + 0.5, bottom);
    cairo_line_to(cr, std::round(px(t)) + 0.5, bottom + 5);
    cairo_stroke(cr);
    text_at(cr, px(t), bottom + 9, tick_label(t, xstep), 0.5, 0.0);
  }
  for (double t : yt) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, left, std::round(py(t)) + 0.5);
    cairo_line_to(cr, right, std::round(py(t)) + 0.5);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, left - 5, std::round(py(t)) + 0.5);
    cairo_line_to(cr, left, std::round(py(t)) + 0.5);
    cairo_stroke(cr);
    text_at(cr, left - 9, py(t), tick_label(t, ystep), 1.0, 0.5);
  }
  cairo_rectangle(cr, left + 0.5, top + 0.5, right - left, bottom - top);
  cairo_stroke(cr);

  // Axis labels and title.
  font(cr, 15);
  text_at(cr, 0.5 * (left + right), H - 14, spec.x_label, 0.5, 1.0);
  cairo_save(cr);
  cairo_translate(cr, 18, 0.5 * (top + bottom));
  cairo_rotate(cr, -M_PI / 2.0);
  text_at(cr, 0, 0, spec.y_label, 0.5, 0.5);
  cairo_restore(cr);
  font(cr, 18, true);
  text_at(cr, 0.5 * (left + right), 16, spec.title, 0.5, 0.0);

  // Curves, clipped to the plot area; missing values break the line.
  cairo_save(cr);
  cairo_rectangle(cr, left, top, right - left, bottom - top);
  cairo_clip(cr);
  cairo_set_line_width(cr, 2.2);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const ChartSeries& s : series) {
    cairo_set_source_rgb(cr, s.colour.r / 255.0, s.colour.g / 255.0, s.colour.b / 255.0);
    set_dash(cr, s.dash);
    bool pen_down = false;
    for (size_t i = 0; i < s.x.size(); ++i) {
      if (!std::isfinite(s.y[i]) || s.y[i] <= spec.y_floor) {
        pen_down = false;
        continue;
      }
      if (pen_down) {
        cairo_line_to(cr, px(s.x[i]), py(s.y[i]));
      } else {
        cairo_move_to(cr, px(s.x[i]), py(s.y[i]));
        pen_down = true;
      }
    }
    cairo_stroke(cr);
  }
  cairo_restore(cr);
  set_dash(cr, 0);

  // Legend.
  font(cr, 13);
  const double lx = right + 22.0;
  const double row_h =
      std::min(22.0, (bottom - top) / static_cast<double>(std::max<size_t>(1, series.size())));
  for (size_t i = 0; i < series.size(); ++i) {
    const ChartSeries& s = series[i];
    const double y = top + 8.0 + row_h * static_cast<double>(i);
    cairo_set_source_rgb(cr, s.colour.r / 255.0, s.colour.g / 255.0, s.colour.b / 255.0);
    cairo_set_line_width(cr, 2.5);
    set_dash(cr, s.dash);
    cairo_move_to(cr, lx, y);
    cairo_line_to(cr, lx + 34, y);
    cairo_stroke(cr);
    set_dash(cr, 0);
    cairo_set_source_rgb(cr, 0, 0, 0);
    text_at(cr, lx + 42, y, s.label, 0.0, 0.5);
  }

  cairo_surface_flush(surf.s);
  AtomicPath out(path);
  if (cairo_surface_write_to_png(surf.s, out.temp_path().c_str()) != CAIRO_STATUS_SUCCESS) {
    throw InputError(path.string(), "", "cannot write the PNG (is the folder writable?)");
  }
  out.commit();
}

}  // namespace ris
