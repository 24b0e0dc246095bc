#include "ris/backscatter/sigma0_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "ris/io/safe_paths.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

std::string trim(std::string_view s) {
  size_t a = 0;
  size_t b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return std::string(s.substr(a, b - a));
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

double parse_number(const std::string& path, int line_no, const std::string& column,
                    const std::string& text) {
  double v = 0.0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, v);
  if (ec != std::errc() || ptr != end || !std::isfinite(v)) {
    throw InputError(path, fmt::format("line {}", line_no),
                     fmt::format("column {}: expected a finite number, got \"{}\"", column, text));
  }
  return v;
}

bool same_frequency(double a_hz, double b_hz) {
  return std::abs(a_hz - b_hz) <= 1e-6 * std::max(std::abs(a_hz), std::abs(b_hz));
}

}  // namespace

Sigma0Table Sigma0Table::load(const std::string& path) {
  require_regular_input(path);
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open the sigma0 table");
  Sigma0Table table;
  table.path_ = path;
  const std::vector<std::string> expected = {"category", "frequency_ghz", "polarisation",
                                             "angle_deg", "sigma0_db"};
  bool header_seen = false;
  std::set<std::string> finished;  // curves already closed, to reject split curves
  std::string line;
  int line_no = 0;
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      // Directives: "# clamp: true|false", "# category N: name".
      const std::string body = trim(std::string_view(t).substr(1));
      if (body.rfind("clamp:", 0) == 0) {
        const std::string v = trim(std::string_view(body).substr(6));
        if (v != "true" && v != "false") {
          throw InputError(path, fmt::format("line {}", line_no),
                           "clamp: expected true or false, got \"" + v + "\"");
        }
        table.clamp_ = v == "true";
      } else if (body.rfind("category ", 0) == 0 && body.find(':') != std::string::npos) {
        const size_t colon = body.find(':');
        const std::string id_text = trim(std::string_view(body).substr(9, colon - 9));
        int id = 0;
        auto [p, ec] = std::from_chars(id_text.data(), id_text.data() + id_text.size(), id);
        if (ec == std::errc() && p == id_text.data() + id_text.size() && id >= 0 && id <= 65535) {
          table.names_[static_cast<std::uint16_t>(id)] =
              trim(std::string_view(body).substr(colon + 1));
        }
      }
      continue;
    }
    const std::vector<std::string> f = split_csv(t);
    if (!header_seen) {
      if (f != expected) {
        throw InputError(path, fmt::format("line {}", line_no),
                         "expected the header "
                         "\"category,frequency_ghz,polarisation,angle_deg,sigma0_db\"");
      }
      header_seen = true;
      continue;
    }
    if (f.size() != expected.size()) {
      throw InputError(path, fmt::format("line {}", line_no),
                       fmt::format("expected 5 comma-separated fields, got {}", f.size()));
    }
    const double cat = parse_number(path, line_no, "category", f[0]);
    if (cat < 1 || cat > 65535 || cat != std::floor(cat)) {
      throw InputError(path, fmt::format("line {}", line_no),
                       "column category: expected an integer id in 1..65535, got " + f[0]);
    }
    const double freq_ghz = parse_number(path, line_no, "frequency_ghz", f[1]);
    if (freq_ghz <= 0.0) {
      throw InputError(path, fmt::format("line {}", line_no),
                       "column frequency_ghz: expected a frequency > 0 GHz, got " + f[1]);
    }
    Polarisation pol{};
    try {
      pol = parse_polarisation(f[2]);
    } catch (const std::invalid_argument& e) {
      throw InputError(path, fmt::format("line {}", line_no),
                       std::string("column polarisation: ") + e.what());
    }
    const double angle_deg = parse_number(path, line_no, "angle_deg", f[3]);
    if (angle_deg < 0.0 || angle_deg > 90.0) {
      throw InputError(path, fmt::format("line {}", line_no),
                       "column angle_deg: expected an incidence angle in [0, 90] deg, got " + f[3]);
    }
    const double s0_db = parse_number(path, line_no, "sigma0_db", f[4]);

    const auto category = static_cast<std::uint16_t>(cat);
    const double freq_hz = freq_ghz * 1e9;
    const std::string curve_key = fmt::format("{} {:g} {}", category, freq_ghz, to_string(pol));
    Curve* cur = table.curves_.empty() ? nullptr : &table.curves_.back();
    const bool continues = cur != nullptr && cur->category == category &&
                           same_frequency(cur->frequency_hz, freq_hz) && cur->polarisation == pol;
    if (!continues) {
      if (cur != nullptr) {
        finished.insert(fmt::format("{} {:g} {}", cur->category, cur->frequency_hz / 1e9,
                                    to_string(cur->polarisation)));
      }
      if (finished.count(curve_key) != 0) {
        throw InputError(path, fmt::format("line {}", line_no),
                         fmt::format("rows for category {} at {:g} GHz {} appear again after "
                                     "other rows; keep each curve's rows together",
                                     category, freq_ghz, to_string(pol)));
      }
      table.curves_.push_back(Curve{category, freq_hz, pol, {}, {}, line_no});
      cur = &table.curves_.back();
    }
    const double angle_rad = deg_to_rad(angle_deg);
    if (!cur->angle_rad.empty() && !(angle_rad > cur->angle_rad.back())) {
      throw InputError(path, fmt::format("line {}", line_no),
                       fmt::format("angles must increase within a curve: {:g} deg follows {:g} "
                                   "deg (category {}, {:g} GHz {})",
                                   angle_deg, rad_to_deg(cur->angle_rad.back()), category, freq_ghz,
                                   to_string(pol)));
    }
    cur->angle_rad.push_back(angle_rad);
    cur->sigma0_db.push_back(s0_db);
  }
  if (!header_seen || table.curves_.empty()) {
    throw InputError(path, "", "the table has no rows (expected a header and data rows)");
  }
  return table;
}

