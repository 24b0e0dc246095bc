// The Python extension `ris._ris`: thin pybind11 bindings over ris_core, the
// library the command line uses (no second implementation of anything). The
// Pythonic layer (argument checks, array conversion, dict -> TOML) is
// python/ris/__init__.py; this file only moves data across and turns
// ris::InputError into Python exceptions.
//
// Arrays: the scene's arrays and the simulation's maps are zero-copy,
// read-only views whose base object keeps the C++ data alive; the pictures
// that rerender() replaces are copies (a view would dangle after it).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "ris/backscatter/backscatter_model.h"
#include "ris/backscatter/library.h"
#include "ris/image/geocode.h"
#include "ris/image/slar_image.h"
#include "ris/io/config_table.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/scene.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/polarisation.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_json.h"
#include "ris/sim/point_target_irf.h"
#include "ris/sim/ppi_products.h"
#include "ris/sim/run.h"
#include "ris/sim/slar_products.h"
#include "ris/util/error.h"

namespace py = pybind11;

namespace {

PyObject* g_input_error = nullptr;    // ris.InputError(ValueError)
PyObject* g_missing_error = nullptr;  // ris.InputFileNotFoundError(InputError, FileNotFoundError)

// A missing input file is reported as a FileNotFoundError subclass, every
// other bad input as ris.InputError; both carry the C++ message and the
// file and key it names.
void raise_input_error(const ris::InputError& e) {
  const bool missing = !e.file().empty() && !std::filesystem::exists(e.file());
  PyObject* type = missing ? g_missing_error : g_input_error;
  py::object err = py::reinterpret_borrow<py::object>(type)(py::str(e.what()));
  err.attr("file") = e.file();
  err.attr("key") = e.key();
  PyErr_SetObject(type, err.ptr());
}

// Parsed JSON (nlohmann) as a Python object, through the json module.
py::object json_to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

// A read-only view of `n` elements of C++ memory, shaped `shape`, kept alive
// by `owner`.
template <typename T>
py::array view(const T* data, std::vector<py::ssize_t> shape, const py::object& owner) {
  py::array a(py::dtype::of<T>(), std::move(shape), {}, data, owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// A copy, shaped `shape`.
template <typename T>
py::array_t<T> copy(const T* data, std::vector<py::ssize_t> shape) {
  py::array_t<T> a(shape);
  std::copy(data, data + a.size(), a.mutable_data());
  return a;
}

struct PyScene {
  std::shared_ptr<const ris::Scene> scene;
  std::string path;  // where it was read from ("" when built from arrays)
  std::string name;
};

PyScene scene_from_arrays(py::array_t<float, py::array::c_style> elevation_m,
                          py::array_t<std::uint16_t, py::array::c_style> category,
                          py::array_t<std::uint8_t, py::array::c_style> valid, double cell_size_m,
                          double origin_x_m, double origin_y_m, const std::string& crs) {
  auto s = std::make_shared<ris::Scene>();
  s->rows = static_cast<int>(elevation_m.shape(0));
  s->cols = static_cast<int>(elevation_m.shape(1));
  s->dx_m = s->dy_m = cell_size_m;
  s->origin_x_m = origin_x_m;
  s->origin_y_m = origin_y_m;
  s->crs_wkt = crs;
  s->elevation_m.assign(elevation_m.data(), elevation_m.data() + elevation_m.size());
  s->category.assign(category.data(), category.data() + category.size());
  s->valid.assign(valid.data(), valid.data() + valid.size());
  s->validate("Scene.from_arrays");
  return PyScene{std::move(s), "", ""};
}

PyScene load_scene(const std::string& path, std::optional<std::string> category_path,
                   std::optional<double> cell_size_m, std::optional<std::string> crs,
                   int category) {
  if (!ris::is_scene_description(path) && ris::dem_needs_import(path)) {
    ris::DemImportOptions opt;
    opt.cell_size_m = cell_size_m;
    opt.crs = crs;
    opt.category = static_cast<std::uint16_t>(category);
    opt.cell_size_key = "cell_size_m";
    opt.crs_key = "crs";
    return PyScene{std::make_shared<ris::Scene>(ris::import_dem(path, opt).scene), path, ""};
  }
  ris::LoadedScene in = ris::load_scene_source(path, category_path);
  return PyScene{std::make_shared<ris::Scene>(std::move(in.scene)), path, in.name};
}

struct PyRadar {
  ris::RadarParams radar;
};

PyRadar radar_from_text(const std::string& text, const std::string& source) {
  toml::table doc;
  try {
    doc = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw ris::InputError(source, "",
                          "expected TOML: " + std::string(e.description()) + " at line " +
                              std::to_string(e.source().begin.line));
  }
  return PyRadar{ris::radar_from_toml(doc, source)};
}

struct PyResult {
  std::shared_ptr<ris::RunResult> res;
  std::vector<std::string> warnings;

  const ris::SlarSimulation& slar() const {
    if (!res->slar) {
      throw ris::InputError(res->info.radar_path, "mode",
                            "this product exists for SLAR and SAR runs only (a PPI run: use "
                            "write() and metadata)");
    }
    return *res->slar;
  }
  const ris::SlarPictures& pictures() const {
    slar();
    return *res->slar_pictures;
  }
  std::vector<py::ssize_t> slant_shape() const { return {slar().image.lines, slar().image.bins}; }
  std::vector<py::ssize_t> ground_shape() const {
    return {slar().image.lines, slar().ground_grid.count};
  }
  std::vector<py::ssize_t> scene_shape() const { return {res->scene->rows, res->scene->cols}; }

  nlohmann::json metadata() const {
    if (res->kind == ris::RunKind::ppi) {
      return ris::ppi_metadata(*res->scene, *res->ppi, *res->ppi_pictures, res->info);
    }
    nlohmann::json extra = nlohmann::json::object();
    if (res->has_targets) {
      extra["point_targets"] = ris::point_target_irf_json(res->irfs, *res->slar, res->targets_path,
                                                          res->kind == ris::RunKind::coherent_sar);
    }
    return ris::slar_metadata(*res->scene, *res->slar, *res->slar_pictures, res->info, extra);
  }
};

PyResult simulate(const PyScene& scene, const PyRadar& radar, const std::string& backscatter,
                  std::uint64_t seed, int threads, const std::string& targets,
                  std::function<void(std::string, double)> progress) {
  ris::RunRequest r;
  r.scene = scene.scene;
  r.scene_path = scene.path;
  r.radar = radar.radar;
  r.radar_path = radar.radar.source_file;
  r.backscatter_path = backscatter;
  r.targets_path = targets;
  r.seed = seed;
  r.threads = threads;
  r.quiet = true;
  PyResult out;
  ris::RunCallbacks cb;
  cb.warning = [&out](const std::string& w) { out.warnings.push_back(w); };
  if (progress) {
    cb.progress = [&progress](std::string_view stage, double fraction) {
      py::gil_scoped_acquire gil;
      progress(std::string(stage), fraction);
    };
  }
  {
    py::gil_scoped_release nogil;
    out.res = std::make_shared<ris::RunResult>(ris::run_simulation(r, cb));
  }
  return out;
}

// One library or table file, loaded once and evaluated many times.
struct PySigma0Source {
  std::shared_ptr<const ris::Sigma0Source> source;
  std::string path;

  std::uint16_t category_id(const py::object& category) const {
    if (py::isinstance<py::str>(category)) {
      const auto name = category.cast<std::string>();
      for (std::uint16_t id : source->category_ids()) {
        if (source->category_name(id) == name) return id;
      }
      throw ris::InputError(path, "category",
                            "no category \"" + name + "\" in the file (give an id or a name)");
    }
    const long id = category.cast<long>();
    if (id < 0 || id > ris::kMaxCategory || !source->has_category(static_cast<std::uint16_t>(id))) {
      throw ris::InputError(path, "category", "no category " + std::to_string(id) + " in the file");
    }
    return static_cast<std::uint16_t>(id);
  }
};

ris::RadarBand band_of(double frequency_hz, const std::string& polarisation) {
  if (!(frequency_hz > 0.0) || !std::isfinite(frequency_hz)) {
    throw ris::InputError("", "frequency_hz", "expected a frequency > 0 Hz");
  }
  try {
    return {frequency_hz, ris::parse_polarisation(polarisation)};
  } catch (const std::invalid_argument& e) {
    throw ris::InputError("", "polarisation", e.what());
  }
}

// sigma0 (linear) of a category at angles (radians) for one band.
py::array_t<double> category_sigma0(const PySigma0Source& src, const py::object& category,
                                    py::array_t<double, py::array::c_style> incidence_rad,
                                    double frequency_hz, const std::string& polarisation) {
  const std::uint16_t id = src.category_id(category);
  const ris::RadarBand band = band_of(frequency_hz, polarisation);
  py::array_t<double> out(incidence_rad.size());
  const double* in = incidence_rad.data();
  double* o = out.mutable_data();
  for (py::ssize_t i = 0; i < incidence_rad.size(); ++i) o[i] = src.source->sigma0(id, in[i], band);
  return out;
}

// sigma0 (linear) of a model given as the body of a TOML inline table
// ('name = "oh1992", rms_height = "1 cm", ...'), as `ris sigma0 --model`.
py::array_t<double> model_sigma0(const std::string& model_toml,
                                 py::array_t<double, py::array::c_style> incidence_rad,
                                 double frequency_hz, const std::string& polarisation,
                                 bool allow_extrapolation) {
  toml::table doc;
  try {
    doc = toml::parse("model = { " + model_toml + " }");
  } catch (const toml::parse_error& e) {
    throw ris::InputError(
        "", "model",
        "expected model parameters as TOML key = value pairs: " + std::string(e.description()));
  }
  ris::ConfigTable root(doc, "model", "");
  std::optional<ris::ConfigTable> t = root.subtable("model");
  ris::ModelContext ctx{"model", ".", allow_extrapolation, -1, nullptr};
  std::unique_ptr<ris::BackscatterModel> model = ris::make_backscatter_model(*t, ctx);
  const ris::RadarBand band = band_of(frequency_hz, polarisation);
  model->check_band(band);
  py::array_t<double> out(incidence_rad.size());
  const double* in = incidence_rad.data();
  double* o = out.mutable_data();
  for (py::ssize_t i = 0; i < incidence_rad.size(); ++i) o[i] = model->sigma0(in[i], band);
  return out;
}

}  // namespace

PYBIND11_MODULE(_ris, m) {
  m.doc() = "ris radar image simulator: C++ core bindings (use the `ris` package)";
  m.attr("__version__") = RIS_VERSION;

  g_input_error = PyErr_NewException("ris.InputError", PyExc_ValueError, nullptr);
  py::tuple bases = py::make_tuple(py::handle(g_input_error), py::handle(PyExc_FileNotFoundError));
  g_missing_error = PyErr_NewException("ris.InputFileNotFoundError", bases.ptr(), nullptr);
  m.add_object("InputError", py::handle(g_input_error));
  m.add_object("InputFileNotFoundError", py::handle(g_missing_error));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const ris::InputError& e) {
      raise_input_error(e);
    }
  });

  py::class_<PyScene>(m, "_Scene")
      .def_property_readonly("rows", [](const PyScene& s) { return s.scene->rows; })
      .def_property_readonly("cols", [](const PyScene& s) { return s.scene->cols; })
      .def_property_readonly("dx_m", [](const PyScene& s) { return s.scene->dx_m; })
      .def_property_readonly("dy_m", [](const PyScene& s) { return s.scene->dy_m; })
      .def_property_readonly("crs", [](const PyScene& s) { return s.scene->crs_wkt; })
      .def_property_readonly("path", [](const PyScene& s) { return s.path; })
      .def_property_readonly("name", [](const PyScene& s) { return s.name; })
      .def_property_readonly("geotransform",
                             [](const PyScene& s) {
                               const auto g = s.scene->geotransform();
                               return py::make_tuple(g[0], g[1], g[2], g[3], g[4], g[5]);
                             })
      .def_property_readonly(
          "elevation_m",
          [](py::object self) {
            const PyScene& s = self.cast<const PyScene&>();
            return view(s.scene->elevation_m.data(), {s.scene->rows, s.scene->cols}, self);
          })
      .def_property_readonly(
          "category",
          [](py::object self) {
            const PyScene& s = self.cast<const PyScene&>();
            return view(s.scene->category.data(), {s.scene->rows, s.scene->cols}, self);
          })
      .def_property_readonly(
          "valid",
          [](py::object self) {
            const PyScene& s = self.cast<const PyScene&>();
            return view(s.scene->valid.data(), {s.scene->rows, s.scene->cols}, self);
          })
      .def("write", [](const PyScene& s, const std::string& path) {
        ris::write_scene_geotiff(*s.scene, path, ris::scene_label_metadata(s.name, {}));
      });
  m.def("_scene_from_arrays", &scene_from_arrays);
  m.def("_load_scene", &load_scene);

  py::class_<PyRadar>(m, "_Radar")
      .def_property_readonly("source", [](const PyRadar& r) { return r.radar.source_file; })
      .def("params", [](const PyRadar& r) { return json_to_python(ris::radar_to_json(r.radar)); })
      .def("derived", [](const PyRadar& r) {
        return json_to_python(ris::derived_to_json(ris::derive(r.radar)));
      });
  m.def("_load_radar", [](const std::string& path) { return PyRadar{ris::load_radar(path)}; });
  m.def("_radar_from_toml", &radar_from_text);

  py::class_<PyResult>(m, "_Result")
      .def_property_readonly("warnings", [](const PyResult& r) { return r.warnings; })
      .def_property_readonly("kind",
                             [](const PyResult& r) {
                               switch (r.res->kind) {
                                 case ris::RunKind::slar:
                                   return "slar";
                                 case ris::RunKind::sar:
                                   return "sar";
                                 case ris::RunKind::coherent_sar:
                                   return "coherent_sar";
                                 case ris::RunKind::ppi:
                                   return "ppi";
                                 case ris::RunKind::streamed:
                                   return "streamed";
                               }
                               return "";
                             })
      .def_property_readonly("seed", [](const PyResult& r) { return r.res->info.seed; })
      .def("metadata", [](const PyResult& r) { return json_to_python(r.metadata()); })
      .def("mean_power_w",
           [](const PyResult& r) {
             const ris::SlarImage& img = r.slar().image;
             py::array_t<float> a = copy(img.mean_power_w.data(), r.slant_shape());
             float* d = a.mutable_data();
             // As mean_power_slant.tif: NaN where no data.
             for (py::ssize_t i = 0; i < a.size(); ++i)
               if (img.mask[static_cast<std::size_t>(i)] & ris::pixel_flag::kNoData)
                 d[i] = std::numeric_limits<float>::quiet_NaN();
             return a;
           })
      .def("speckled_power_w",
           [](const PyResult& r) {
             return copy(r.pictures().speckled_power_w.data(), r.slant_shape());
           })
      .def("slant_grey",
           [](const PyResult& r) { return copy(r.pictures().slant_grey.data(), r.slant_shape()); })
      .def("ground_power_w",
           [](const PyResult& r) {
             return copy(r.pictures().ground_power_w.data(), r.ground_shape());
           })
      .def(
          "ground_grey",
          [](const PyResult& r) { return copy(r.pictures().ground_grey.data(), r.ground_shape()); })
      .def(
          "ground_mask",
          [](const PyResult& r) { return copy(r.pictures().ground_mask.data(), r.ground_shape()); })
      .def("ground_range_m",
           [](const PyResult& r) {
             const ris::GroundRangeGrid& g = r.slar().ground_grid;
             py::array_t<double> a(g.count);
             for (int j = 0; j < g.count; ++j) a.mutable_data()[j] = g.centre_m(j);
             return a;
           })
      .def("slant_range_m",
           [](const PyResult& r) {
             const ris::SlarImage& img = r.slar().image;
             py::array_t<double> a(img.bins);
             for (int j = 0; j < img.bins; ++j) a.mutable_data()[j] = img.range.centre_m(j);
             return a;
           })
      .def("mask_slant",
           [](py::object self) {
             const PyResult& r = self.cast<const PyResult&>();
             return view(r.slar().image.mask.data(), r.slant_shape(), self);
           })
      .def("scene_mask",
           [](py::object self) {
             const PyResult& r = self.cast<const PyResult&>();
             return view(r.slar().scene_maps.mask.data(), r.scene_shape(), self);
           })
      .def("local_incidence_deg",
           [](py::object self) {
             const PyResult& r = self.cast<const PyResult&>();
             return view(r.slar().scene_maps.local_incidence_deg.data(), r.scene_shape(), self);
           })
      .def("geocoded_power_w",
           [](const PyResult& r) {
             std::vector<float> g = ris::geocode_slant_image(
                 *r.res->scene, r.slar().track, r.slar().image, r.pictures().speckled_power_w);
             return copy(g.data(), r.scene_shape());
           })
      .def("geocoded_grey",
           [](const PyResult& r) {
             std::vector<std::uint8_t> g = ris::geocode_slant_grey(
                 *r.res->scene, r.slar().track, r.slar().image, r.pictures().slant_grey);
             return copy(g.data(), r.scene_shape());
           })
      .def("rerender",
           [](PyResult& r, std::uint64_t seed, std::optional<std::vector<double>> film) {
             py::gil_scoped_release nogil;
             if (film) {
               RIS_CHECK(film->size() == 6);
               const ris::FilmParams f{(*film)[0], (*film)[1], (*film)[2],
                                       (*film)[3], (*film)[4], (*film)[5]};
               ris::rerender(*r.res, seed, &f);
             } else {
               ris::rerender(*r.res, seed);
             }
           })
      .def("film",
           [](const PyResult& r) {
             const ris::FilmParams& f =
                 r.res->slar ? r.res->slar->radar.film : r.res->ppi->radar.film;
             return std::vector<double>{f.density_range, f.gamma, f.k1, f.k2, f.m1, f.m2};
           })
      .def("write", [](const PyResult& r, const std::string& dir) {
        py::gil_scoped_release nogil;
        return ris::write_run_products(*r.res, dir);
      });
  m.def("_simulate", &simulate);

  py::class_<PySigma0Source>(m, "_Sigma0Source")
      .def_property_readonly("path", [](const PySigma0Source& s) { return s.path; })
      .def("category_ids", [](const PySigma0Source& s) { return s.source->category_ids(); })
      .def("category_name",
           [](const PySigma0Source& s, std::uint16_t id) { return s.source->category_name(id); });
  m.def("_load_sigma0_source", [](const std::string& path) {
    const std::string p = path.empty() ? ris::default_sigma0_library_path() : path;
    return PySigma0Source{std::shared_ptr<const ris::Sigma0Source>(ris::load_sigma0_source(p)), p};
  });
  m.def("_category_sigma0", &category_sigma0);
  m.def("_model_sigma0", &model_sigma0);
  m.def("_list_models", [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const ris::ModelInfo& i : ris::backscatter_model_names())
      out.emplace_back(i.name, i.summary);
    return out;
  });
}
