// The Python extension `ris._ris`: thin pybind11 bindings over ris_core, the
// library the command line uses (no second implementation of anything). The
// Pythonic layer (argument checks, array conversion, dict -> TOML) is
// python/ris/__init__.py; this file only moves data across and turns
// ris::InputError into Python exceptions.
//
// Arrays: the scene's arrays and the simulation's maps are zero-copy,
// read-only views whose base object keeps the C++ data alive; the pictures
// that rerender() replaces are copies (a view would dangle after it).
#include <fmt/format.h>
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "ris/backscatter/backscatter_model.h"
#include "ris/backscatter/dielectric.h"
#include "ris/backscatter/library.h"
#include "ris/geometry/topo.h"
#include "ris/image/compare_report.h"
#include "ris/image/geocode.h"
#include "ris/image/greytone_image.h"
#include "ris/image/polsar/quad_pol_slc.h"
#include "ris/image/quality_report.h"
#include "ris/image/slar_image.h"
#include "ris/io/compression_preset.h"
#include "ris/io/config_table.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/io/toml_nesting.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/landcover.h"
#include "ris/scene/scene.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/polarisation.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_json.h"
#include "ris/sim/acquisition_products.h"
#include "ris/sim/point_target_irf.h"
#include "ris/sim/ppi_products.h"
#include "ris/sim/run.h"
#include "ris/sim/sar_quad_pol.h"
#include "ris/sim/slar_products.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"

namespace py = pybind11;

namespace {

PyObject* g_input_error = nullptr;    // ris.InputError(ValueError)
PyObject* g_missing_error = nullptr;  // ris.InputFileNotFoundError(InputError, FileNotFoundError)

// An error about text the bindings were handed rather than a file on disk
// (a radar dict written as TOML, a model's parameters, a scene from arrays):
// its "file" is a pseudo-name such as "<dict>", which is never missing.
class TextInputError : public ris::InputError {
 public:
  explicit TextInputError(const ris::InputError& e) : ris::InputError(e) {}
};

// Runs f; an InputError naming `source` (the pseudo-file of the text being
// read) comes out as a TextInputError, so it keeps the class InputError.
template <typename F>
auto reading_text(const std::string& source, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const TextInputError&) {
    throw;
  } catch (const ris::InputError& e) {
    if (e.file() == source) throw TextInputError(e);
    throw;
  }
}