std::vector<std::uint16_t> Sigma0Table::categories() const {
  std::set<std::uint16_t> ids;
  for (const Curve& c : curves_) ids.insert(c.category);
  return {ids.begin(), ids.end()};
}

std::string Sigma0Table::name_of(std::uint16_t category) const {
  auto it = names_.find(category);
  return it == names_.end() ? std::string() : it->second;
}

const Sigma0Table::Curve* Sigma0Table::find(std::uint16_t category, const RadarBand& band) const {
  for (const Curve& c : curves_) {
    if (c.category == category && c.polarisation == band.polarisation &&
        same_frequency(c.frequency_hz, band.frequency_hz)) {
      return &c;
    }
  }
  return nullptr;
}

std::string Sigma0Table::bands_of(std::uint16_t category) const {
  std::string out;
  for (const Curve& c : curves_) {
    if (c.category != category) continue;
    if (!out.empty()) out += ", ";
    out += fmt::format("{:g} GHz {}", c.frequency_hz / 1e9, to_string(c.polarisation));
  }
  return out.empty() ? std::string("none") : out;
}

double Sigma0Table::eval_db(const Curve& curve, double incidence_rad, bool clamp) const {
  const std::vector<double>& a = curve.angle_rad;
  const std::vector<double>& v = curve.sigma0_db;
  // A tolerance of 1e-9 rad lets a table ending at exactly 90 deg cover pi/2.
  constexpr double kTol = 1e-9;
  if (incidence_rad < a.front() - kTol || incidence_rad > a.back() + kTol) {
    if (!clamp) {
      throw InputError(
          path_, fmt::format("line {}", curve.first_line),
          fmt::format("incidence {:.3f} deg is outside the table's {:g}..{:g} deg "
                      "for category {} at {:g} GHz {} (extend the table or add "
                      "\"# clamp: true\")",
                      rad_to_deg(incidence_rad), rad_to_deg(a.front()), rad_to_deg(a.back()),
                      curve.category, curve.frequency_hz / 1e9, to_string(curve.polarisation)));
    }
  }
  if (incidence_rad <= a.front()) return v.front();
  if (incidence_rad >= a.back()) return v.back();
  const auto it = std::upper_bound(a.begin(), a.end(), incidence_rad);
  const size_t i = static_cast<size_t>(it - a.begin());  // a[i-1] <= x < a[i]
  const double f = (incidence_rad - a[i - 1]) / (a[i] - a[i - 1]);
  return v[i - 1] + f * (v[i] - v[i - 1]);
}

namespace {

class TableSource final : public Sigma0Source {
 public:
  explicit TableSource(std::shared_ptr<const Sigma0Table> table)
      : table_(std::move(table)), ids_(table_->categories()) {}

  bool has_category(std::uint16_t category) const override {
    return std::binary_search(ids_.begin(), ids_.end(), category);
  }
  double sigma0(std::uint16_t category, double incidence_rad,
                const RadarBand& band) const override {
    const Sigma0Table::Curve* c = table_->find(category, band);
    if (c == nullptr) {
      throw InputError(table_->path(), "",
                       fmt::format("no rows for category {} at {:g} GHz {} (it has: {})", category,
                                   band.frequency_hz / 1e9, to_string(band.polarisation),
                                   table_->bands_of(category)));
    }
    return std::pow(10.0, table_->eval_db(*c, incidence_rad) / 10.0);
  }
  std::string category_name(std::uint16_t category) const override {
    const std::string n = table_->name_of(category);
    return n.empty() ? std::to_string(category) : n;
  }
  std::string description() const override { return "table " + table_->path(); }
  std::vector<std::uint16_t> category_ids() const override { return ids_; }

 private:
  std::shared_ptr<const Sigma0Table> table_;
  std::vector<std::uint16_t> ids_;
};

}  // namespace

std::unique_ptr<Sigma0Source> make_table_source(std::shared_ptr<const Sigma0Table> table) {
  return std::make_unique<TableSource>(std::move(table));
}

}  // namespace ris
