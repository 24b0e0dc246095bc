#include "ris/serve/session.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <regex>
#include <sstream>

#include <stdlib.h>

#include "ris/backscatter/library.h"
#include "ris/io/atomic_file.h"
#include "ris/io/config_table.h"
#include "ris/io/raster_io.h"
#include "ris/io/zip_archive.h"
#include "ris/scene/scene_builder.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/radar_json.h"
#include "ris/serve/category_paint.h"
#include "ris/serve/client_paths.h"
#include "ris/serve/json_toml.h"
#include "ris/serve/pixel_inspector.h"
#include "ris/serve/radar_overrides.h"
#include "ris/serve/run_compare.h"
#include "ris/serve/run_views.h"
#include "ris/serve/sensor_view.h"
#include "ris/serve/view_link.h"
#include "ris/sim/run.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"

namespace ris {
namespace {

constexpr const char* kBody = "request body";
constexpr std::size_t kMaxUndo = 100;

// Every regular file in `folder` with one of the extensions, by file name.
std::map<std::string, std::string> files_by_name(const std::filesystem::path& folder,
                                                 std::initializer_list<const char*> extensions) {
  std::map<std::string, std::string> out;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(folder, ec)) {
    if (!e.is_regular_file()) continue;
    for (const char* ext : extensions) {
      if (e.path().extension() == ext) out[e.path().filename().string()] = e.path().string();
    }
  }
  return out;
}

// The file's name without its folders (what answers tell a client).
std::string file_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

std::string toml_text(const toml::table& doc) {
  std::ostringstream s;
  s << doc << '\n';
  return s.str();
}

}  // namespace

Session::SceneState Session::scene_from_doc(toml::table doc, const std::string& path) {
  SceneState s;
  s.version = ++scene_versions_;
  s.path = path;
  s.editable = true;
  const SceneDescription d = parse_scene_description(doc, s.path);
  s.scene = std::make_shared<const Scene>(build_scene(d));
  s.objects = cultural_objects(d);
  s.doc = std::move(doc);
  return s;
}

namespace {

// A folder of the session's own under `parent` (mode 0700, a name no
// other process chose): mkdtemp.
std::filesystem::path make_private_folder(const std::filesystem::path& parent) {
  const std::filesystem::path base =
      parent.empty() ? std::filesystem::temp_directory_path() : parent;
  std::string name = (base / "ris-serve-XXXXXX").string();
  if (mkdtemp(name.data()) == nullptr) {
    throw InputError(base.string(), "", "cannot make the server's working folder for uploads");
  }
  return name;
}

}  // namespace

Session::SceneState Session::scene_from_file(const std::string& path) {
  if (is_scene_description(path)) return scene_from_doc(parse_toml_file(path), path);
  SceneState s;
  s.version = ++scene_versions_;
  s.path = path;
  s.scene = std::make_shared<const Scene>(load_scene_source(path).scene);
  return s;
}

void Session::use_library(const std::string& path) {
  std::shared_ptr<const Sigma0Source> source = load_sigma0_source(path, allow_extrapolation_);
  backscatter_name_ = std::filesystem::path(path).filename().string();
  backscatter_files_[backscatter_name_] = path;
  sigma0_ = std::move(source);
}

Session::Session(ServeInputs inputs) : inputs_(std::move(inputs)) {
  radar_presets_ = files_by_name(inputs_.data_dir / "radars", {".toml"});
  backscatter_files_ = files_by_name(inputs_.data_dir / "backscatter", {".toml", ".csv"});
  landcover_mappings_ = files_by_name(inputs_.data_dir / "landcover", {".toml"});
  // The command line's own files are offered too, under their file names.
  const std::string own_radar = std::filesystem::path(inputs_.radar_path).filename().string();
  radar_presets_[own_radar] = inputs_.radar_path;
  scene_ = scene_from_file(inputs_.scene_path);
  // --backscatter, else the library the scene names, as `ris simulate`.
  use_library(backscatter_library_for(inputs_.backscatter_path, inputs_.scene_path));
  scene_.library = backscatter_name_;
  radar_path_ = inputs_.radar_path;
  radar_doc_ = parse_toml_file(radar_path_);
  radar_ = radar_from_toml(radar_doc_, radar_path_);
  seed_ = inputs_.seed;
  result_ =
      run(scene_, radar_, radar_path_, sigma0_, backscatter_files_.at(backscatter_name_), seed_);
  last_seconds_ = result_.seconds;
  run_id_ = 1;
  history_.keep(run_id_, result_);
  work_dir_ = make_private_folder(inputs_.work_parent);
}