// A real input file that is not there is reported as
// ris.InputFileNotFoundError (a FileNotFoundError subclass), every other bad
// input as ris.InputError; both carry the C++ message and the file and key
// it names.
void raise_input_error(const ris::InputError& e, bool text_source) {
  const bool missing = !text_source && !e.file().empty() && !std::filesystem::exists(e.file());
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

// An image's mean power as mean_power_slant.tif / mean_power_bscope.tif
// hold it: NaN where no data.
py::array_t<float> mean_power_nan(const ris::SlarImage& img, std::vector<py::ssize_t> shape) {
  py::array_t<float> a = copy(img.mean_power_w.data(), std::move(shape));
  float* d = a.mutable_data();
  for (py::ssize_t i = 0; i < a.size(); ++i)
    if (img.mask[static_cast<std::size_t>(i)] & ris::pixel_flag::kNoData)
      d[i] = std::numeric_limits<float>::quiet_NaN();
  return a;
}

// Equation 15's film constants as a list (density_range, gamma, k1, k2, m1,
// m2; python/ris/__init__.py's _FILM_KEYS) and back.
std::vector<double> film_list(const ris::FilmParams& f) {
  return {f.density_range, f.gamma, f.k1, f.k2, f.m1, f.m2};
}
ris::FilmParams film_params(const std::vector<double>& v) {
  RIS_CHECK(v.size() == 6);
  return {v[0], v[1], v[2], v[3], v[4], v[5]};
}

struct PyScene {
  std::shared_ptr<const ris::Scene> scene;
  std::string path;  // where it was read from ("" when built from arrays)
  std::string name;
  // The backscatter library the scene's categories are ids of, which
  // simulate() takes when given none (as `ris simulate` does for a scene
  // raster that names one): "" for the standard library.
  std::string library;
  // A description's buildings and reflectors (traced by simulate()).
  std::vector<ris::CulturalObject> objects;
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
  reading_text("Scene.from_arrays", [&] { s->validate("Scene.from_arrays"); });
  return PyScene{std::move(s), "", "", "", {}};
}

PyScene load_scene(const std::string& path, std::optional<std::string> category_path,
                   std::optional<double> cell_size_m, std::optional<std::string> crs,
                   std::optional<std::string> category) {
  if (!ris::is_scene_description(path) && ris::dem_needs_import(path)) {
    ris::DemImportOptions opt;
    opt.cell_size_m = cell_size_m;
    opt.crs = crs;
    // As `ris scene import --category`: an id or a name of the generic-terrain
    // library; none: kDefaultCategory (grass).
    if (category) {
      opt.category = ris::parse_category(
          *category, ris::read_category_names(ris::data_dir() / ris::kDefaultCategoryLibrary),
          "category");
    }
    opt.cell_size_key = "cell_size_m";
    opt.crs_key = "crs";
    // The import's categories are ids of that library (`ris scene import`
    // names it in the scene GeoTIFF it writes).
    return PyScene{std::make_shared<ris::Scene>(ris::import_dem(path, opt).scene),
                   path,
                   "",
                   (ris::data_dir() / ris::kDefaultCategoryLibrary).string(),
                   {}};
  }
  ris::LoadedScene in = ris::load_scene_source(path, category_path);
  return PyScene{std::make_shared<ris::Scene>(std::move(in.scene)), path, in.name,
                 ris::scene_backscatter_library(path), std::move(in.cultural_objects)};
}

struct PyRadar {
  ris::RadarParams radar;
};

PyRadar radar_from_text(const std::string& text, const std::string& source) {
  return reading_text(source, [&] {
    ris::require_toml_nesting_within(text, ris::kMaxTomlNesting, source);
    toml::table doc;
    try {
      doc = toml::parse(text, source);
    } catch (const toml::parse_error& e) {
      throw ris::InputError(source, "",
                            "expected TOML: " + std::string(e.description()) + " at line " +
                                std::to_string(e.source().begin.line));
    }
    return PyRadar{ris::radar_from_toml(doc, source)};
  });
}

// `ris radar info`'s derived quantities with its units: the angles it prints
// in degrees (metadata.json's radar_derived keeps radians) become *_deg keys.
nlohmann::json derived_in_degrees(const ris::RadarParams& radar) {
  const nlohmann::json si = ris::derived_to_json(ris::derive(radar));
  nlohmann::json out = nlohmann::json::object();
  constexpr std::string_view kRad = "_rad";
  for (const auto& [key, value] : si.items()) {
    if (key.ends_with(kRad)) {
      out[key.substr(0, key.size() - kRad.size()) + "_deg"] = ris::rad_to_deg(value.get<double>());
    } else {
      out[key] = value;
    }
  }
  return out;
}

struct PyResult {
  std::shared_ptr<ris::RunResult> res;
  std::vector<std::string> warnings;
  std::filesystem::path out_dir;  // where the run wrote its products ("" none)

  bool streamed() const { return !res->in_memory(); }
  void require_in_memory() const {
    if (streamed()) {
      throw ris::InputError(res->info.scene_path, "stream",
                            "a streamed run keeps no images in memory: its products are the "
                            "files in " +
                                out_dir.string() + " (read them with GDAL)");
    }
  }
  const ris::SlarRun& slar_run() const {
    require_in_memory();
    const ris::SlarRun* run = ris::slar_image_run(*res);
    if (std::holds_alternative<ris::MultiChannelSlarRun>(res->run)) {
      throw ris::InputError(res->info.radar_path, "channel",
                            "a multi-channel run: take one channel's arrays with "
                            "channel(name) (the names: channels)");
    }
    if (run == nullptr) {
      throw ris::InputError(res->info.radar_path, "mode",
                            "this product exists for SLAR and SAR runs only (a PPI run: use "
                            "write() and metadata)");
    }
    return *run;
  }
  const ris::SlarSimulation& slar() const { return slar_run().sim; }
  const ris::SlarPictures& pictures() const { return slar_run().pictures; }
  const ris::PpiRun& ppi_run() const {
    require_in_memory();
    const auto* run = std::get_if<ris::PpiRun>(&res->run);
    if (run == nullptr) {
      throw ris::InputError(res->info.radar_path, "mode",
                            "this product exists for PPI runs only (a SLAR or SAR run: use "
                            "mean_power_w, slant_grey, ...)");
    }
    return *run;
  }
  const ris::PpiSimulation& ppi() const { return ppi_run().sim; }
  const ris::PpiPictures& ppi_pictures() const { return ppi_run().pictures; }
  // Whether the run was on an acquisition's radar grid (in memory or streamed).
  bool on_acquisition() const {
    return std::holds_alternative<ris::AcquisitionRun>(res->run) ||
           std::holds_alternative<ris::StreamedAcquisitionRun>(res->run);
  }
  // A scene run's scene (an acquisition run has the product's radar grid
  // instead).
  const ris::Scene& scene() const {
    slar();
    if (on_acquisition()) {
      throw ris::InputError(res->info.scene_path, "acquisition",
                            "an acquisition run has no scene grid: its products lie on the "
                            "product's radar grid (mean_power_w, local_incidence_deg, "
                            "layover_shadow_mask, ...)");
    }
    return *res->scene;
  }
  const ris::AcquisitionSimulation& acquisition() const {
    slar();
    const auto* run = std::get_if<ris::AcquisitionRun>(&res->run);
    if (run == nullptr) {
      throw ris::InputError(res->info.scene_path, "acquisition",
                            "this product exists for acquisition runs only (a scene run: "
                            "scene_mask, local_incidence_deg on the scene grid)");
    }
    return *run->grid;
  }
  // The image of this run's slant-range products: the SLAR/SAR image or the
  // PPI's B-scope (rays as lines).
  const ris::SlarImage& slant_image() const {
    return std::holds_alternative<ris::PpiRun>(res->run) ? ppi().bscope : slar().image;
  }
  std::vector<py::ssize_t> bscope_shape() const { return {ppi().bscope.lines, ppi().bscope.bins}; }
  std::vector<py::ssize_t> scope_shape() const {
    return {ppi().scope_grid.size, ppi().scope_grid.size};
  }
  std::vector<py::ssize_t> slant_shape() const { return {slar().image.lines, slar().image.bins}; }
  std::vector<py::ssize_t> ground_shape() const {
    return {slar().image.lines, slar().ground_grid.count};
  }
  std::vector<py::ssize_t> scene_shape() const { return {scene().rows, scene().cols}; }

  nlohmann::json metadata() const {
    if (streamed()) {  // written by the run, as the command line's
      std::ifstream in(out_dir / "metadata.json");
      return nlohmann::json::parse(in);
    }
    return ris::run_metadata(*res);
  }

  // A multi-channel run's channel names, in the radar file's order (empty
  // for a one-channel run).
  std::vector<std::string> channel_names() const {
    std::vector<std::string> out;
    if (const auto* multi = std::get_if<ris::MultiChannelSlarRun>(&res->run)) {
      for (const ris::ChannelRun& c : multi->channels) out.push_back(c.name);
    }
    return out;
  }
  // One channel of a multi-channel run as a one-channel result (its arrays
  // copied; the scene shared).
  PyResult channel(const std::string& name) const {
    const auto* multi = std::get_if<ris::MultiChannelSlarRun>(&res->run);
    if (multi == nullptr) {
      throw ris::InputError(res->info.radar_path, "channel",
                            "not a multi-channel run (its radar lists no [[channel]] tables)");
    }
    for (const ris::ChannelRun& c : multi->channels) {
      if (c.name != name) continue;
      PyResult out;
      out.res = std::make_shared<ris::RunResult>();
      out.res->run = c.run;
      out.res->radar = c.run.sim.radar;
      out.res->info = res->info;
      out.res->info.backscatter_path = c.backscatter_path;
      out.res->scene = res->scene;
      out.warnings = warnings;
      return out;
    }
    std::string names;
    for (const std::string& n : channel_names()) names += (names.empty() ? "" : ", ") + n;
    throw ris::InputError(res->info.radar_path, "channel",
                          "no channel \"" + name + "\" (the channels: " + names + ")");
  }

  // A quad-pol run's images and what formed them (ris/sim/sar_quad_pol.h).
  const ris::QuadPolRun& quad_pol() const {
    require_in_memory();
    const auto* multi = std::get_if<ris::MultiChannelSlarRun>(&res->run);
    if (multi == nullptr || !multi->quad_pol) {
      throw ris::InputError(res->info.radar_path, "sar.quad_pol",
                            "not a quad-pol run: set [sar] quad_pol = true (with coherent = "
                            "true) in the radar file");
    }
    return *multi->quad_pol;
  }
  // The four SLCs (HH, HV, VH, VV), complex64, (4, lines, bins).
  py::array_t<std::complex<float>> quad_pol_slc() const {
    const ris::QuadPolImages& q = quad_pol().images;
    py::array_t<std::complex<float>> a({py::ssize_t{4}, py::ssize_t{q.lines}, py::ssize_t{q.bins}});
    std::complex<float>* d = a.mutable_data();
    for (std::size_t c = 0; c < 4; ++c) d = std::copy(q.slc[c].begin(), q.slc[c].end(), d);
    return a;
  }
  // C3 or T3 averaged over a window x window boxcar (as ris polsar), complex64
  // (3, 3, lines, bins).
  py::array_t<std::complex<float>> quad_pol_matrix(const std::string& kind, int window) const {
    if (kind != "c3" && kind != "t3") {
      throw ris::InputError("", "kind", "expected \"c3\" or \"t3\", got \"" + kind + "\"");
    }
    if (window < 1 || window % 2 == 0) {
      throw ris::InputError("", "window",
                            "expected an odd number of pixels >= 1, got " + std::to_string(window));
    }
    const ris::QuadPolImages& q = quad_pol().images;
    ris::QuadPolSlc set;
    set.cols = q.bins;
    set.rows = q.lines;
    set.hh = q.slc[0];
    set.hv = q.slc[1];
    set.vh = q.slc[2];
    set.vv = q.slc[3];
    ris::CovarianceImage c = ris::boxcar_average(ris::single_look_c3(set), window, window);
    if (kind == "t3") c = ris::to_t3(c);
    const auto n = static_cast<py::ssize_t>(c.m.size());
    py::array_t<std::complex<float>> a(
        {py::ssize_t{3}, py::ssize_t{3}, py::ssize_t{c.rows}, py::ssize_t{c.cols}});
    std::complex<float>* d = a.mutable_data();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (py::ssize_t k = 0; k < n; ++k)
          *d++ = std::complex<float>(c.m[static_cast<std::size_t>(k)](i, j));
    return a;
  }

  // A streamed run's blocks and passes (`ris simulate --stream`'s report).
  py::dict stream_summary() const {
    if (!streamed()) {
      throw ris::InputError(res->info.scene_path, "stream", "not a streamed run");
    }
    py::dict d;
    if (const auto* ppi = std::get_if<ris::StreamedPpiRun>(&res->run)) {
      const ris::PpiStreamSummary& p = ppi->summary;
      d["blocks"] = p.blocks;
      d["block_lines"] = p.block_rays;
      d["scene_windows"] = p.windows;
      d["stage_seconds"] = p.stage_seconds;
      return d;
    }
    if (const auto* acq = std::get_if<ris::StreamedAcquisitionRun>(&res->run)) {
      d["blocks"] = acq->summary.blocks;
      d["block_lines"] = acq->summary.block_lines;
      d["stage_seconds"] = acq->summary.stage_seconds;
      return d;
    }
    const ris::SlarStreamSummary& s = std::get<ris::StreamedSlarRun>(res->run).summary;
    d["blocks"] = s.blocks;
    d["block_lines"] = s.block_lines;
    d["stage_seconds"] = s.stage_seconds;
    return d;
  }
};

// What a run is asked for beyond the scene and radar (`ris simulate`'s
// options; python/ris/__init__.py fills it).
struct PyRunOptions {
  std::string scene_path;  // a streamed run reads its scene raster from here
  std::string backscatter, targets;
  std::uint64_t seed = 1;
  int threads = 0;
  std::string out_dir;  // "" : nothing written
  bool stream = false;
  int block_lines = 0;
  std::vector<std::string> products;
  std::string compress = "fast";
  bool overviews = true;
  bool calibrated = false;  // also sigma0/beta0/gamma0 (--calibrated)
  // An acquisition run (`--acquisition` and what goes with it).
  std::string acquisition, frequency = "A", swath, dem, land_cover, earth;
  int burst = -1;
  int category = ris::AcquisitionSimOptions{}.category;
  bool full_grid = false;
};

ris::RunRequest run_request(const PyScene* scene, const PyRadar& radar, const PyRunOptions& o) {
  ris::RunRequest r;
  if (scene != nullptr) {
    r.scene = scene->scene;
    r.objects = scene->objects;
    r.scene_path = scene->path;
  } else {
    r.scene_path = o.scene_path;
  }
  r.radar = radar.radar;
  r.radar_path = radar.radar.source_file;
  r.backscatter_path = !o.backscatter.empty() || scene == nullptr ? o.backscatter : scene->library;
  r.targets_path = o.targets;
  r.seed = o.seed;
  r.threads = o.threads;
  r.quiet = true;
  r.out_dir = o.out_dir;
  r.stream = o.stream;
  r.block_lines = o.block_lines;
  r.products.stems = o.products;
  r.compression = ris::parse_compression_preset(o.compress, "compress");
  r.overviews = o.overviews;
  r.calibrated = o.calibrated;
  if (!o.acquisition.empty()) {
    r.acquisition_path = o.acquisition;
    r.acquisition.frequency = o.frequency;
    if (o.burst >= 0) r.acquisition.burst = o.burst;
    r.acquisition.swath = o.swath;
    r.dem_path = o.dem;
    r.land_cover_path = o.land_cover;
    if (o.category < 0 || o.category > ris::kMaxCategory) {
      throw ris::InputError(
          "", "category",
          fmt::format("expected a category id 0..{}, got {}", ris::kMaxCategory, o.category));
    }
    r.category = static_cast<std::uint16_t>(o.category);
    r.full_grid = o.full_grid;
  }
  if (!o.earth.empty()) {
    if (o.earth != "flat" && o.earth != "ellipsoid") {
      throw ris::InputError("", "earth",
                            "expected \"flat\" or \"ellipsoid\", got \"" + o.earth + "\"");
    }
    r.earth = o.earth == "flat" ? ris::EarthModel::flat : ris::EarthModel::ellipsoid;
  }
  return r;
}

// run_simulation (ris/sim/run.h), the command line's run, with the GIL
// released. scene: none for a streamed run (it reads o.scene_path) or an
// acquisition run.
PyResult run(const PyScene* scene, const PyRadar& radar, const PyRunOptions& o,
             std::function<void(std::string, double)> progress) {
  const ris::RunRequest r = run_request(scene, radar, o);
  PyResult out;
  out.out_dir = r.out_dir;
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
  ris::require_toml_nesting_within(model_toml, ris::kMaxTomlNesting - 1, "model");
  try {
    doc = toml::parse("model = { " + model_toml + " }");
  } catch (const toml::parse_error& e) {
    throw ris::InputError(
        "", "model",
        "expected model parameters as TOML key = value pairs: " + std::string(e.description()));
  }
  // "model" names the parameters given, not a file.
  ris::RadarBand band;
  const std::unique_ptr<ris::BackscatterModel> model = reading_text("model", [&] {
    ris::ConfigTable root(doc, "model", "");
    std::optional<ris::ConfigTable> t = root.subtable("model");
    ris::ModelContext ctx{"model", ".", allow_extrapolation, -1, nullptr};
    std::unique_ptr<ris::BackscatterModel> m = ris::make_backscatter_model(*t, ctx);
    band = band_of(frequency_hz, polarisation);
    m->check_band(band);
    return m;
  });
  py::array_t<double> out(incidence_rad.size());
  const double* in = incidence_rad.data();
  double* o = out.mutable_data();
  for (py::ssize_t i = 0; i < incidence_rad.size(); ++i) o[i] = model->sigma0(in[i], band);
  return out;
}

// Soil permittivity (eps' - j eps'', as std::complex(eps', -eps'')) of
// `model` at each (moisture, frequency) pair, as `ris dielectric` computes it;
// the soil's texture is shared. Validity-range problems are refused (naming
// the range) unless allow_extrapolation, when they come back as warnings.
std::pair<py::array_t<std::complex<double>>, std::vector<std::string>> permittivity(
    const std::string& model_name, py::array_t<double, py::array::c_style> moisture_m3_m3,
    py::array_t<double, py::array::c_style> frequency_hz, double clay, double sand,
    double bulk_density_g_cm3, double temperature_c, const std::string& conductivity_name,
    bool allow_extrapolation) {
  const std::optional<ris::DielectricModel> model = ris::parse_dielectric_model(model_name);
  if (!model) {
    throw ris::InputError("", "model",
                          "unknown dielectric model \"" + model_name + "\" (known: " +
                              ris::joined_names(ris::dielectric_model_names()) + ")");
  }
  const std::optional<ris::DobsonConductivity> conductivity =
      ris::parse_dobson_conductivity(conductivity_name);
  if (!conductivity) {
    throw ris::InputError("", "conductivity",
                          "expected one of " + ris::joined_names(ris::dobson_conductivity_names()) +
                              ", got \"" + conductivity_name + "\"");
  }
  RIS_CHECK(moisture_m3_m3.size() == frequency_hz.size());
  py::array_t<std::complex<double>> out(moisture_m3_m3.size());
  std::vector<std::string> warnings;
  const double* mv = moisture_m3_m3.data();
  const double* f = frequency_hz.data();
  std::complex<double>* o = out.mutable_data();
  for (py::ssize_t i = 0; i < moisture_m3_m3.size(); ++i) {
    const ris::SoilComposition soil{mv[i],         clay,         sand, bulk_density_g_cm3,
                                    temperature_c, *conductivity};
    for (const std::string& problem : ris::dielectric_validity(*model, soil, f[i])) {
      const std::string msg = std::string(ris::to_string(*model)) + ": " + problem;
      if (!allow_extrapolation) {
        throw ris::InputError("", "model", msg + " (allow_extrapolation=True to go on)");
      }
      if (std::find(warnings.begin(), warnings.end(), msg) == warnings.end()) {
        warnings.push_back(msg);
      }
    }
    o[i] = ris::soil_permittivity(*model, soil, f[i]);
  }
  return {out, warnings};
}

// `ris greytone` on an array: fading and equation 15 from a lines x bins
// mean power (W, NaN = no data) with the radar's film (or `film`), reference
// and fading law. N per bin comes from `looks_per_bin` when given, else from
// the radar's range bins (the array must then have the radar's bins, as
// `ris greytone` requires).
py::dict greytone(const PyRadar& radar, py::array_t<float, py::array::c_style> mean_power_w,
                  std::uint64_t seed, std::optional<std::vector<double>> film,
                  std::optional<std::vector<double>> looks_per_bin) {
  RIS_CHECK(mean_power_w.ndim() == 2);
  const int lines = static_cast<int>(mean_power_w.shape(0));
  const int bins = static_cast<int>(mean_power_w.shape(1));
  ris::RadarParams r = radar.radar;
  if (film) r.film = film_params(*film);
  if (!looks_per_bin && bins != r.range_bins) {
    throw ris::InputError("", "mean_power_w",
                          "expected " + std::to_string(r.range_bins) +
                              " columns (the radar's range bins, " + r.source_file + "), got " +
                              std::to_string(bins) + "; or give looks per bin");
  }
  const std::span<const float> p(mean_power_w.data(),
                                 static_cast<std::size_t>(mean_power_w.size()));
  std::optional<ris::GreytoneImage> g;
  {
    py::gil_scoped_release nogil;
    g = looks_per_bin ? ris::make_greytone_image(r, p, lines, bins, std::move(*looks_per_bin), seed)
                      : ris::make_greytone_image(r, p, lines, bins, r.near_slant_range_m,
                                                 r.range_bin_m, seed);
  }
  const std::vector<py::ssize_t> shape{lines, bins};
  py::dict out;
  out["grey"] = copy(g->greytone.data(), shape);
  out["speckled_power_w"] = copy(g->speckled_power_w.data(), shape);
  out["looks_per_bin"] = copy(g->looks_per_bin.data(), {bins});
  out["reference_power_w"] = g->map.reference_power_w();
  out["reference_greytone"] = g->map.reference_greytone();
  out["greytones_per_decade"] = g->map.greytones_per_decade();
  out["film"] = film_list(r.film);
  out["fading"] = r.switches.fading;
  return out;
}

// `ris topo`'s layers (apps/ris/cmd_topo.cpp): the same readers and
// compute_topo, the layers as numpy arrays (lines x bins of the window).
py::dict topo(const std::string& acquisition, const std::string& dem_path,
              const std::string& frequency, int burst, const std::string& swath, int oversample,
              bool full_grid, int threads) {
  ris::AcquisitionOptions ao;
  ao.frequency = frequency;
  if (burst >= 0) ao.burst = burst;
  ao.swath = swath;
  if (oversample < 0 || oversample > 64) {
    throw ris::InputError("", "oversample", "expected 0 (automatic) to 64");
  }
  ris::checked_thread_count(threads, "threads");  // the cap, as `ris topo --threads`
  ris::TopoLayers t;
  std::optional<ris::Acquisition> read;
  {
    py::gil_scoped_release nogil;
    read = ris::read_acquisition(acquisition, ao);
    const ris::Acquisition& acq = *read;
    const ris::EllipsoidalDem dem = ris::read_ellipsoidal_dem(dem_path);
    ris::TopoOptions opt;
    opt.oversample = oversample;
    opt.full_grid = full_grid;
    opt.threads = threads;
    t = ris::compute_topo(acq, dem, opt);
  }
  const ris::Acquisition& acq = *read;
  const ris::GridWindow& w = t.window;
  const std::vector<py::ssize_t> shape{w.lines, w.bins};
  py::dict d;
  d["lat_deg"] = copy(t.lat_deg.data(), shape);
  d["lon_deg"] = copy(t.lon_deg.data(), shape);
  d["hgt_m"] = copy(t.height_m.data(), shape);
  d["incidence_deg"] = copy(t.incidence_deg.data(), shape);
  d["incidence_geocentric_deg"] = copy(t.incidence_geocentric_deg.data(), shape);
  d["local_incidence_deg"] = copy(t.local_incidence_deg.data(), shape);
  d["look_deg"] = copy(t.look_deg.data(), shape);
  d["heading_deg"] = copy(t.heading_deg.data(), shape);
  d["gamma_area_m2"] = copy(t.gamma_area_m2.data(), shape);
  d["simamp"] = copy(t.simulated_amplitude.data(), shape);
  d["layover_shadow_mask"] = copy(t.mask.data(), shape);
  d["window"] = py::make_tuple(w.line0, w.lines, w.bin0, w.bins);
  d["grid_shape"] = py::make_tuple(acq.grid.lines, acq.grid.bins);
  d["oversample"] = t.oversample;
  d["beta_area_m2"] = t.beta_area_m2;
  d["unconverged"] = t.unconverged;
  d["dem_facets"] = t.dem_facets;
  d["mission"] = acq.mission;
  return d;
}

using FloatGrid = py::array_t<float, py::array::c_style | py::array::forcecast>;
using DoubleGrid = py::array_t<double, py::array::c_style | py::array::forcecast>;

// The values of an optional raster of `rows` x `cols` (None: empty), naming
// `key` when its shape differs.
std::span<const double> optional_grid(const std::optional<DoubleGrid>& a, py::ssize_t rows,
                                      py::ssize_t cols, const char* key) {
  if (!a) return {};
  if (a->ndim() != 2 || a->shape(0) != rows || a->shape(1) != cols) {
    throw ris::InputError("", key,
                          fmt::format("expected a {} x {} array like the image", rows, cols));
  }
  return {a->data(), static_cast<std::size_t>(a->size())};
}

// `ris quality`'s measures (ris/image/quality_report.h) of a power image.
py::object quality(const FloatGrid& power, const std::optional<DoubleGrid>& mask,
                   const std::optional<DoubleGrid>& categories,
                   const std::vector<std::array<int, 4>>& regions, int window, int mask_bit,
                   const std::vector<std::pair<int, int>>& targets, double line_spacing_m,
                   double range_bin_m) {
  if (power.ndim() != 2) throw ris::InputError("", "power", "expected a 2-D array (rows, cols)");
  const py::ssize_t rows = power.shape(0), cols = power.shape(1);
  const std::span<const double> mask_values = optional_grid(mask, rows, cols, "mask");
  ris::QualityRequest request;
  request.categories = optional_grid(categories, rows, cols, "categories");
  for (const auto& r : regions) request.regions.push_back({r[0], r[1], r[2], r[3]});
  request.window = window;
  request.mask_bit = mask_bit;
  request.targets = targets;
  request.line_spacing_m = line_spacing_m;
  request.range_bin_m = range_bin_m;
  nlohmann::json out;
  {
    py::gil_scoped_release nogil;
    const std::vector<std::uint8_t> bits = ris::quality_mask_bits(mask_values);
    out = ris::quality_measures(
        ris::IntensityView{
            std::span<const float>(power.data(), static_cast<std::size_t>(power.size())),
            static_cast<int>(cols), static_cast<int>(rows), bits},
        request);
  }
  return json_to_python(out);
}

// `ris compare`'s measures (ris/image/compare_report.h) of two power images
// on one grid; the real image as moved onto the simulation's.
py::tuple compare(const FloatGrid& simulated, const FloatGrid& real, bool register_images,
                  int max_shift_px, const std::optional<DoubleGrid>& mask,
                  const std::optional<DoubleGrid>& categories,
                  const std::optional<DoubleGrid>& local_incidence_deg) {
  if (simulated.ndim() != 2) {
    throw ris::InputError("", "simulated", "expected a 2-D array (rows, cols)");
  }
  const py::ssize_t rows = simulated.shape(0), cols = simulated.shape(1);
  if (real.ndim() != 2 || real.shape(0) != rows || real.shape(1) != cols) {
    throw ris::InputError(
        "", "real", fmt::format("expected a {} x {} array like the simulated image", rows, cols));
  }
  ris::CompareRequest request;
  request.register_images = register_images;
  request.max_shift_px = max_shift_px;
  request.mask = optional_grid(mask, rows, cols, "mask");
  request.categories = optional_grid(categories, rows, cols, "categories");
  request.local_incidence_deg =
      optional_grid(local_incidence_deg, rows, cols, "local_incidence_deg");
  std::optional<ris::CompareReport> rep;
  {
    py::gil_scoped_release nogil;
    rep = ris::compare_measures(
        std::span<const float>(simulated.data(), static_cast<std::size_t>(simulated.size())),
        std::span<const float>(real.data(), static_cast<std::size_t>(real.size())),
        static_cast<int>(cols), static_cast<int>(rows), request);
  }
  return py::make_tuple(json_to_python(rep->measures),
                        copy(rep->real_aligned.data(), {rows, cols}));
}

// The module's parts, bound in the order PYBIND11_MODULE calls them.
void bind_errors(py::module_& m) {
  g_input_error = PyErr_NewException("ris.InputError", PyExc_ValueError, nullptr);
  py::tuple bases = py::make_tuple(py::handle(g_input_error), py::handle(PyExc_FileNotFoundError));
  g_missing_error = PyErr_NewException("ris.InputFileNotFoundError", bases.ptr(), nullptr);
  m.add_object("InputError", py::handle(g_input_error));
  m.add_object("InputFileNotFoundError", py::handle(g_missing_error));
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const TextInputError& e) {
      raise_input_error(e, true);
    } catch (const ris::InputError& e) {
      raise_input_error(e, false);
    }
  });
}

