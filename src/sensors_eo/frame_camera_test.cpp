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

}  // namespace
}  // namespace ris