Session::~Session() {
  std::error_code ec;
  if (!work_dir_.empty()) std::filesystem::remove_all(work_dir_, ec);
}

RunResult Session::run(const SceneState& scene, const RadarParams& radar,
                       const std::string& radar_path,
                       const std::shared_ptr<const Sigma0Source>& sigma0,
                       const std::string& backscatter_path, std::uint64_t seed) const {
  if (radar.channels.size() > 1) {  // the page shows one image, its views one channel's
    throw InputError(radar_path, "channel",
                     fmt::format("{} channels: the server shows one channel; list one "
                                 "[[channel]] (ris simulate writes every channel's products)",
                                 radar.channels.size()));
  }
  RunRequest r;
  r.scene_path = scene.path;
  r.scene = scene.scene;
  r.objects = scene.objects;
  r.radar_path = radar_path;
  r.radar = radar;
  r.backscatter_path = backscatter_path;
  r.sigma0 = sigma0;
  r.seed = seed;
  r.quiet = true;
  RunCallbacks callbacks;
  callbacks.warning = [](const std::string& w) { spdlog::warn("{}", w); };
  return run_simulation(r, callbacks);
}

nlohmann::json Session::run_summary() const {
  const RunResult& r = result_;
  nlohmann::json j = {{"id", run_id_},
                      {"kind", run_kind_name(r)},
                      {"seed", r.info.seed},
                      {"film_only", last_film_only_},
                      {"seconds", last_seconds_}};
  std::vector<std::string> views = {"slant", "ground", "scene"};
  // The mode's own report (ris/sim/run.h), and its warnings.
  const RunSummary summary = ris::run_summary(r);
  nlohmann::json report = run_summary_json(summary);
  strip_directories_in(report);  // file names only, never the server's folders
  j["summary"] = std::move(report);
  if (r.in_memory()) j["warnings"] = summary.warnings;
  if (const SlarRun* slar = slar_image_run(r)) {  // the page's figures of the image
    const SlarGeometry& g = slar->sim.geometry;
    const double samples = double(g.lines) * double(g.samples);
    j["lines"] = slar->sim.image.lines;
    j["bins"] = slar->sim.image.bins;
    j["near_range_m"] = slar->sim.image.range.near_m;
    j["range_bin_m"] = slar->sim.image.range.bin_m;
    j["shadow_percent"] = 100.0 * double(g.shadow_samples) / samples;
    j["layover_percent"] = 100.0 * double(g.layover_samples) / samples;
    j["back_facing_percent"] = 100.0 * double(g.back_facing_samples) / samples;
    views.push_back("geocoded");
  }
  nlohmann::json images = nlohmann::json::object();
  for (const std::string& v : views) {
    images[v] = v == "scene" ? fmt::format("/api/image/scene.png?scene={}", scene_.version)
                             : fmt::format("/api/image/{}.png?run={}", v, run_id_);
  }
  j["images"] = images;
  j["map"] = map_furniture(r, *sigma0_);
  return j;
}