void bind_scene(py::module_& m) {
  py::class_<PyScene>(m, "_Scene")
      .def_property_readonly("rows", [](const PyScene& s) { return s.scene->rows; })
      .def_property_readonly("cols", [](const PyScene& s) { return s.scene->cols; })
      .def_property_readonly("dx_m", [](const PyScene& s) { return s.scene->dx_m; })
      .def_property_readonly("dy_m", [](const PyScene& s) { return s.scene->dy_m; })
      .def_property_readonly("crs", [](const PyScene& s) { return s.scene->crs_wkt; })
      .def_property_readonly("path", [](const PyScene& s) { return s.path; })
      .def_property_readonly("name", [](const PyScene& s) { return s.name; })
      .def_property_readonly("library", [](const PyScene& s) { return s.library; })
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
}

void bind_radar(py::module_& m) {
  py::class_<PyRadar>(m, "_Radar")
      .def_property_readonly("source", [](const PyRadar& r) { return r.radar.source_file; })
      .def("params", [](const PyRadar& r) { return json_to_python(ris::radar_to_json(r.radar)); })
      .def("derived", [](const PyRadar& r) { return json_to_python(derived_in_degrees(r.radar)); })
      .def("film", [](const PyRadar& r) { return film_list(r.radar.film); });
  m.def("_load_radar", [](const std::string& path) { return PyRadar{ris::load_radar(path)}; });
  m.def("_radar_from_toml", &radar_from_text);
  // `ris greytone --radar`'s default (apps/ris/main.cpp's default_radar_path).
  m.def("_default_radar", [] {
    return PyRadar{ris::load_radar((ris::data_dir() / "radars" / "seed-fig4-5.toml").string())};
  });
  m.def("_greytone", &greytone);
}

