// The linked zoom's regions (ris/serve/view_link.h): a scene region maps to
// the slant pixels its cells geocode into (the inspector's own mapping), and
// that slant region maps back to a scene region holding the first; bad
// regions are refused.
#include "ris/serve/view_link.h"

#include <gtest/gtest.h>

#include "ris/serve/session.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

TEST(ViewLink, SceneAndSlantRegionsMapThroughTheGeocoding) {
  ServeInputs in;
  in.scene_path = std::string(test::data_dir()) + "/scenes/ku-geometric.toml";
  in.radar_path = std::string(test::data_dir()) + "/radars/seed-fig4-5.toml";
  in.data_dir = test::data_dir();
  test::TempDir tmp;
  in.out_dir = tmp / "out";
  Session session(in);
  const nlohmann::json run = session.state()["run"];
  const int lines = run["lines"], bins = run["bins"];
  // Cells 400..460 x 300..340 (flat crop land between the solids).
  const nlohmann::json slant = session.link("scene", 400, 300, 460, 340);
  EXPECT_EQ(slant["view"], "slant");
  const double b0 = slant["x0"], l0 = slant["y0"], b1 = slant["x1"], l1 = slant["y1"];
  EXPECT_LT(b1 - b0, 0.5 * bins);
  EXPECT_LT(l1 - l0, 0.5 * lines);
  for (const auto& [c, r] : {std::pair{400, 300}, {459, 339}, {430, 320}}) {
    const nlohmann::json cell = session.inspect("scene", c, r);
    ASSERT_TRUE(cell.contains("pixel")) << cell.dump();
    const int bin = cell["pixel"]["bin"], line = cell["pixel"]["line"];
    EXPECT_GE(bin, b0);
    EXPECT_LT(bin, b1);
    EXPECT_GE(line, l0);
    EXPECT_LT(line, l1);
  }
  // Back: the scene region of those pixels holds the cells asked for.
  const nlohmann::json back = session.link("slant", b0, l0, b1, l1);
  EXPECT_EQ(back["view"], "scene");
  EXPECT_LE(back["x0"].get<double>(), 400.0);
  EXPECT_GE(back["x1"].get<double>(), 460.0);
  EXPECT_LE(back["y0"].get<double>(), 300.0);
  EXPECT_GE(back["y1"].get<double>(), 340.0);
  // And not much more (a sampling step of 4 cells and a pixel's footprint).
  EXPECT_LT(back["x1"].get<double>() - back["x0"].get<double>(), 60 + 40);
  EXPECT_LT(back["y1"].get<double>() - back["y0"].get<double>(), 40 + 40);

  EXPECT_THROW(session.link("ground", 0, 0, 10, 10), InputError);
  EXPECT_THROW(session.link("scene", 10, 10, 5, 20), InputError);
  EXPECT_THROW(session.link("scene", -500, -500, -400, -400), InputError);
  EXPECT_THROW(session.link("slant", 1e6, 1e6, 2e6, 2e6), InputError);
}

}  // namespace
}  // namespace ris