nlohmann::json Session::state() const {
  std::lock_guard lock(mutex_);
  nlohmann::json presets = nlohmann::json::array();
  for (const auto& [name, path] : radar_presets_) presets.push_back(name);
  nlohmann::json libraries = nlohmann::json::array();
  for (const auto& [name, path] : backscatter_files_) libraries.push_back(name);
  nlohmann::json mappings = nlohmann::json::array();
  for (const auto& [name, path] : landcover_mappings_) mappings.push_back(name);
  const Scene& s = *scene_.scene;
  nlohmann::json scene = {{"file", file_name(scene_.path)},
                          {"editable", scene_.editable},
                          {"rows", s.rows},
                          {"cols", s.cols},
                          {"cell_m", s.dx_m},
                          {"undo_depth", undo_.size()}};
  if (scene_.editable) scene["description"] = toml_to_json(scene_.doc);
  // The library's categories, for painting.
  nlohmann::json categories = nlohmann::json::array();
  for (const std::uint16_t c : sigma0_->category_ids()) {
    categories.push_back({{"id", c}, {"name", sigma0_->category_name(c)}});
  }
  nlohmann::json radar = {{"file", file_name(radar_path_)},
                          {"description", toml_to_json(radar_doc_)},
                          {"params", radar_to_json(radar_)}};
  // Names, never the server's folders (the parsed radar keeps its source
  // path; a description may name a file).
  strip_directories_in(scene);
  strip_directories_in(radar);
  return {{"scene", scene},
          {"radar", radar},
          {"radar_presets", presets},
          {"backscatter", backscatter_name_},
          {"allow_extrapolation", allow_extrapolation_},
          {"categories", categories},
          {"landcover_mappings", mappings},
          {"backscatter_libraries", libraries},
          {"seed", seed_},
          {"run", run_summary()}};
}

SimulateOutcome Session::simulate(const std::string& body) {
  const auto t0 = std::chrono::steady_clock::now();
  const std::uint64_t ticket = ++latest_request_;
  // Parse before waiting: a bad body is refused at once.
  const toml::table request = json_body_to_toml(body, kBody);
  std::lock_guard lock(mutex_);
  SimulateOutcome out;
  if (ticket != latest_request_.load()) {
    out.superseded = true;
    return out;
  }
  ConfigTable t(request, kBody, "");
  const std::int64_t seed = t.get_int_or("seed", static_cast<std::int64_t>(seed_));
  if (seed < 0) t.fail("seed", "expected a seed >= 0");
  // The radar: a preset replaces the description, then overrides, then the
  // depression angle (which needs the altitude as overridden).
  // Messages name the file the description came from, as the CLI's would.
  toml::table doc = radar_doc_;
  std::string radar_path = radar_path_;
  if (auto preset = t.get_string_opt("radar_preset")) {
    const auto it = radar_presets_.find(*preset);
    if (it == radar_presets_.end()) t.fail("radar_preset", "unknown radar \"" + *preset + "\"");
    radar_path = it->second;
    doc = parse_toml_file(radar_path);
  }
  if (const toml::node* overrides = t.raw("radar")) {
    if (!overrides->is_table()) t.fail("radar", "expected an object of radar-file keys");
    merge_toml(doc, *overrides->as_table());
  }
  RadarParams radar = radar_from_toml(doc, radar_path);
  if (auto depression = t.get_quantity_opt("depression", Quantity::angle)) {
    set_near_range_depression(doc, radar, *depression);
    radar = radar_from_toml(doc, radar_path);
  }
  if (auto swath = t.get_quantity_opt("swath", Quantity::length)) {
    set_slant_swath(doc, radar, *swath);
    radar = radar_from_toml(doc, radar_path);
  }
  std::string bs_name = backscatter_name_;
  if (auto name = t.get_string_opt("backscatter")) {
    if (backscatter_files_.count(*name) == 0) {
      t.fail("backscatter", "unknown backscatter library \"" + *name + "\"");
    }
    bs_name = *name;
  }
  const bool allow = t.get_bool_or("allow_extrapolation", allow_extrapolation_);
  t.finish();
  const bool same_library = bs_name == backscatter_name_ && allow == allow_extrapolation_;
  const bool same_inputs = same_library && result_.in_memory();
  if (same_inputs && film_only_change(radar_doc_, doc, radar_, radar)) {
    // Film, fading law and switch: the image chain after the mean power.
    SlarRun* slar = slar_image_run(result_);
    for (RadarParams* used :
         {slar != nullptr ? &slar->sim.radar : &std::get<PpiRun>(result_.run).sim.radar,
          &result_.radar}) {
      used->switches.fading = radar.switches.fading;
      used->fading = radar.fading;
    }
    rerender(result_, static_cast<std::uint64_t>(seed), &radar.film);
    result_.radar.film = radar.film;
    last_film_only_ = true;
  } else {
    std::shared_ptr<const Sigma0Source> sigma0 = sigma0_;
    if (!same_library) sigma0 = load_sigma0_source(backscatter_files_.at(bs_name), allow);
    result_ = run(scene_, radar, radar_path, sigma0, backscatter_files_.at(bs_name),
                  static_cast<std::uint64_t>(seed));
    sigma0_ = sigma0;
    backscatter_name_ = bs_name;
    scene_.library = bs_name;
    allow_extrapolation_ = allow;
    last_film_only_ = false;
  }
  radar_doc_ = std::move(doc);
  radar_path_ = radar_path;
  radar_ = radar;
  seed_ = static_cast<std::uint64_t>(seed);
  ++run_id_;
  history_.keep(run_id_, result_);
  last_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.run = run_summary();
  return out;
}