// A run's SLAR / SAR images.
void bind_result_slar(py::class_<PyResult>& c) {
  c.def("mean_power_w",
        [](const PyResult& r) { return mean_power_nan(r.slar().image, r.slant_shape()); })
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
             const ris::SlarImage& img = r.slant_image();
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
             if (r.on_acquisition()) {  // local_incidence.tif, on the radar grid
               return view(r.acquisition().local_incidence_deg.data(), r.slant_shape(), self);
             }
             return view(r.slar().scene_maps.local_incidence_deg.data(), r.scene_shape(), self);
           })
      .def("layover_shadow_mask",
           [](py::object self) {
             const PyResult& r = self.cast<const PyResult&>();
             return view(r.acquisition().layover_shadow_mask.data(), r.slant_shape(), self);
           })
      .def("geocoded_power_w",
           [](const PyResult& r) {
             std::vector<float> g = ris::geocode_slant_image(
                 r.scene(), r.slar().track, r.slar().image, r.pictures().speckled_power_w);
             return copy(g.data(), r.scene_shape());
           })
      .def("geocoded_grey", [](const PyResult& r) {
        std::vector<std::uint8_t> g = ris::geocode_slant_grey(
            r.scene(), r.slar().track, r.slar().image, r.pictures().slant_grey);
        return copy(g.data(), r.scene_shape());
      });
}

