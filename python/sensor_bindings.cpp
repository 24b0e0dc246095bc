// Optical and thermal images from Python (ris.sensor): the bindings over
// ris/sensors_eo/, the code `ris sensor` runs (the same scene loader, place,
// terrain, grid render and camera), so the arrays hold the command line's
// values. The product files stay the command line's; python/ris/__init__.py
// wraps the result. Errors are translated by ris_module.cpp (InputError
// keeps its class).
#include <omp.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>

#include "ris/scene/scene_source.h"
#include "ris/sensors_eo/camera_view.h"
#include "ris/sensors_eo/eo_place.h"
#include "ris/sensors_eo/eo_render.h"

namespace py = pybind11;

namespace {

template <typename T>
py::array_t<T> as_array(const std::vector<T>& v, int rows, int cols) {
  py::array_t<T> a({rows, cols});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

py::dict run_sensor(const std::string& scene_path, const std::string& sensor_path,
                    const std::string& table_path, int threads) {
  ris::EoSensorConfig cfg;
  ris::LoadedScene loaded;
  ris::EoImage grid, quiet;
  ris::CameraImage cam;
  double lat = 0, lon = 0;
  {
    py::gil_scoped_release nogil;
    const int before = omp_get_max_threads();
    if (threads > 0) omp_set_num_threads(threads);
    cfg = ris::load_eo_sensor(sensor_path);
    const ris::EoSurfaceTable table = ris::load_eo_surface_table(
        table_path.empty() ? ris::default_eo_surface_table(scene_path) : table_path);
    loaded = ris::load_scene_source(scene_path);
    std::tie(lat, lon) = ris::eo_place(loaded.scene, cfg, scene_path);
    const ris::EoTerrain terrain = ris::build_eo_terrain(loaded.scene);
    grid = ris::render_eo(loaded.scene, cfg, table, lat, lon, &terrain);
    if (cfg.camera) {
      ris::EoSensorConfig noise_free = cfg;
      noise_free.noise = 0;
      quiet = cfg.noise == 0 ? grid
                             : ris::render_eo(loaded.scene, noise_free, table, lat, lon, &terrain);
      cam = ris::view_through_camera(loaded.scene, quiet, cfg, *cfg.camera, cfg.detector, &terrain);
    }
    omp_set_num_threads(before);
  }
  py::dict out;
  py::dict bands;
  for (std::size_t b = 0; b < grid.bands.size(); ++b) {
    bands[py::str(grid.band_names[b])] = as_array(grid.bands[b], grid.rows, grid.cols);
  }
  out["bands"] = bands;
  out["unit"] = grid.unit;
  out["latitude_deg"] = lat;
  out["longitude_deg"] = lon;
  out["sun"] = py::dict(py::arg("zenith_deg") = grid.sun.zenith_deg,
                        py::arg("azimuth_deg") = grid.sun.azimuth_deg,
                        py::arg("elevation_deg") = grid.sun.elevation_deg,
                        py::arg("earth_sun_distance_au") = grid.sun.earth_sun_distance_au);
  out["night"] = grid.night;
  out["shadowed_cells"] = grid.shadowed_cells;
  out["geotransform"] = loaded.scene.geotransform();
  out["crs_wkt"] = loaded.scene.crs_wkt;
  if (cfg.camera) {
    py::dict c;
    py::dict cb;
    for (std::size_t b = 0; b < cam.bands.size(); ++b) {
      cb[py::str(cam.band_names[b])] = as_array(cam.bands[b], cam.rows, cam.cols);
    }
    c["bands"] = cb;
    c["range_m"] = as_array(cam.range_m, cam.rows, cam.cols);
    c["footprint_area_m2"] = as_array(cam.footprint_area_m2, cam.rows, cam.cols);
    py::dict dn;
    for (std::size_t b = 0; b < cam.digital_numbers.size(); ++b) {
      dn[py::str(cam.band_names[b])] = as_array(cam.digital_numbers[b], cam.rows, cam.cols);
    }
    c["digital_numbers"] = dn;
    py::list gcps;
    for (const ris::GroundControlPoint& g : cam.gcps) {
      gcps.append(py::make_tuple(g.pixel, g.line, g.x, g.y, g.z));
    }
    c["gcps"] = gcps;
    c["empty_pixels"] = cam.empty_pixels;
    out["camera"] = c;
  } else {
    out["camera"] = py::none();
  }
  return out;
}

}  // namespace

void bind_sensor(py::module_& m) {
  m.def("_sensor", &run_sensor, py::arg("scene"), py::arg("sensor"), py::arg("table"),
        py::arg("threads"));
}
