// Reads a study description file (ris/analysis/study_config.h).
#include "ris/analysis/study_config.h"

#include <fmt/format.h>

#include <filesystem>

#include "ris/io/config_table.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

std::optional<std::string> path_key(ConfigTable& t, const std::string& key,
                                    const std::filesystem::path& base) {
  const std::optional<std::string> v = t.get_string_opt(key);
  if (!v) return std::nullopt;
  std::filesystem::path p(*v);
  if (p.is_relative()) p = base / p;
  return p.lexically_normal().string();
}

}  // namespace

void check_study_window(const StudyWindow& w, const std::string& file, const std::string& key) {
  if (!(w.range_lo_fraction >= 0.0 && w.range_lo_fraction < w.range_hi_fraction &&
        w.range_hi_fraction <= 1.0)) {
    throw InputError(file, key,
                     fmt::format("expected two fractions of the swath 0 <= lo < hi <= 1, got "
                                 "{:g}, {:g} (the middle third is 0.3333, 0.6667)",
                                 w.range_lo_fraction, w.range_hi_fraction));
  }
  if (!(w.incidence_bin_rad > 0.0 && w.incidence_bin_rad <= deg_to_rad(90.0))) {
    throw InputError(file, key,
                     fmt::format("expected an incidence bin width in (0, 90] deg, got {:g} deg",
                                 rad_to_deg(w.incidence_bin_rad)));
  }
}

StudyConfig read_study_config(const std::string& path) {
  const toml::table doc = parse_toml_file(path);
  ConfigTable top(doc, path, "");
  std::optional<ConfigTable> t = top.subtable("study");
  if (!t) throw InputError(path, "study", "missing [study] table (docs/study.md)");
  top.finish();
  const std::filesystem::path base = std::filesystem::path(path).parent_path();
  StudyConfig c;
  c.file = path;
  c.name = t->get_string_or("name", "");
  (void)t->get_string_opt("description");
  c.scene = path_key(*t, "scene", base);
  c.radar = path_key(*t, "radar", base);
  c.backscatter = path_key(*t, "backscatter", base);
  c.bands = t->get_string_opt("bands");
  if (t->has("seed")) {
    const std::int64_t seed = t->get_int("seed");
    if (seed < 0) t->fail("seed", "expected a non-negative integer");
    c.seed = static_cast<std::uint64_t>(seed);
  }
  StudyWindow w;
  if (t->has("range_fraction")) {
    const std::vector<double> f = t->get_double_array("range_fraction");
    if (f.size() != 2) t->fail("range_fraction", "expected [lo, hi], e.g. [0.3333, 0.6667]");
    w.range_lo_fraction = f[0];
    w.range_hi_fraction = f[1];
    check_study_window(w, path, t->key_path("range_fraction"));
    c.range_lo_fraction = f[0];
    c.range_hi_fraction = f[1];
  }
  if (t->has("incidence_bin")) {
    w.incidence_bin_rad = t->get_quantity("incidence_bin", Quantity::angle);
    check_study_window(w, path, t->key_path("incidence_bin"));
    c.incidence_bin_rad = w.incidence_bin_rad;
  }
  t->finish();
  return c;
}

}  // namespace ris
