#include "ris/backscatter/library.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <mutex>
#include <set>

#include "ris/backscatter/backscatter_model.h"
#include "ris/backscatter/sigma0_table.h"
#include "ris/io/config_table.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"

namespace ris {

namespace {

using Colour = std::array<std::uint8_t, 3>;

Colour parse_colour(const ConfigTable& t, const std::string& key, const std::string& text) {
  auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
  };
  bool ok = text.size() == 7 && text[0] == '#';
  Colour out{};
  for (size_t i = 0; ok && i < 3; ++i) {
    const int hi = hex(text[1 + 2 * i]);
    const int lo = hex(text[2 + 2 * i]);
    ok = hi >= 0 && lo >= 0;
    if (ok) out[i] = static_cast<std::uint8_t>(hi * 16 + lo);
  }
  if (!ok) t.fail(key, "expected a colour \"#rrggbb\", got \"" + text + "\"");
  return out;
}

// One override of a category's model for a frequency range and/or a set of
// polarisations.
struct BandEntry {
  double min_hz = 0.0;
  double max_hz = 1e300;
  std::vector<Polarisation> polarisations;  // empty: all
  std::unique_ptr<BackscatterModel> model;

  bool matches(const RadarBand& band) const {
    if (band.frequency_hz < min_hz || band.frequency_hz > max_hz) return false;
    if (polarisations.empty()) return true;
    return std::find(polarisations.begin(), polarisations.end(), band.polarisation) !=
           polarisations.end();
  }
};

struct Category {
  std::uint16_t id = 0;
  std::string name;
  Colour colour{};
  std::string key;  // "category[3]", for messages
  std::vector<BandEntry> bands;
  std::unique_ptr<BackscatterModel> model;  // default; may be null when bands cover all
};

class LibrarySource final : public Sigma0Source {
 public:
  LibrarySource(std::string path, std::string name, std::vector<Category> categories)
      : path_(std::move(path)), name_(std::move(name)), categories_(std::move(categories)) {
    for (size_t i = 0; i < categories_.size(); ++i) index_[categories_[i].id] = i;
  }

  bool has_category(std::uint16_t category) const override { return index_.count(category) != 0; }

  double sigma0(std::uint16_t category, double incidence_rad,
                const RadarBand& band) const override {
    const BackscatterModel& m = resolve(category, band);
    return m.sigma0(incidence_rad, band);
  }

  // The model resolved (and its band checked, under the mutex) once per
  // curve, not per angle.
  void sigma0_curve(std::uint16_t category, const double* incidence_rad, std::size_t n,
                    const RadarBand& band, double* out) const override {
    resolve(category, band).sigma0_curve(incidence_rad, n, band, out);
  }

  std::string category_name(std::uint16_t category) const override {
    auto it = index_.find(category);
    return it == index_.end() ? std::to_string(category) : categories_[it->second].name;
  }

  std::string description() const override { return fmt::format("library {} ({})", path_, name_); }

  std::vector<std::uint16_t> category_ids() const override {
    std::vector<std::uint16_t> ids;
    for (const auto& [id, i] : index_) ids.push_back(id);
    return ids;
  }

  std::optional<Colour> category_colour(std::uint16_t category) const override {
    auto it = index_.find(category);
    if (it == index_.end()) return std::nullopt;
    return categories_[it->second].colour;
  }

  std::string category_model(std::uint16_t category, const RadarBand& band) const override {
    return resolve(category, band).describe();
  }

 private:
  // The model for a category at a band (first matching band entry, else the
  // default), checked against the band once per (category, band).
  const BackscatterModel& resolve(std::uint16_t category, const RadarBand& band) const {
    auto it = index_.find(category);
    if (it == index_.end()) {
      throw InputError(path_, "", fmt::format("no category {} in the library", category));
    }
    const Category& c = categories_[it->second];
    const BackscatterModel* model = c.model.get();
    for (const BandEntry& b : c.bands) {
      if (b.matches(band)) {
        model = b.model.get();
        break;
      }
    }
    if (model == nullptr) {
      throw InputError(
          path_, c.key,
          fmt::format("category {} ({}) has no model for {:g} GHz {} (add a "
                      "default [{}.model] or a matching band entry)",
                      c.id, c.name, band.frequency_hz / 1e9, to_string(band.polarisation), c.key));
    }
    const auto key = std::make_tuple(category, band.frequency_hz, band.polarisation);
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (checked_.count(key) != 0) return *model;
    }
    model->check_band(band);  // throws InputError when outside validity
    std::lock_guard<std::mutex> lock(mutex_);
    checked_.insert(key);
    return *model;
  }

  std::string path_;
  std::string name_;
  std::vector<Category> categories_;
  std::map<std::uint16_t, size_t> index_;
  mutable std::mutex mutex_;
  mutable std::set<std::tuple<std::uint16_t, double, Polarisation>> checked_;
};

