// The session on a raster scene: painting categories re-simulates, undoes,
// and saves as a scene GeoTIFF that reads back with the painted cells.
#include "ris/serve/session.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "ris/scene/scene_io.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

TEST(ServeSession, PaintUndoAndSaveARasterScene) {
  test::TempDir tmp;
  const Scene flat = Scene::flat(120, 200, 6.096, 0.0f, 1);
  write_scene_geotiff(flat, tmp / "flat.tif");
  ServeInputs in;
  in.scene_path = (tmp / "flat.tif").string();
  in.radar_path = std::string(test::data_dir()) + "/radars/seed-fig4-5.toml";
  in.data_dir = test::data_dir();
  in.out_dir = tmp / "out";
  Session session(in);
  EXPECT_FALSE(session.state()["scene"]["editable"].get<bool>());
  // Objects belong to scene descriptions.
  EXPECT_THROW(session.add_object(R"({"type": "box"})"), InputError);
  // A 10 x 5 rectangle of category 5.
  nlohmann::json r =
      session.paint(R"({"category": 5, "polygon": [[20, 10], [30, 10], [30, 15], [20, 15]]})");
  EXPECT_EQ(r["run"]["id"], 2);
  EXPECT_EQ(r["undo_depth"], 1);
  // A category the backscatter library lacks: the run refuses it, and the
  // scene stays as it was.
  EXPECT_THROW(session.paint(R"({"category": 999, "brush": [[50, 50]], "radius": 3})"), InputError);
  session.save_scene(R"({"name": "painted"})");
  const Scene back = read_scene(tmp / "out" / "painted.tif");
  EXPECT_EQ(std::count(back.category.begin(), back.category.end(), 5), 50);
  EXPECT_EQ(std::count(back.category.begin(), back.category.end(), 999), 0);
  r = session.undo();
  EXPECT_EQ(r["undo_depth"], 0);
  session.save_scene(R"({"name": "undone"})");
  const Scene undone = read_scene(tmp / "out" / "undone.tif");
  EXPECT_EQ(std::count(undone.category.begin(), undone.category.end(), 5), 0);
  EXPECT_THROW(session.undo(), InputError);
}

}  // namespace
}  // namespace ris
