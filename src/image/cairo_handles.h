// Internal: owning handles for cairo's surface and context (the drawings in
// contact_sheet.cpp, line_chart.cpp and scene_preview.cpp), so every return path frees them.
#pragma once

#include <cairo.h>

namespace ris::detail {

struct CairoSurface {
  cairo_surface_t* s = nullptr;
  ~CairoSurface() {
    if (s != nullptr) cairo_surface_destroy(s);
  }
};

struct CairoContext {
  cairo_t* c = nullptr;
  ~CairoContext() {
    if (c != nullptr) cairo_destroy(c);
  }
};

}  // namespace ris::detail
