// Contact sheets: layout arithmetic and the drawn panels read back.
#include "ris/image/contact_sheet.h"

#include <gtest/gtest.h>

#include <vector>

#include "ris/io/raster_io.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

TEST(ContactSheet, LayoutOfFivePanelsInThreeColumns) {
  const std::vector<std::uint8_t> img(40 * 100, 7);
  std::vector<ContactPanel> panels(5, ContactPanel{img.data(), 40, 100, "x"});
  ContactSheetStyle st;
  st.max_panel_px = 50;  // 100 rows -> scale 0.5: 20 x 50 panels
  const ContactSheetLayout l = contact_sheet_layout(panels, st);
  EXPECT_DOUBLE_EQ(l.scale, 0.5);
  EXPECT_EQ(l.columns, 3);
  EXPECT_EQ(l.rows, 2);
  // 16 + 3 (20 + 16) = 124; 40 + 2 (26 + 50 + 16) + 16 = 240
  EXPECT_EQ(l.width_px, 124);
  EXPECT_EQ(l.height_px, 240);
  EXPECT_EQ(l.x_px[4], 16 + 36);
  EXPECT_EQ(l.y_px[4], 40 + 92 + 26);
  // Small panels are not enlarged; fewer panels than columns narrow the grid.
  st.max_panel_px = 1000;
  const ContactSheetLayout one = contact_sheet_layout({panels[0]}, st);
  EXPECT_DOUBLE_EQ(one.scale, 1.0);
  EXPECT_EQ(one.columns, 1);
  EXPECT_EQ(one.width_px, 16 + 40 + 16);
  EXPECT_THROW(contact_sheet_layout({}, st), InputError);
}

TEST(ContactSheet, EachPanelIsDrawnWhereTheLayoutSays) {
  test::TempDir dir;
  const int cols = 30, rows = 80;
  std::vector<std::vector<std::uint8_t>> img;
  std::vector<ContactPanel> panels;
  for (int i = 0; i < 6; ++i) {
    img.emplace_back(static_cast<std::size_t>(cols * rows), static_cast<std::uint8_t>(20 + 40 * i));
  }
  for (int i = 0; i < 6; ++i) {
    panels.push_back(
        {img[static_cast<std::size_t>(i)].data(), cols, rows, "panel " + std::to_string(i)});
  }
  const ContactSheetStyle st;
  const ContactSheetLayout l = contact_sheet_layout(panels, st);
  const auto path = dir / "sheet.png";
  write_contact_sheet_png(path, "six panels", panels, st);
  const RasterF64 png = read_raster_f64(path);
  ASSERT_EQ(png.cols, l.width_px);
  ASSERT_EQ(png.rows, l.height_px);
  ASSERT_GE(png.bands, 1);
  const auto at = [&](int x, int y) {
    return png.data[static_cast<std::size_t>(y) * static_cast<std::size_t>(png.cols) +
                    static_cast<std::size_t>(x)];
  };
  int found = 0;
  for (std::size_t i = 0; i < panels.size(); ++i) {
    // Every pixel of the panel's box carries its grey; just outside is paper.
    bool all = true;
    for (int y = l.y_px[i]; y < l.y_px[i] + l.h_px[i]; ++y) {
      for (int x = l.x_px[i]; x < l.x_px[i] + l.w_px[i]; ++x)
        all = all && at(x, y) == 20 + 40 * int(i);
    }
    EXPECT_TRUE(all) << i;
    EXPECT_EQ(at(l.x_px[i] - 1, l.y_px[i] + 5), 255.0);
    EXPECT_EQ(at(l.x_px[i] + l.w_px[i], l.y_px[i] + 5), 255.0);
    found += all ? 1 : 0;
  }
  EXPECT_EQ(found, 6);
  // The label band above each panel has ink (dark text on white).
  double darkest = 255.0;
  for (int y = l.y_px[0] - st.label_px; y < l.y_px[0]; ++y) {
    for (int x = l.x_px[0]; x < l.x_px[0] + l.w_px[0]; ++x) darkest = std::min(darkest, at(x, y));
  }
  EXPECT_LT(darkest, 128.0);
}

}  // namespace
}  // namespace ris
