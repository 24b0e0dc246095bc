#include "ris/sensors_eo/frame_camera.h"

#include <cmath>
#include <numbers>

namespace ris {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

}  // namespace

CameraFrame camera_frame(const FrameCamera& cam) {
  const double h = cam.heading_deg * kDeg;
  const double d = cam.depression_deg * kDeg;
  CameraFrame f;
  f.forward = {std::sin(h) * std::cos(d), std::cos(h) * std::cos(d), -std::sin(d)};
  f.right = {std::cos(h), -std::sin(h), 0.0};
  f.down = f.forward.cross(f.right);
  f.focal_px = 0.5 * cam.cols / std::tan(0.5 * cam.fov_deg * kDeg);
  return f;
}

Vec3 camera_ray_direction(const CameraFrame& frame, const FrameCamera& cam, double row,
                          double col) {
  const double u = col - 0.5 * cam.cols;  // pixels right of the principal point
  const double v = row - 0.5 * cam.rows;  // pixels below it
  return (frame.forward * frame.focal_px + frame.right * u + frame.down * v).normalized();
}

double pixel_solid_angle_sr(const CameraFrame& frame, const Vec3& direction) {
  const double c = direction.dot(frame.forward);
  return c * c * c / (frame.focal_px * frame.focal_px);
}

std::optional<std::pair<double, double>> camera_project(const CameraFrame& frame,
                                                        const FrameCamera& cam,
                                                        const Vec3& offset) {
  const double z = offset.dot(frame.forward);
  if (!(z > 0)) return std::nullopt;
  return std::pair{0.5 * cam.rows + frame.focal_px * offset.dot(frame.down) / z,
                   0.5 * cam.cols + frame.focal_px * offset.dot(frame.right) / z};
}

}  // namespace ris
