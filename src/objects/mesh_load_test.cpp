// Mesh loading through Assimp: a good file, and each refusal.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "ris/objects/mesh_load.h"
#include "ris/util/error.h"

namespace ris {
namespace {

std::string write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("ris_mesh_" + name);
  std::ofstream(path) << text;
  return path.string();
}

const char* kQuadObj = "v 0 -1 -1\nv 0 1 -1\nv 0 1 1\nv 0 -1 1\nf 1 2 3 4\n";

TEST(MeshLoad, ReadsObjTriangulatesAndPlaces) {
  const TriangleMesh m =
      load_mesh(write_file("quad.obj", kQuadObj), {.scale = 2.0, .position_m = {10.0, 0.0, 0.0}});
  ASSERT_EQ(m.triangles.size(), 2u);
  for (const Vec3& v : m.vertices) {
    EXPECT_DOUBLE_EQ(v.x, 10.0);
    EXPECT_DOUBLE_EQ(std::abs(v.y), 2.0);
  }
}

TEST(MeshLoad, ReadsAsciiStl) {
  const std::string stl =
      "solid t\nfacet normal 1 0 0\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 0 0 1\n"
      "endloop\nendfacet\nendsolid t\n";
  EXPECT_EQ(load_mesh(write_file("tri.stl", stl), {}).triangles.size(), 1u);
}

void expect_refused(const std::string& path, const std::string& what, std::size_t cap = 1000) {
  try {
    (void)load_mesh(path, {}, cap);
    ADD_FAILURE() << "accepted " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

TEST(MeshLoad, Refusals) {
  expect_refused((std::filesystem::temp_directory_path() / "ris_mesh_absent.obj").string(), "");
  expect_refused(write_file("garbage.stl", "this is not a mesh\n"), "cannot read");
  expect_refused(write_file("points.obj", "v 0 0 0\nv 1 0 0\n"), "cannot read");
  expect_refused(write_file("degenerate.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
                 "degenerate");
  expect_refused(write_file("cap.obj", kQuadObj), "more than the cap", 1);
  expect_refused(write_file("inf.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n"), "not finite");
}

}  // namespace
}  // namespace ris