// A run's PPI images (and the line spacing of either).
void bind_result_ppi(py::class_<PyResult>& c) {
  c.def("bscope_mean_power_w",
        [](const PyResult& r) { return mean_power_nan(r.ppi().bscope, r.bscope_shape()); })
      .def("bscope_speckled_power_w",
           [](const PyResult& r) {
             return copy(r.ppi_pictures().speckled_power_w.data(), r.bscope_shape());
           })
      .def("bscope_grey",
           [](const PyResult& r) {
             return copy(r.ppi_pictures().bscope_grey.data(), r.bscope_shape());
           })
      .def("bscope_mask",
           [](py::object self) {
             const PyResult& r = self.cast<const PyResult&>();
             return view(r.ppi().bscope.mask.data(), r.bscope_shape(), self);
           })
      .def("scope_power_w",
           [](const PyResult& r) {
             return copy(r.ppi_pictures().scope_power_w.data(), r.scope_shape());
           })
      .def("scope_mask",
           [](const PyResult& r) {
             return copy(r.ppi_pictures().scope_mask.data(), r.scope_shape());
           })
      .def("scope_grey",
           [](const PyResult& r) {
             return copy(r.ppi_pictures().scope_grey.data(), r.scope_shape());
           })
      .def("ray_azimuth_deg",
           [](const PyResult& r) {
             const ris::PpiGeometry& g = r.ppi().geometry;
             py::array_t<double> a(r.ppi().bscope.lines);
             for (py::ssize_t k = 0; k < a.size(); ++k)
               a.mutable_data()[k] = ris::rad_to_deg(g.azimuth_rad(g.pad + static_cast<int>(k)));
             return a;
           })
      .def("scope_axes_m",
           [](const PyResult& r) {
             const ris::PpiScopeGrid& g = r.ppi().scope_grid;
             py::array_t<double> east(g.size), north(g.size);
             for (int k = 0; k < g.size; ++k) {
               east.mutable_data()[k] = g.east_m(k);
               north.mutable_data()[k] = g.north_m(k);
             }
             return py::make_tuple(east, north);
           })
      .def("line_spacing_m", [](const PyResult& r) { return r.slant_image().line_spacing_m; })
      .def("scope_presentation",
           [](const PyResult& r) {
             return r.ppi().scope_grid.presentation == ris::PpiPresentation::slant ? "slant"
                                                                                   : "ground";
           })
      .def("site_m", [](const PyResult& r) {
        return py::make_tuple(r.ppi().geometry.site_x_m, r.ppi().geometry.site_y_m);
      });
}