std::unique_ptr<Sigma0Source> load_library(const std::string& path,
                                           bool force_allow_extrapolation) {
  const toml::table doc = parse_toml_file(path);
  ConfigTable root(doc, path, "");
  std::string lib_name = std::filesystem::path(path).stem().string();
  bool allow_extrapolation = false;
  if (auto lib = root.subtable("library")) {
    lib_name = lib->get_string_or("name", lib_name);
    lib->get_string_or("description", "");
    lib->get_string_or("source", "");
    allow_extrapolation = lib->get_bool_or("allow_extrapolation", false);
    lib->finish();
  }
  auto tables = std::make_shared<std::map<std::string, std::shared_ptr<const Sigma0Table>>>();
  const std::string base_dir = std::filesystem::path(path).parent_path().string();
  std::vector<Category> categories;
  std::set<std::int64_t> seen;
  std::vector<ConfigTable> entries = root.table_array("category");
  if (entries.empty()) {
    throw InputError(path, "category", "the library defines no [[category]] entries");
  }
  for (size_t i = 0; i < entries.size(); ++i) {
    ConfigTable& t = entries[i];
    Category c;
    c.key = fmt::format("category[{}]", i);
    const std::int64_t id = t.get_int("id");
    if (id < 1 || id > 65534) t.fail("id", "expected a category id in 1..65534");
    if (!seen.insert(id).second) t.fail("id", fmt::format("category {} is defined twice", id));
    c.id = static_cast<std::uint16_t>(id);
    c.name = t.get_string("name");
    c.colour = parse_colour(t, "colour", t.get_string("colour"));
    t.get_string_or("source", "");  // a citation, kept in the file for readers
    ModelContext ctx;
    ctx.file = path;
    ctx.base_dir = base_dir;
    ctx.allow_extrapolation =
        t.get_bool_or("allow_extrapolation", allow_extrapolation) || force_allow_extrapolation;
    ctx.category_id = static_cast<int>(id);
    ctx.table_cache = tables;
    if (auto m = t.subtable("model")) c.model = make_backscatter_model(*m, ctx);
    std::vector<ConfigTable> bands = t.table_array("band");
    for (ConfigTable& b : bands) {
      BandEntry e;
      if (b.has("frequency")) {
        const std::vector<double> f = b.get_quantity_array("frequency", Quantity::frequency);
        if (f.size() != 2 || !(f[0] > 0.0) || !(f[1] >= f[0])) {
          b.fail("frequency",
                 "expected [low, high] with 0 < low <= high, e.g. [\"8 GHz\", \"9 GHz\"]");
        }
        e.min_hz = f[0] * (1.0 - 1e-9);
        e.max_hz = f[1] * (1.0 + 1e-9);
      }
      if (b.has("polarisation")) {
        const toml::node* n = b.raw("polarisation");
        const toml::array* arr = n->as_array();
        if (arr == nullptr) b.fail("polarisation", "expected an array such as [\"HH\", \"VV\"]");
        for (const toml::node& p : *arr) {
          const auto s = p.value<std::string>();
          if (!s) b.fail("polarisation", "expected an array of strings such as [\"HH\", \"VV\"]");
          try {
            e.polarisations.push_back(parse_polarisation(*s));
          } catch (const std::invalid_argument& err) {
            b.fail("polarisation", err.what());
          }
        }
      }
      std::optional<ConfigTable> m = b.subtable("model");
      if (!m) b.fail("model", "missing required table (the model for this band)");
      e.model = make_backscatter_model(*m, ctx);
      b.finish();
      c.bands.push_back(std::move(e));
    }
    if (!c.model && c.bands.empty()) {
      t.fail("model", "missing required table (the category's backscatter model)");
    }
    t.finish();
    categories.push_back(std::move(c));
  }
  root.finish();
  return std::make_unique<LibrarySource>(path, lib_name, std::move(categories));
}

}  // namespace

std::unique_ptr<Sigma0Source> load_sigma0_source(const std::string& path) {
  return load_sigma0_source(path, false);
}

std::unique_ptr<Sigma0Source> load_sigma0_source(const std::string& path,
                                                 bool force_allow_extrapolation) {
  const std::string ext = std::filesystem::path(path).extension().string();
  if (!path_exists(path)) {
    throw InputError(path, "", "backscatter file not found");
  }
  if (ext == ".csv") {
    return make_table_source(std::make_shared<const Sigma0Table>(Sigma0Table::load(path)));
  }
  if (ext == ".toml") return load_library(path, force_allow_extrapolation);
  throw InputError(
      path, "",
      "expected a category library (.toml) or a sigma0 table (.csv), got \"" + ext + "\"");
}

std::string default_sigma0_library_path() {
  return (data_dir() / "backscatter" / "ku-geometric.toml").string();
}

}  // namespace ris