const toml::array& Session::objects() const {
  static const toml::array empty;
  const toml::array* a = scene_.doc["object"].as_array();
  return a != nullptr ? *a : empty;
}

nlohmann::json Session::apply_scene(SceneState next, bool push_undo) {
  result_ =
      run(next, radar_, radar_path_, sigma0_, backscatter_files_.at(backscatter_name_), seed_);
  if (push_undo) {
    undo_.push_back(std::move(scene_));
    if (undo_.size() > kMaxUndo) undo_.erase(undo_.begin());
  }
  scene_ = std::move(next);
  scene_.library = backscatter_name_;
  last_film_only_ = false;
  last_seconds_ = result_.seconds;
  ++run_id_;
  history_.keep(run_id_, result_);
  nlohmann::json j = {{"run", run_summary()}, {"undo_depth", undo_.size()}};
  if (scene_.editable) {
    j["objects"] = toml_to_json(scene_.doc).value("object", nlohmann::json::array());
  }
  return j;
}

namespace {

void require_editable(bool editable, const std::string& path) {
  if (!editable) {
    throw InputError(path, "", "only a scene description (.toml) can be edited");
  }
}

void check_index(std::size_t index, std::size_t count, const std::string& path) {
  if (index >= count) {
    throw InputError(path, fmt::format("object[{}]", index),
                     fmt::format("no such object (the scene has {})", count));
  }
}

}  // namespace

nlohmann::json Session::add_object(const std::string& body) {
  const toml::table object = json_body_to_toml(body, kBody);
  std::lock_guard lock(mutex_);
  require_editable(scene_.editable, scene_.path);
  toml::table doc = scene_.doc;
  if (!doc.contains("object")) doc.insert("object", toml::array{});
  toml::array* list = doc["object"].as_array();
  if (list == nullptr) throw InputError(scene_.path, "object", "expected an array of tables");
  list->push_back(object);
  return apply_scene_doc(std::move(doc));
}

nlohmann::json Session::update_object(std::size_t index, const std::string& body) {
  const toml::table changes = json_body_to_toml(body, kBody);
  std::lock_guard lock(mutex_);
  require_editable(scene_.editable, scene_.path);
  check_index(index, objects().size(), scene_.path);
  toml::table doc = scene_.doc;
  toml::table* object = doc["object"][index].as_table();
  if (object == nullptr) throw InputError(scene_.path, "object", "expected an array of tables");
  merge_toml(*object, changes);
  return apply_scene_doc(std::move(doc));
}

nlohmann::json Session::delete_object(std::size_t index) {
  std::lock_guard lock(mutex_);
  require_editable(scene_.editable, scene_.path);
  check_index(index, objects().size(), scene_.path);
  toml::table doc = scene_.doc;
  toml::array* list = doc["object"].as_array();
  list->erase(list->begin() + static_cast<std::ptrdiff_t>(index));
  return apply_scene_doc(std::move(doc));
}

