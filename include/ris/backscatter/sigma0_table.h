// A measured (or tabulated) sigma0 table read from CSV: sigma0 in dB at
// listed incidence angles per category, frequency and polarisation, linear in
// dB between angles (MODEL.md section 4, table model).
//
// File format (docs/backscatter.md):
//   # comment lines start with '#'; two directives may appear in them:
//   # clamp: true                  angles outside a curve take its end value
//   # category 4: short corn       a display name for a category
//   category,frequency_ghz,polarisation,angle_deg,sigma0_db
//   4,8.6,HH,0,2.31
//   4,8.6,HH,1,2.05
// Rows of one (category, frequency, polarisation) curve must be contiguous
// and their angles strictly increasing; anything else is an InputError naming
// the file and line.
//
// Example:
//   ris::Sigma0Table t = ris::Sigma0Table::load("data/backscatter/ku-geometric-8.6GHz.csv");
//   const ris::Sigma0Table::Curve* c = t.find(4, ris::RadarBand{8.6e9, ris::Polarisation::HH});
//   double s0_db = t.eval_db(*c, ris::deg_to_rad(30.0));
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "ris/backscatter/polarisation.h"
#include "ris/backscatter/sigma0_source.h"

namespace ris {

class Sigma0Table {
 public:
  struct Curve {
    std::uint16_t category = 0;
    double frequency_hz = 0.0;
    Polarisation polarisation = Polarisation::HH;
    std::vector<double> angle_rad;  // strictly increasing
    std::vector<double> sigma0_db;
    int first_line = 0;  // for messages
  };

  static Sigma0Table load(const std::string& path);

  const std::string& path() const { return path_; }
  bool clamp() const { return clamp_; }
  const std::vector<Curve>& curves() const { return curves_; }
  // Categories with at least one curve, ascending.
  std::vector<std::uint16_t> categories() const;
  // Name given by a "# category N: name" directive, or "".
  std::string name_of(std::uint16_t category) const;

  // The curve for a category and band (frequency equal to within 1e-6
  // relative), or nullptr.
  const Curve* find(std::uint16_t category, const RadarBand& band) const;
  // "8.6 GHz HH, 8.6 GHz VV": the bands a category has, for messages.
  std::string bands_of(std::uint16_t category) const;

  // sigma0 in dB at incidence_rad, linear in dB between angles. Outside the
  // curve: its end value when clamp is set, else an InputError naming the
  // file, the curve and its angle range.
  double eval_db(const Curve& curve, double incidence_rad, bool clamp) const;
  double eval_db(const Curve& curve, double incidence_rad) const {
    return eval_db(curve, incidence_rad, clamp_);
  }

 private:
  std::string path_;
  bool clamp_ = false;
  std::vector<Curve> curves_;
  std::map<std::uint16_t, std::string> names_;
};

// The table file as a Sigma0Source: every category with a curve. A band the
// table lacks for a category is an InputError naming the bands it has.
std::unique_ptr<Sigma0Source> make_table_source(std::shared_ptr<const Sigma0Table> table);

}  // namespace ris
