#include "ris/image/contact_sheet.h"

#include <cairo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "image/cairo_handles.h"
#include "ris/io/atomic_file.h"
#include "ris/util/error.h"

namespace ris {

ContactSheetLayout contact_sheet_layout(const std::vector<ContactPanel>& panels,
                                        const ContactSheetStyle& style) {
  if (panels.empty()) throw InputError("", "panels", "a contact sheet needs at least one panel");
  int longest = 0;
  for (const ContactPanel& p : panels) {
    if (p.cols <= 0 || p.rows <= 0 || p.grey == nullptr) {
      throw InputError("", "panels", fmt::format("panel '{}' is empty", p.label));
    }
    longest = std::max({longest, p.cols, p.rows});
  }
  ContactSheetLayout l;
  l.scale = std::min(1.0, double(std::max(style.max_panel_px, 1)) / double(longest));
  int cell_w = 0, cell_h = 0;
  for (const ContactPanel& p : panels) {
    l.w_px.push_back(std::max(1, static_cast<int>(std::lround(p.cols * l.scale))));
    l.h_px.push_back(std::max(1, static_cast<int>(std::lround(p.rows * l.scale))));
    cell_w = std::max(cell_w, l.w_px.back());
    cell_h = std::max(cell_h, l.h_px.back());
  }
  const int n = static_cast<int>(panels.size());
  l.columns = std::clamp(style.columns, 1, n);
  l.rows = (n + l.columns - 1) / l.columns;
  l.width_px = style.margin_px + l.columns * (cell_w + style.margin_px);
  l.height_px =
      style.title_px + l.rows * (style.label_px + cell_h + style.margin_px) + style.margin_px;
  for (int i = 0; i < n; ++i) {
    const int c = i % l.columns;
    const int r = i / l.columns;
    const size_t k = static_cast<size_t>(i);
    l.x_px.push_back(style.margin_px + c * (cell_w + style.margin_px) + (cell_w - l.w_px[k]) / 2);
    l.y_px.push_back(style.title_px + r * (style.label_px + cell_h + style.margin_px) +
                     style.label_px);
  }
  return l;
}

namespace {

using Surface = detail::CairoSurface;
using Context = detail::CairoContext;

void centred_text(cairo_t* cr, double cx, double baseline_y, const std::string& s) {
  cairo_text_extents_t e;
  cairo_text_extents(cr, s.c_str(), &e);
  cairo_move_to(cr, cx - e.x_bearing - 0.5 * e.width, baseline_y);
  cairo_show_text(cr, s.c_str());
}

}  // namespace

void write_contact_sheet_png(const std::filesystem::path& path, const std::string& title,
                             const std::vector<ContactPanel>& panels,
                             const ContactSheetStyle& style) {
  const ContactSheetLayout l = contact_sheet_layout(panels, style);
  Surface surf;
  surf.s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, l.width_px, l.height_px);
  Context ctx;
  ctx.c = cairo_create(surf.s);
  cairo_t* cr = ctx.c;
  if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
    throw InputError(path.string(), "", "cannot create the drawing surface");
  }
  const double bg = style.background / 255.0;
  cairo_set_source_rgb(cr, bg, bg, bg);
  cairo_paint(cr);

  // Text first; the panels' pixels are then written straight into the
  // surface (nearest-neighbour at the common scale).
  const double fg = bg > 0.5 ? 0.0 : 1.0;
  cairo_set_source_rgb(cr, fg, fg, fg);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_BOLD);
  // The title shrinks to fit a narrow sheet.
  double title_size = 0.5 * style.title_px;
  cairo_set_font_size(cr, title_size);
  cairo_text_extents_t te;
  cairo_text_extents(cr, title.c_str(), &te);
  const double room = l.width_px - 2.0 * style.margin_px;
  if (te.width > room && te.width > 0.0) title_size *= room / te.width;
  cairo_set_font_size(cr, title_size);
  centred_text(cr, 0.5 * l.width_px, 0.72 * style.title_px, title);
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 0.6 * style.label_px);
  for (size_t i = 0; i < panels.size(); ++i) {
    centred_text(cr, l.x_px[i] + 0.5 * l.w_px[i], l.y_px[i] - 0.3 * style.label_px,
                 panels[i].label);
  }
  cairo_surface_flush(surf.s);
  unsigned char* data = cairo_image_surface_get_data(surf.s);
  const int stride = cairo_image_surface_get_stride(surf.s);
  for (size_t i = 0; i < panels.size(); ++i) {
    const ContactPanel& p = panels[i];
    for (int y = 0; y < l.h_px[i]; ++y) {
      const int sr = std::min(p.rows - 1, static_cast<int>((y + 0.5) / l.scale));
      auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<size_t>(l.y_px[i] + y) *
                                                              static_cast<size_t>(stride));
      for (int x = 0; x < l.w_px[i]; ++x) {
        const int sc = std::min(p.cols - 1, static_cast<int>((x + 0.5) / l.scale));
        const std::uint32_t g =
            p.grey[static_cast<size_t>(sr) * static_cast<size_t>(p.cols) + static_cast<size_t>(sc)];
        row[l.x_px[i] + x] = 0xff000000u | (g << 16) | (g << 8) | g;
      }
    }
  }
  cairo_surface_mark_dirty(surf.s);

  AtomicPath out(path);
  if (cairo_surface_write_to_png(surf.s, out.temp_path().c_str()) != CAIRO_STATUS_SUCCESS) {
    throw InputError(path.string(), "", "cannot write the contact sheet PNG");
  }
  out.commit();
}

}  // namespace ris
