// Fresnel coefficients against their closed forms, the Brewster angle, the
// Ament factor, and the material library's values and refusals.
#include <cmath>
#include <complex>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "ris/objects/fresnel.h"
#include "ris/objects/material.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

TEST(Fresnel, NormalIncidenceIsTheClosedFormWithOppositeSigns) {
  const std::complex<double> eps{5.24, -0.7};
  const FresnelPair r = fresnel_reflection(eps, 1.0);
  const std::complex<double> n = std::sqrt(eps);
  const std::complex<double> expected = (1.0 - n) / (1.0 + n);  // Born & Wolf 1.5 (20)
  EXPECT_NEAR(std::abs(r.s - expected), 0.0, 1e-14);
  EXPECT_NEAR(std::abs(r.p + expected), 0.0, 1e-14);  // r_p = -r_s at normal incidence
}

TEST(Fresnel, ObliqueRealPermittivityMatchesSnellForm) {
  // Born & Wolf's forms with Snell's law: r_s = -sin(t - t2)/sin(t + t2),
  // r_p = tan(t - t2)/tan(t + t2) (their sign of r_p is ours: PEC limit +1).
  const double eps = 4.0;
  for (double deg : {10.0, 30.0, 50.0, 70.0, 85.0}) {
    const double t = deg_to_rad(deg);
    const double t2 = std::asin(std::sin(t) / std::sqrt(eps));
    const FresnelPair r = fresnel_reflection({eps, 0.0}, std::cos(t));
    EXPECT_NEAR(r.s.real(), -std::sin(t - t2) / std::sin(t + t2), 1e-12) << deg;
    EXPECT_NEAR(r.p.real(), std::tan(t - t2) / std::tan(t + t2), 1e-12) << deg;
  }
}

TEST(Fresnel, BrewsterAngleCancelsTm) {
  for (double eps : {2.0, 4.0, 6.31, 80.0}) {
    const double tb = std::atan(std::sqrt(eps));
    EXPECT_NEAR(std::abs(fresnel_reflection({eps, 0.0}, std::cos(tb)).p), 0.0, 1e-12) << eps;
    EXPECT_GT(std::abs(fresnel_reflection({eps, 0.0}, std::cos(tb + 0.05)).p), 1e-3);
  }
}

TEST(Fresnel, LargePermittivityTendsToThePerfectConductor) {
  const FresnelPair r = fresnel_reflection({1.0, -1e9}, std::cos(0.5));
  EXPECT_NEAR(std::abs(r.s - pec_reflection().s), 0.0, 1e-3);
  EXPECT_NEAR(std::abs(r.p - pec_reflection().p), 0.0, 1e-3);
}

TEST(Fresnel, AmentFactorIsExpMinusTwoKhCosSquared) {
  const double k = 2.0 * kPi / 0.03, h = 0.002, c = std::cos(0.3);
  EXPECT_NEAR(ament_amplitude_factor(k, h, c), std::exp(-2.0 * std::pow(k * h * c, 2)), 1e-15);
  EXPECT_DOUBLE_EQ(ament_amplitude_factor(k, 0.0, c), 1.0);
}

TEST(Materials, ShippedLibraryGivesItuValues) {
  const MaterialLibrary lib = MaterialLibrary::load(default_materials_path());
  const std::complex<double> eps = lib.find("concrete").permittivity(10e9);
  EXPECT_NEAR(eps.real(), 5.24, 1e-12);
  // ITU-R P.2040-1 eq. 9b: eps'' = 17.98 sigma / f_GHz.
  EXPECT_NEAR(-eps.imag(), 17.98 * 0.0462 * std::pow(10.0, 0.7822) / 10.0, 1e-3);
  for (const char* name : {"pec", "concrete", "brick", "glass", "asphalt", "wood", "water"}) {
    EXPECT_NO_THROW(lib.find(name)) << name;
  }
  const std::complex<double> water = lib.find("water").permittivity(10e9);
  EXPECT_NEAR(water.real(), 63.0, 3.0);  // pure water at 10 GHz, 20 C: about 63 - j 31
  EXPECT_NEAR(-water.imag(), 31.0, 3.0);
  EXPECT_TRUE(lib.find("pec").is_pec());
}

std::string write_library(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::temp_directory_path() / ("ris_materials_" + name + ".toml");
  std::ofstream(path) << text;
  return path.string();
}

void expect_refused(const std::string& path, const std::string& key_part) {
  try {
    (void)MaterialLibrary::load(path);
    ADD_FAILURE() << "accepted " << path;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path);
    EXPECT_NE(std::string(e.what()).find(key_part), std::string::npos) << e.what();
  }
}

const char* kGlass =
    "[material.glass]\nkind = \"itu-p2040\"\na = 6.31\nb = 0.0\nc = 0.0036\nd = 1.3394\n"
    "f_min_ghz = 0.1\nf_max_ghz = 100.0\nrms_height_m = 0.0\ncitation = \"ITU\"\n";

TEST(Materials, RefusesUnknownKeyNamingMaterialAndKey) {
  expect_refused(write_library("unknown", std::string(kGlass) + "colour = \"blue\"\n"),
                 "material.glass.colour");
}

TEST(Materials, RefusesNegativeLoss) {
  expect_refused(
      write_library("loss",
                    "[material.odd]\nkind = \"constant\"\neps_re = 3.0\neps_im = -0.1\n"
                    "f_min_ghz = 1\nf_max_ghz = 10\nrms_height_m = 0\ncitation = \"x\"\n"),
      "material.odd.eps_im");
  expect_refused(write_library("cneg",
                               "[material.g]\nkind = \"itu-p2040\"\na = 2\nb = 0\nc = -1\n"
                               "d = 0\nf_min_ghz = 1\nf_max_ghz = 10\nrms_height_m = 0\n"
                               "citation = \"x\"\n"),
                 "material.g.c");
}

TEST(Materials, RefusesMissingKeyAndBadKind) {
  expect_refused(write_library("missing", "[material.m]\nkind = \"pec\"\ncitation = \"x\"\n"),
                 "rms_height_m");
  expect_refused(write_library("kind",
                               "[material.m]\nkind = \"gold\"\nrms_height_m = 0\n"
                               "citation = \"x\"\n"),
                 "material.m.kind");
}

TEST(Materials, RefusesFrequencyOutsideValidity) {
  const MaterialLibrary lib = MaterialLibrary::load(write_library("glass", kGlass));
  EXPECT_NO_THROW(lib.find("glass").permittivity(10e9));
  try {
    (void)lib.find("glass").permittivity(200e9);
    ADD_FAILURE() << "200 GHz accepted";
  } catch (const InputError& e) {
    EXPECT_NE(e.key().find("material.glass"), std::string::npos);
  }
  EXPECT_THROW((void)lib.find("steel"), InputError);
}

}  // namespace
}  // namespace ris
