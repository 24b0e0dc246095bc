// A contact sheet: several greytone images side by side in a grid, each with
// a label above it and a title at the top (cairo, fonts DejaVu Sans), like the
// seed's figure 7 (one scene at six frequency/polarisation pairs).
//
// Panels are drawn at one common scale so that equal image sizes stay equal:
// the largest panel is fitted into max_panel_px (never enlarged), with
// nearest-neighbour sampling so pixels stay sharp. The file is written
// atomically.
//
// Example:
//   ris::ContactPanel p{grey.data(), bins, lines, "8.6 GHz HH"};
//   ris::write_contact_sheet_png("sheet.png", "ku-geometric", {p}, {});
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ris {

struct ContactPanel {
  const std::uint8_t* grey = nullptr;  // rows x cols, row-major
  int cols = 0;
  int rows = 0;
  std::string label;
};

struct ContactSheetStyle {
  int columns = 3;         // panels per row (fewer when there are fewer panels)
  int max_panel_px = 360;  // the largest panel's longer side, at most
  int margin_px = 16;      // around and between panels
  int label_px = 26;       // label band above each panel
  int title_px = 40;       // title band at the top
  std::uint8_t background = 255;
};

// Where panel i goes: top-left corner and drawn size, in pixels.
struct ContactSheetLayout {
  int width_px = 0, height_px = 0;
  int columns = 0, rows = 0;
  double scale = 1.0;
  std::vector<int> x_px, y_px, w_px, h_px;
};

ContactSheetLayout contact_sheet_layout(const std::vector<ContactPanel>& panels,
                                        const ContactSheetStyle& style);

// Throws InputError (key "panels") with no panels or an empty panel.
void write_contact_sheet_png(const std::filesystem::path& path, const std::string& title,
                             const std::vector<ContactPanel>& panels,
                             const ContactSheetStyle& style);

}  // namespace ris