void bind_result(py::module_& m) {
  py::class_<PyResult> c(m, "_Result");
  c.def_property_readonly("warnings", [](const PyResult& r) { return r.warnings; })
      .def_property_readonly("kind", [](const PyResult& r) { return ris::run_kind_name(*r.res); })
      .def_property_readonly(
          "summary",
          [](const PyResult& r) {
            return json_to_python(ris::run_summary_json(ris::run_summary(*r.res)));
          })
      .def_property_readonly("seed", [](const PyResult& r) { return r.res->info.seed; })
      .def("metadata", [](const PyResult& r) { return json_to_python(r.metadata()); });
  bind_result_slar(c);
  bind_result_ppi(c);
  c.def("rerender",
        [](PyResult& r, std::uint64_t seed, std::optional<std::vector<double>> film) {
          py::gil_scoped_release nogil;
          if (film) {
            const ris::FilmParams f = film_params(*film);
            ris::rerender(*r.res, seed, &f);
          } else {
            ris::rerender(*r.res, seed);
          }
        })
      .def("film",
           [](const PyResult& r) {
             r.require_in_memory();
             const ris::SlarRun* slar = ris::slar_image_run(*r.res);
             return film_list(slar != nullptr ? slar->sim.radar.film : r.ppi().radar.film);
           })
      .def("write", [](const PyResult& r, const std::string& dir) {
        py::gil_scoped_release nogil;
        return ris::write_run_products(*r.res, dir);
      });
  c.def_property_readonly("acquisition", [](const PyResult& r) { return r.on_acquisition(); })
      .def_property_readonly("out_dir", [](const PyResult& r) { return r.out_dir.string(); })
      .def("stream_summary", &PyResult::stream_summary)
      .def_property_readonly("channels", &PyResult::channel_names)
      .def("quad_pol_slc", &PyResult::quad_pol_slc)
      .def("quad_pol_matrix", &PyResult::quad_pol_matrix)
      .def("channel", &PyResult::channel);
  py::class_<PyRunOptions>(m, "_RunOptions")
      .def(py::init<>())
      .def_readwrite("scene_path", &PyRunOptions::scene_path)
      .def_readwrite("backscatter", &PyRunOptions::backscatter)
      .def_readwrite("targets", &PyRunOptions::targets)
      .def_readwrite("seed", &PyRunOptions::seed)
      .def_readwrite("threads", &PyRunOptions::threads)
      .def_readwrite("out_dir", &PyRunOptions::out_dir)
      .def_readwrite("stream", &PyRunOptions::stream)
      .def_readwrite("block_lines", &PyRunOptions::block_lines)
      .def_readwrite("products", &PyRunOptions::products)
      .def_readwrite("compress", &PyRunOptions::compress)
      .def_readwrite("overviews", &PyRunOptions::overviews)
      .def_readwrite("calibrated", &PyRunOptions::calibrated)
      .def_readwrite("acquisition", &PyRunOptions::acquisition)
      .def_readwrite("frequency", &PyRunOptions::frequency)
      .def_readwrite("burst", &PyRunOptions::burst)
      .def_readwrite("swath", &PyRunOptions::swath)
      .def_readwrite("dem", &PyRunOptions::dem)
      .def_readwrite("land_cover", &PyRunOptions::land_cover)
      .def_readwrite("category", &PyRunOptions::category)
      .def_readwrite("full_grid", &PyRunOptions::full_grid)
      .def_readwrite("earth", &PyRunOptions::earth);
  m.def("_run", &run, py::arg("scene").none(true), py::arg("radar"), py::arg("options"),
        py::arg("progress").none(true));
}

