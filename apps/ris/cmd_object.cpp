// ris object rcs: the monostatic radar cross section of a canonical reflector
// or of a mesh file, by the shooting-and-bouncing-rays tracer
// (src/objects/sbr.cpp, docs/objects.md).
//
//   ris object rcs --kind trihedral-square --size 0.3 --frequency "9.6 GHz"
//   ris object rcs --kind dihedral --size 0.3 --size2 0.25 --azimuth -30:30:1 --out d.csv
//   ris object rcs --mesh tower.obj --scale 0.01 --material concrete --elevation 30
//
// Prints sigma in dBsm for HH, HV, VH, VV (backscatter alignment) per
// azimuth, the tracer's ray count and rays per second.
#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cmath>

#include "command_registry.h"
#include "number_list.h"
#include "ris/io/atomic_file.h"
#include "ris/objects/material.h"
#include "ris/objects/mesh.h"
#include "ris/objects/mesh_load.h"
#include "ris/objects/sbr.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace {

using ris::InputError;

struct Options {
  std::string kind;
  std::string mesh;
  double size = 0.0;
  double size2 = 0.0;
  double scale = 1.0;
  std::string material = "pec";
  std::string materials = "";
  std::string frequency = "10 GHz";
  std::string azimuth = "0";
  double elevation_deg = 0.0;
  double roll_deg = 0.0;
  double tilt_deg = 0.0;
  int bounces = 3;
  double rays_per_wavelength = 10.0;
  std::string out;
};

ris::TriangleMesh canonical(const Options& o, double lambda) {
  if (!(o.size > 0.0)) throw InputError("", "--size", "expected a size > 0 m");
  const double b = o.size2 > 0.0 ? o.size2 : o.size;
  if (o.kind == "plate") return ris::make_plate(o.size, b);
  if (o.kind == "dihedral") return ris::make_dihedral(o.size, b);
  if (o.kind == "trihedral-square") return ris::make_trihedral_square(o.size);
  if (o.kind == "trihedral-triangular") return ris::make_trihedral_triangular(o.size);
  // Facets well inside the first Fresnel zone sqrt(lambda r) (docs/objects.md).
  const double fresnel = std::sqrt(lambda * o.size);
  if (o.kind == "sphere") {
    int n = 0;
    while (n < 7 && 1.1 * o.size / std::pow(2.0, n) > fresnel / 8.0) ++n;
    return ris::make_sphere(o.size, n);
  }
  if (o.kind == "cylinder") {
    if (!(o.size2 > 0.0)) throw InputError("", "--size2", "a cylinder needs its length (m)");
    const int n =
        std::max(64, static_cast<int>(std::ceil(2.0 * ris::kPi * o.size / (fresnel / 20.0))));
    return ris::make_cylinder(o.size, o.size2, n);
  }
  throw InputError("", "--kind",
                   "expected plate, dihedral, trihedral-square, trihedral-triangular, sphere or "
                   "cylinder, got \"" +
                       o.kind + "\"");
}