nlohmann::json Session::paint(const std::string& body) {
  const PaintStroke stroke = parse_paint_stroke(json_body_to_toml(body, kBody));
  std::lock_guard lock(mutex_);
  if (scene_.editable) {
    throw InputError(scene_.path, "",
                     "categories are painted on raster scenes (imported DEMs); a description's "
                     "categories are its objects' (add a patch object)");
  }
  SceneState next = scene_;
  auto painted = std::make_shared<Scene>(*scene_.scene);
  if (paint_categories(*painted, stroke) == 0) {
    throw InputError(kBody, "", "the stroke covers no cell with data");
  }
  next.scene = std::move(painted);
  next.version = ++scene_versions_;
  return apply_scene(std::move(next), true);
}

nlohmann::json Session::undo() {
  std::lock_guard lock(mutex_);
  if (undo_.empty()) throw InputError(scene_.path, "", "nothing to undo");
  const std::string old_library = backscatter_name_;
  const std::shared_ptr<const Sigma0Source> old_sigma0 = sigma0_;
  const auto library = backscatter_files_.find(undo_.back().library);
  if (library != backscatter_files_.end() && library->first != backscatter_name_) {
    use_library(library->second);
  }
  SceneState previous = std::move(undo_.back());
  undo_.pop_back();
  try {
    return apply_scene(previous, false);
  } catch (...) {
    undo_.push_back(std::move(previous));
    backscatter_name_ = old_library;
    sigma0_ = old_sigma0;
    throw;
  }
}

std::filesystem::path Session::save_path(const std::string& body, const std::string& what,
                                         const std::string& extension) const {
  const toml::table request = json_body_to_toml(body, kBody);
  ConfigTable t(request, kBody, "");
  const std::string name = t.get_string("name");
  t.finish();
  // A plain name only: no folder, no "..", nothing a shell or a file system
  // reads specially; the file always lands in out_dir.
  static const std::regex plain("[A-Za-z0-9][A-Za-z0-9_-]{0,63}");
  if (name.size() > 64 || !std::regex_match(name, plain)) {
    t.fail("name", "expected a plain " + what +
                       " name (letters, digits, '-' and '_', at most 64, no extension), got \"" +
                       name + "\"");
  }
  std::filesystem::create_directories(inputs_.out_dir);
  return inputs_.out_dir / (name + extension);
}

nlohmann::json Session::save_scene(const std::string& body) {
  std::lock_guard lock(mutex_);
  const std::filesystem::path path = save_path(body, "scene", scene_.editable ? ".toml" : ".tif");
  if (scene_.editable) {
    write_text_file_atomic(path, toml_text(scene_.doc));
  } else {
    write_scene_geotiff(*scene_.scene, path);
  }
  return {{"file", path.filename().string()}};
}

nlohmann::json Session::save_radar(const std::string& body) {
  const std::filesystem::path path = save_path(body, "radar", ".toml");
  std::lock_guard lock(mutex_);
  write_text_file_atomic(path, toml_text(radar_doc_));
  return {{"file", path.filename().string()}};
}

std::string Session::scene_toml() const {
  std::lock_guard lock(mutex_);
  require_editable(scene_.editable, scene_.path);
  return toml_text(scene_.doc);
}

std::string Session::radar_toml() const {
  std::lock_guard lock(mutex_);
  return toml_text(radar_doc_);
}