void bind_backscatter(py::module_& m) {
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
  m.def("_permittivity", &permittivity);
  // The dielectric registry's names (ris/backscatter/dielectric.h), in its order.
  m.def("_dielectric_models", [] {
    std::vector<std::string> out;
    for (std::string_view n : ris::dielectric_model_names()) out.emplace_back(n);
    return out;
  });
  m.def("_dobson_conductivities", [] {
    std::vector<std::string> out;
    for (std::string_view n : ris::dobson_conductivity_names()) out.emplace_back(n);
    return out;
  });
}

}  // namespace

void bind_study(py::module_& m);   // study_bindings.cpp
void bind_sensor(py::module_& m);  // sensor_bindings.cpp

PYBIND11_MODULE(_ris, m) {
  m.doc() = "ris radar image simulator: C++ core bindings (use the `ris` package)";
  m.attr("__version__") = RIS_VERSION;
  bind_errors(m);
  bind_scene(m);
  bind_radar(m);
  bind_result(m);
  bind_backscatter(m);
  bind_study(m);
  bind_sensor(m);
  m.def("_data_dir", [] { return ris::data_dir().string(); });
  m.def("_topo", &topo);
  m.def("_quality", &quality);
  m.def("_compare", &compare);
  m.def("_list_models", [] {
    std::vector<std::pair<std::string, std::string>> out;
    for (const ris::ModelInfo& i : ris::backscatter_model_names())
      out.emplace_back(i.name, i.summary);
    return out;
  });
}
