#include "ris/sensors_eo/frame_camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace ris {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

FrameCamera camera(double heading, double depression, int cols, int rows, double fov) {
  FrameCamera c;
  c.heading_deg = heading;
  c.depression_deg = depression;
  c.cols = cols;
  c.rows = rows;
  c.fov_deg = fov;
  return c;
}

// Nadir, heading north: the principal ray points down, columns run east,
// rows south; the edge of the middle row is half the field of view off axis.
TEST(FrameCamera, NadirHeadingNorthLooksDownWithNorthUp) {
  const FrameCamera cam = camera(0, 90, 100, 60, 30);
  const CameraFrame f = camera_frame(cam);
  const Vec3 centre = camera_ray_direction(f, cam, 30, 50);
  EXPECT_NEAR(centre.z, -1.0, 1e-12);
  const Vec3 east = camera_ray_direction(f, cam, 30, 100);
  EXPECT_GT(east.x, 0.0);
  EXPECT_NEAR(std::acos(east.dot(centre)), 15 * kDeg, 1e-12);
  const Vec3 south = camera_ray_direction(f, cam, 60, 50);
  EXPECT_LT(south.y, 0.0);
  EXPECT_NEAR(south.x, 0.0, 1e-12);
}

// Heading east, 30 deg below the horizontal: the axis is
// (cos 30, 0, -sin 30), the columns run south (right of the heading) and the
// rows downwards in the picture (towards the nadir).
TEST(FrameCamera, ObliqueHeadingEastAxisAndImagePlane) {
  const FrameCamera cam = camera(90, 30, 64, 64, 20);
  const CameraFrame f = camera_frame(cam);
  EXPECT_NEAR(f.forward.x, std::cos(30 * kDeg), 1e-12);
  EXPECT_NEAR(f.forward.y, 0.0, 1e-12);
  EXPECT_NEAR(f.forward.z, -std::sin(30 * kDeg), 1e-12);
  EXPECT_NEAR(f.right.y, -1.0, 1e-12);
  EXPECT_NEAR(f.down.dot(f.forward), 0.0, 1e-12);
  EXPECT_NEAR(f.down.dot(f.right), 0.0, 1e-12);
  EXPECT_LT(f.down.z, 0.0);  // lower in the picture is nearer the nadir
  EXPECT_NEAR(f.focal_px, 32.0 / std::tan(10 * kDeg), 1e-9);
}

// The pixels' solid angles add up to the field of view's: a rectangular
// pyramid of half-angles a, b subtends 4 asin(sin a sin b) steradians.
TEST(FrameCamera, PixelSolidAnglesSumToTheFieldOfView) {
  const FrameCamera cam = camera(0, 90, 200, 120, 40);
  const CameraFrame f = camera_frame(cam);
  double sum = 0;
  for (int r = 0; r < cam.rows; ++r) {
    for (int c = 0; c < cam.cols; ++c) {
      sum += pixel_solid_angle_sr(f, camera_ray_direction(f, cam, r + 0.5, c + 0.5));
    }
  }
  const double a = 20 * kDeg;
  const double b = std::atan(60.0 / f.focal_px);
  const double omega = 4.0 * std::asin(std::sin(a) * std::sin(b));
  EXPECT_NEAR(sum, omega, 1e-5 * omega);
}

// A point of known position projects to the pixel the collinearity
// equations predict (Kraus 2007, eq. 4.2-1, here with the axes written out):
// a nadir camera 500 m up sees a point dx east, dy north at
// col = cols/2 + f dx / 500, row = rows/2 - f dy / 500; the ray through that
// image point returns to the point; behind the camera nothing projects.
TEST(FrameCamera, KnownPointsProjectToThePredictedPixel) {
  const FrameCamera nadir_cam = camera(0, 90, 640, 480, 30);
  const CameraFrame f = camera_frame(nadir_cam);
  const Vec3 offset{37.0, -21.0, -500.0};
  const auto px = camera_project(f, nadir_cam, offset);
  ASSERT_TRUE(px.has_value());
  EXPECT_NEAR(px->second, 320.0 + f.focal_px * 37.0 / 500.0, 0.1);
  EXPECT_NEAR(px->first, 240.0 + f.focal_px * 21.0 / 500.0, 0.1);
  // Oblique, any heading: project then cast back through the image point.
  const FrameCamera oblique = camera(123, 35, 800, 600, 50);
  const CameraFrame g = camera_frame(oblique);
  const Vec3 p{-150.0, -80.0, -300.0};
  const auto q = camera_project(g, oblique, p);
  ASSERT_TRUE(q.has_value());
  const Vec3 back = camera_ray_direction(g, oblique, q->first, q->second);
  EXPECT_NEAR(back.dot(p.normalized()), 1.0, 1e-12);
  EXPECT_FALSE(camera_project(g, oblique, -g.forward).has_value());
}

}  // namespace
}  // namespace ris