nlohmann::json Session::write_products() {
  std::lock_guard lock(mutex_);
  std::filesystem::create_directories(inputs_.out_dir);
  const std::filesystem::path dir = inputs_.out_dir / fmt::format("products-run{}", run_id_);
  const bool mine = std::find(written_product_dirs_.begin(), written_product_dirs_.end(), dir) !=
                    written_product_dirs_.end();
  if (!mine || !path_exists(dir)) {
    // Run ids restart with every server: a folder of this name from an
    // earlier one holds another run's products.
    std::filesystem::remove_all(dir);
    write_run_products(result_, dir);
    written_product_dirs_.push_back(dir);
  }
  for (const std::string& gone : prune_product_folders(inputs_.out_dir, dir, inputs_.products)) {
    spdlog::info("removed {} (over --max-product-runs {} or --max-product-mib {})", gone,
                 inputs_.products.max_folders, inputs_.products.max_bytes >> 20);
    std::erase(written_product_dirs_, inputs_.out_dir / gone);
  }
  products_.clear();
  nlohmann::json names = nlohmann::json::array();
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    if (!e.is_regular_file()) continue;
    products_[e.path().filename().string()] = e.path();
  }
  for (const auto& [name, path] : products_) names.push_back(name);
  return {{"folder", dir.filename().string()}, {"files", names}};
}

std::optional<std::filesystem::path> Session::product_file(const std::string& name) const {
  std::lock_guard lock(mutex_);
  const auto it = products_.find(name);
  if (it == products_.end()) return std::nullopt;
  return it->second;
}

std::vector<std::uint8_t> Session::products_zip() const {
  std::lock_guard lock(mutex_);
  if (products_.empty()) throw InputError("request", "", "no products yet: write them first");
  std::vector<std::filesystem::path> files;
  for (const auto& [name, path] : products_) files.push_back(path);
  return zip_files(files);
}

std::vector<std::uint8_t> Session::image_png(const std::string& view) const {
  std::lock_guard lock(mutex_);
  if (view != "scene") return view_png(result_, view);
  if (scene_png_.empty() || scene_png_version_ != scene_.version) {
    scene_png_ = view_png(result_, view);
    scene_png_version_ = scene_.version;
  }
  return scene_png_;
}

std::vector<std::uint8_t> Session::sensor_png(const std::string& kind,
                                              std::optional<int> minute_of_day) const {
  std::lock_guard lock(mutex_);
  const std::string key = fmt::format("{} {} {} {}", kind, minute_of_day.value_or(-1),
                                      scene_.version, backscatter_name_);
  if (key != sensor_png_key_) {
    sensor_png_ = sensor_view_png(*scene_.scene, backscatter_files_.at(backscatter_name_), kind,
                                  minute_of_day);
    sensor_png_key_ = key;
  }
  return sensor_png_;
}

std::vector<std::uint8_t> Session::overlay_png(const std::string& view,
                                               const std::string& masks) const {
  std::lock_guard lock(mutex_);
  return ris::overlay_png(result_, view, masks);
}

std::string Session::shadow_map() const {
  std::lock_guard lock(mutex_);
  return ris::shadow_map(result_);
}

nlohmann::json Session::histogram() const {
  std::lock_guard lock(mutex_);
  return greytone_histogram(result_);
}

nlohmann::json Session::sigma0_chart() const {
  std::lock_guard lock(mutex_);
  return sigma0_curves(result_, *sigma0_);
}

nlohmann::json Session::inspect(const std::string& view, int x, int y) const {
  std::lock_guard lock(mutex_);
  return inspect_pixel(result_, *sigma0_, view, x, y);
}

nlohmann::json Session::link(const std::string& from, double x0, double y0, double x1,
                             double y1) const {
  std::lock_guard lock(mutex_);
  return linked_region(result_, from, x0, y0, x1, y1);
}

nlohmann::json Session::runs() const {
  std::lock_guard lock(mutex_);
  return history_.list(run_id_);
}

std::vector<std::uint8_t> Session::kept_slant_png(std::uint64_t id) const {
  std::lock_guard lock(mutex_);
  const KeptRun& k = history_.get(id);
  return encode_png(k.grey.data(), k.grid.bins, k.grid.lines, 1);
}