void run(const Options& o) {
  double f_hz = 0.0;
  try {
    f_hz = ris::parse_quantity(o.frequency, ris::Quantity::frequency);
  } catch (const std::invalid_argument& e) {
    throw InputError("", "--frequency", e.what());
  }
  if (!(f_hz > 0.0)) throw InputError("", "--frequency", "expected a frequency > 0");
  if (o.kind.empty() == o.mesh.empty()) {
    throw InputError("", "--kind", "give either --kind (a canonical reflector) or --mesh FILE");
  }
  if (o.bounces < 1 || o.bounces > 7) throw InputError("", "--bounces", "expected 1..7");
  if (!(o.rays_per_wavelength >= 1.0 && o.rays_per_wavelength <= 100.0)) {
    throw InputError("", "--rays-per-wavelength", "expected 1..100 (10 is the PO-SBR norm)");
  }
  const double lambda = ris::kSpeedOfLight_m_per_s / f_hz;
  const ris::MeshPlacement placement{.scale = o.mesh.empty() ? 1.0 : o.scale,
                                     .roll_rad = ris::deg_to_rad(o.roll_deg),
                                     .tilt_rad = ris::deg_to_rad(o.tilt_deg)};
  ris::TriangleMesh mesh;
  if (o.mesh.empty()) {
    mesh = canonical(o, lambda);
    ris::place(mesh, placement);
  } else {
    mesh = ris::load_mesh(o.mesh, placement);
  }
  const ris::MaterialLibrary lib =
      ris::MaterialLibrary::load(o.materials.empty() ? ris::default_materials_path() : o.materials);
  const ris::Material& mat = lib.find(o.material);
  ris::SurfaceResponse surf;
  surf.pec = mat.is_pec();
  if (!surf.pec) surf.eps = mat.permittivity(f_hz);
  surf.rms_height_m = mat.rms_height_m;
  const std::vector<double> azimuths = ris::app::parse_number_list(o.azimuth, "--azimuth", "deg");
  if (azimuths.empty()) throw InputError("", "--azimuth", "no azimuth given");
  ris::EmbreeScene scene(mesh);
  ris::SbrOptions opt;
  opt.max_bounces = o.bounces;
  opt.rays_per_wavelength = o.rays_per_wavelength;
  std::string csv = "azimuth_deg,elevation_deg,hh_dbsm,hv_dbsm,vh_dbsm,vv_dbsm\n";
  nlohmann::json js = nlohmann::json::array();
  std::int64_t rays = 0;
  double seconds = 0.0;
  fmt::print("{:>9} {:>9} {:>9} {:>9} {:>9}   (dBsm, {} triangles, {:g} GHz, {})\n", "az_deg", "HH",
             "HV", "VH", "VV", mesh.triangles.size(), f_hz * 1e-9, o.material);
  for (double az : azimuths) {
    const ris::SbrResult r = ris::trace_sbr(
        scene, {surf}, f_hz,
        ris::radar_direction(ris::deg_to_rad(az), ris::deg_to_rad(o.elevation_deg)), opt);
    std::array<double, 4> dbsm{};
    for (int q = 0; q < 4; ++q) dbsm[q] = 10.0 * std::log10(std::max(r.rcs_m2[q], 1e-30));
    fmt::print("{:9.2f} {:9.2f} {:9.2f} {:9.2f} {:9.2f}\n", az, dbsm[0], dbsm[1], dbsm[2], dbsm[3]);
    csv += fmt::format("{},{},{:.4f},{:.4f},{:.4f},{:.4f}\n", az, o.elevation_deg, dbsm[0], dbsm[1],
                       dbsm[2], dbsm[3]);
    js.push_back({{"azimuth_deg", az},
                  {"elevation_deg", o.elevation_deg},
                  {"hh_dbsm", dbsm[0]},
                  {"hv_dbsm", dbsm[1]},
                  {"vh_dbsm", dbsm[2]},
                  {"vv_dbsm", dbsm[3]},
                  {"rays", r.rays_traced}});
    rays += r.rays_traced;
    seconds += r.seconds;
  }
  fmt::print("tracer: {} rays (bounce and visibility segments), {:.3g} s, {:.3g} M rays/s\n", rays,
             seconds, seconds > 0.0 ? 1e-6 * static_cast<double>(rays) / seconds : 0.0);
  if (!o.out.empty()) {
    const bool json = o.out.size() > 5 && o.out.substr(o.out.size() - 5) == ".json";
    ris::write_text_file_atomic(o.out, json ? js.dump(2) + "\n" : csv);
  }
}

void add_object(CLI::App& app) {
  auto* object =
      app.add_subcommand("object", "Cultural objects: RCS by ray tracing (docs/objects.md)");
  object->require_subcommand(1);
  auto* cmd = object->add_subcommand("rcs", "Monostatic RCS (dBsm, HH HV VH VV) by SBR");
  auto opts = std::make_shared<Options>();
  cmd->add_option("--kind", opts->kind,
                  "plate, dihedral, trihedral-square, trihedral-triangular, sphere, cylinder");
  cmd->add_option("--size", opts->size,
                  "m: plate/dihedral height, trihedral edge, sphere/cylinder radius");
  cmd->add_option("--size2", opts->size2, "m: plate/dihedral width, cylinder length");
  cmd->add_option("--mesh", opts->mesh, "A mesh file (OBJ, PLY, STL, glTF) instead of --kind");
  cmd->add_option("--scale", opts->scale, "Scale of the mesh file")->capture_default_str();
  cmd->add_option("--material", opts->material, "Material name")->capture_default_str();
  cmd->add_option("--materials", opts->materials, "Material library (default: the shipped one)");
  cmd->add_option("--frequency,-f", opts->frequency, "Frequency")->capture_default_str();
  cmd->add_option("--azimuth", opts->azimuth, "deg, or a sweep a:b:step")->capture_default_str();
  cmd->add_option("--elevation", opts->elevation_deg, "deg")->capture_default_str();
  cmd->add_option("--roll", opts->roll_deg, "Rotation about the boresight, deg");
  cmd->add_option("--tilt", opts->tilt_deg, "Boresight raised by, deg");
  cmd->add_option("--bounces", opts->bounces, "Maximum bounces")->capture_default_str();
  cmd->add_option("--rays-per-wavelength", opts->rays_per_wavelength, "Ray density")
      ->capture_default_str();
  cmd->add_option("--out,-o", opts->out, "Also write a CSV (or .json) of the table");
  cmd->callback([opts] { run(*opts); });
}

const ris::app::Registration reg{"object", add_object};

}  // namespace
