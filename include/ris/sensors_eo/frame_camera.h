// A frame camera's geometry (issue 35 item 1; docs/sensors.md "Frame
// camera"): an ideal pinhole (central projection, no distortion) at a
// position over the scene, looking along a heading and a depression angle,
// with a horizontal field of view and a grid of square pixels. The same
// model as a photogrammetric frame camera's collinearity equations (Kraus,
// Photogrammetry, vol. 1, 2nd ed., 2007, section 4.2) with the principal
// point at the image centre.
//
// Frames: the scene's local east-north-up frame (metres, x east, y north,
// z up). The optical axis points along
//   f = (sin h cos d, cos h cos d, -sin d)
// (h the heading clockwise from north, d the depression below the
// horizontal: 90 deg looks at nadir); image columns run along
//   r = (cos h, -sin h, 0)            (to the right of the heading)
// and image rows along f x r (downwards in the picture; for a nadir view
// with heading north, the top of the picture is north).
//
// Example:
//   ris::FrameCamera cam{.x_m = 500, .y_m = 500, .altitude_m = 3000,
//                        .heading_deg = 0, .depression_deg = 90,
//                        .fov_deg = 20, .cols = 640, .rows = 480};
//   ris::Vec3 d = ris::camera_ray_direction(cam, 240.0, 320.0);  // centre
#pragma once

#include <optional>
#include <utility>

#include "ris/util/vec3.h"

namespace ris {

struct FrameCamera {
  double x_m = 0;              // scene x (the scene's CRS metres, as a PPI site)
  double y_m = 0;              // scene y
  double altitude_m = 0;       // above the scene's height datum
  double heading_deg = 0;      // clockwise from north
  double depression_deg = 90;  // below the horizontal; 90 = nadir
  double fov_deg = 20;         // horizontal (across the columns)
  int cols = 0;
  int rows = 0;
  int samples = 2;            // rays per pixel along each axis (footprint average)
  double mtf_at_nyquist = 1;  // Gaussian MTF at 0.5 cycles/pixel; 1: none
};

struct CameraFrame {
  Vec3 forward, right, down;
  double focal_px = 0;  // focal length in pixels: (cols / 2) / tan(fov / 2)
};

CameraFrame camera_frame(const FrameCamera& cam);

// Unit direction of the ray through the image point (row, col) in pixel
// units (pixel (i, j) covers [i, i + 1) x [j, j + 1); its centre is
// (i + 0.5, j + 0.5)).
Vec3 camera_ray_direction(const CameraFrame& frame, const FrameCamera& cam, double row, double col);

// Solid angle of the pixel whose centre direction makes angle `off_axis`
// with the optical axis: cos^3(off_axis) / focal_px^2 steradians (the
// pixel's area over the squared distance, foreshortened).
double pixel_solid_angle_sr(const CameraFrame& frame, const Vec3& direction);

// The image point (row, col) in pixel units where the point at `offset`
// from the camera (point minus camera position, ENU metres) projects: the
// collinearity equations row = rows/2 + f (d . down) / (d . forward),
// col = cols/2 + f (d . right) / (d . forward). nullopt behind the camera.
std::optional<std::pair<double, double>> camera_project(const CameraFrame& frame,
                                                        const FrameCamera& cam, const Vec3& offset);

}  // namespace ris