nlohmann::json Session::inspect_kept(std::uint64_t id, int x, int y) const {
  std::lock_guard lock(mutex_);
  const KeptRun& k = history_.get(id);
  if (x < 0 || y < 0 || x >= k.grid.bins || y >= k.grid.lines) {
    throw InputError("request", "x, y",
                     fmt::format("pixel ({}, {}) is outside run {}'s slant view of {} x {} "
                                 "pixels",
                                 x, y, id, k.grid.bins, k.grid.lines));
  }
  const std::size_t i = static_cast<std::size_t>(y) * k.grid.bins + x;
  const auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; };
  const double mean = k.mean_power_w[i];
  return {{"view", "slant"},
          {"run", id},
          {"label", k.label},
          {"line", y},
          {"bin", x},
          {"mean_power_w", finite(mean)},
          {"mean_power_dbw", finite(mean > 0.0 ? 10.0 * std::log10(mean) : NAN)},
          {"speckled_power_w", finite(k.speckled_power_w[i])},
          {"greytone", k.grey[i]}};
}

std::pair<const KeptRun*, const KeptRun*> Session::compared(std::uint64_t earlier) const {
  const KeptRun* now = nullptr;
  try {
    now = &history_.get(run_id_);
  } catch (const InputError&) {
    throw InputError("request", "earlier",
                     "the current run has no slant image to compare (a PPI run): compare SLAR "
                     "or SAR runs");
  }
  const KeptRun& then = history_.get(earlier);
  check_same_grid(*now, then);
  return {now, &then};
}

nlohmann::json Session::compare(std::uint64_t earlier, const std::string& quantity,
                                double range_db) const {
  const CompareQuantity q = parse_compare_quantity(quantity);
  std::lock_guard lock(mutex_);
  const auto [now, then] = compared(earlier);
  const Difference d = difference_db(*now, *then, q);
  const double range = range_db > 0.0 ? range_db : default_range_db(d);
  const std::string name = compare_quantity_name(q);
  return {{"current", now->id},
          {"earlier", then->id},
          {"current_label", now->label},
          {"earlier_label", then->label},
          {"quantity", name},
          {"range_db", range},
          {"key", difference_key(range)},
          {"images",
           {{"current", fmt::format("/api/runs/{}/slant.png", now->id)},
            {"earlier", fmt::format("/api/runs/{}/slant.png", then->id)},
            {"difference",
             fmt::format("/api/compare/difference.png?earlier={}&quantity={}&range_db={}&run={}",
                         then->id, name, range, now->id)}}}};
}

std::vector<std::uint8_t> Session::difference_png(std::uint64_t earlier,
                                                  const std::string& quantity,
                                                  double range_db) const {
  const CompareQuantity q = parse_compare_quantity(quantity);
  std::lock_guard lock(mutex_);
  const auto [now, then] = compared(earlier);
  const Difference d = difference_db(*now, *then, q);
  return ris::difference_png(d, range_db > 0.0 ? range_db : default_range_db(d));
}

nlohmann::json Session::compare_pixel(std::uint64_t earlier, const std::string& quantity, int x,
                                      int y) const {
  const CompareQuantity q = parse_compare_quantity(quantity);
  std::lock_guard lock(mutex_);
  const auto [now, then] = compared(earlier);
  if (x < 0 || y < 0 || x >= now->grid.bins || y >= now->grid.lines) {
    throw InputError("request", "x, y",
                     fmt::format("pixel ({}, {}) is outside the slant view of {} x {} pixels", x, y,
                                 now->grid.bins, now->grid.lines));
  }
  const std::size_t i = static_cast<std::size_t>(y) * now->grid.bins + x;
  const auto& a = q == CompareQuantity::mean ? now->mean_power_w : now->speckled_power_w;
  const auto& b = q == CompareQuantity::mean ? then->mean_power_w : then->speckled_power_w;
  const double d = pixel_difference_db(a[i], b[i]);
  const auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nullptr; };
  return {{"current", now->id},
          {"earlier", then->id},
          {"quantity", compare_quantity_name(q)},
          {"line", y},
          {"bin", x},
          {"current_power_w", finite(a[i])},
          {"earlier_power_w", finite(b[i])},
          {"difference_db", finite(d)}};
}

}  // namespace ris
