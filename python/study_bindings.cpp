// The study from Python (ris.study): the bindings over
// ris/analysis/study_request.h, the code `ris study` runs, so the same
// inputs give the command line's bytes. The argument checks and the tables
// as Python data are python/ris/__init__.py's; errors are translated by
// ris_module.cpp's exception translator (InputError keeps its class).
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>

#include "ris/analysis/study.h"
#include "ris/analysis/study_request.h"

namespace py = pybind11;

namespace {

// A finished study: what it was asked (the paths, for the products), its
// result and its tables as the files hold them.
struct PyStudy {
  ris::ResolvedStudy study;
  std::shared_ptr<const ris::StudyResult> result;
  ris::StudyTables tables;
};

PyStudy run_study(ris::StudyRequest request, std::function<void(std::string, double)> progress,
                  const std::string& out_dir) {
  request.command_line_keys = false;  // errors name Python's arguments
  if (progress) {
    request.progress = [progress](std::string_view stage, double fraction) {
      py::gil_scoped_acquire gil;
      progress(std::string(stage), fraction);
    };
  }
  PyStudy out;
  {
    py::gil_scoped_release nogil;
    out.study = ris::resolve_study(request);
    out.result = std::make_shared<const ris::StudyResult>(ris::run_resolved_study(out.study));
    out.tables = ris::study_tables(*out.result, out.study.info);
    if (!out_dir.empty()) {
      ris::write_study_products(out_dir, *out.result, out.study.info, out.study.style);
    }
  }
  out.study.options.progress = nullptr;  // holds a Python callable: not kept past the run
  return out;
}

py::list panels(const PyStudy& s) {
  py::list out;
  for (const ris::StudyPanel& p : s.result->panels) {
    py::array_t<std::uint8_t> grey({p.lines, p.bins});
    std::copy(p.slant_grey.begin(), p.slant_grey.end(), grey.mutable_data());
    py::dict d;
    d["band"] = p.band.label();
    d["frequency_hz"] = p.band.frequency_hz;
    d["polarisation"] = ris::to_string(p.band.polarisation);
    d["slant_grey"] = grey;
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_study(py::module_& m) {
  py::class_<ris::StudyRequest>(m, "_StudyRequest")
      .def(py::init<>())
      .def_readwrite("study_file", &ris::StudyRequest::study_file)
      .def_readwrite("scene", &ris::StudyRequest::scene)
      .def_readwrite("radar", &ris::StudyRequest::radar)
      .def_readwrite("backscatter", &ris::StudyRequest::backscatter)
      .def_readwrite("bands", &ris::StudyRequest::bands)
      .def_readwrite("seed", &ris::StudyRequest::seed)
      .def_readwrite("range_lo_fraction", &ris::StudyRequest::range_lo_fraction)
      .def_readwrite("range_hi_fraction", &ris::StudyRequest::range_hi_fraction)
      .def_readwrite("incidence_bin", &ris::StudyRequest::incidence_bin)
      .def_readwrite("null_check", &ris::StudyRequest::null_check)
      .def_readwrite("panel_px", &ris::StudyRequest::panel_px)
      .def_readwrite("threads", &ris::StudyRequest::threads);
  py::class_<PyStudy>(m, "_Study")
      .def_property_readonly("panels", &panels)
      .def_property_readonly("categories_csv",
                             [](const PyStudy& s) { return s.tables.categories_csv; })
      .def_property_readonly("separability_csv",
                             [](const PyStudy& s) { return s.tables.separability_csv; })
      .def_property_readonly("separability_bins_csv",
                             [](const PyStudy& s) { return s.tables.separability_bins_csv; })
      .def_property_readonly("metadata_json",
                             [](const PyStudy& s) { return s.tables.metadata.dump(); })
      .def_property_readonly("title", [](const PyStudy& s) { return s.study.config.name; })
      .def("write", [](const PyStudy& s, const std::string& dir) {
        py::gil_scoped_release nogil;
        ris::write_study_products(dir, *s.result, s.study.info, s.study.style);
      });
  m.def("_study", &run_study, py::arg("request"), py::arg("progress").none(true),
        py::arg("out_dir"));
}
