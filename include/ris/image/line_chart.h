// A line chart as a PNG (cairo): axes with 1-2-5 ticks and numbers, axis
// labels with units, a title, and a legend; for plots such as sigma0 (dB)
// against incidence angle (`ris sigma0 --plot`).
//
// Lines are clipped to the plot area; y values below spec.y_floor are
// treated as missing (a gap in the line), so a model's "no return" floor does
// not stretch the axis. The file is written atomically.
//
// Example:
//   ris::ChartSpec spec{"Backscatter at 8.6 GHz", "incidence angle (deg)", "sigma0 (dB)"};
//   ris::ChartSeries s{"tall corn HH", {0, 10, 20}, {-6.4, -6.5, -6.7}, {214, 140, 30}};
//   ris::write_line_chart_png("sigma0.png", spec, {s});
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ris/image/category_palette.h"

namespace ris {

struct ChartSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
  Rgb8 colour;
  int dash = 0;  // 0 solid, 1 dashed, 2 dotted, 3 dash-dot
};

struct ChartSpec {
  std::string title;
  std::string x_label;  // with units: "incidence angle (deg)"
  std::string y_label;
  std::optional<double> x_min, x_max, y_min, y_max;  // default: from the data
  double y_floor = -1e300;                           // values at or below are missing
  int width_px = 1000;
  int height_px = 640;
};

// Tick positions from lo to hi with a 1-2-5 step giving about `target` ticks.
std::vector<double> nice_ticks(double lo, double hi, int target);

void write_line_chart_png(const std::filesystem::path& path, const ChartSpec& spec,
                          const std::vector<ChartSeries>& series);

}  // namespace ris
