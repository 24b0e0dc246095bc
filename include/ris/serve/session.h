// The state `ris serve` keeps between requests: the scene (and, for a scene
// description, its editable TOML), the radar description, the backscatter
// source, the fading seed and the last run. One state is shared by every
// client (docs/serve.md): a mutex serialises runs, edits and the reads of the
// run's images, so concurrent clients never see a half-made run; health
// checks do not take it.
//
// Every request body is a JSON object whose keys are checked like a file's
// (ris/serve/json_toml.h): an unknown key or a bad value throws InputError
// with the message the command line would print. No path from a client is
// opened: radars and backscatter libraries are chosen by name from the ones
// found at start-up, files are saved under the output folder by a plain name.
//
// Example:
//   ris::ServeInputs in;  in.scene_path = "scene.toml";  in.radar_path = "radar.toml";
//   ris::Session session(in);
//   ris::SimulateOutcome out = session.simulate(R"({"seed": 7})");
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <toml++/toml.h>
#include <nlohmann/json.hpp>

#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/cultural_object.h"
#include "ris/scene/scene.h"
#include "ris/serve/product_folders.h"
#include "ris/serve/run_history.h"
#include "ris/sim/run.h"

namespace ris {

struct ServeInputs {
  std::string scene_path;        // .toml (editable) or a raster
  std::string radar_path;        // radar description (TOML)
  std::string backscatter_path;  // empty: the standard library
  // Saved scenes and radars and written products go here (created when
  // first needed); nothing else is written.
  std::filesystem::path out_dir = "ris-serve-out";
  // The shipped data: its radars/ and backscatter/ files are offered by name.
  std::filesystem::path data_dir;
  std::uint64_t seed = 1;
  // The products folders kept under out_dir (the oldest removed beyond).
  ProductFolderCap products;
  // Uploaded files go into a private folder made here (mode 0700, a fresh
  // name) and removed with the session; empty: the system's temporary folder.
  std::filesystem::path work_parent;
};

struct SimulateOutcome {
  bool superseded = false;  // a newer request came first: nothing was run
  nlohmann::json run;       // the run's summary (run_summary)
};

class Session {
 public:
  // Loads the inputs and runs once; InputError for bad input.
  explicit Session(ServeInputs inputs);
  // Removes the working folder and every upload in it.
  ~Session();
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  nlohmann::json state() const;

  // POST /api/simulate. Body keys: seed, depression, swath, radar (radar-file keys
  // overriding the current description), radar_preset, backscatter (names
  // from state()), allow_extrapolation (every model of the library used
  // outside its validity, with a warning: the switch its refusal names). A film-only change
  // re-renders from the kept mean power. When a newer simulate call arrives while this one waits
  // for the lock, this one is dropped (latest request wins).
  SimulateOutcome simulate(const std::string& body);

  // Scene editing (scene descriptions only): each re-simulates, and an edit
  // that does not parse or build leaves the scene as it was.
  nlohmann::json add_object(const std::string& body);
  nlohmann::json update_object(std::size_t index, const std::string& body);
  nlohmann::json delete_object(std::size_t index);
  // Raster scenes (imported DEMs): paints categories with a brush or a
  // polygon (ris/serve/category_paint.h) and re-simulates.
  nlohmann::json paint(const std::string& body);
  // Undoes the last edit or paint stroke.
  nlohmann::json undo();

  // POST /api/upload: a file's bytes, written into the session's working
  // folder under a plain name (folder and odd characters refused), opened
  // through the checks the command line applies (regular file, VRT sources
  // and side files beside it, grid size against memory) and made the scene.
  // kind: "dem" (imported as `ris scene import` does: every cell the default
  // category, its library), "landcover" (a categorical raster mapped through
  // `mapping`, a file name from the data folder's landcover/, onto the
  // current raster scene) or "scene" (a description .toml or a ris scene
  // raster). The scene's library is used, as `ris simulate` uses it.
  // Returns as an edit does, plus {"uploaded": name}.
  nlohmann::json upload(const std::string& kind, const std::string& name,
                        const std::string& mapping, const std::string& bytes);

  // Writes the scene or radar description as <out_dir>/<name>.toml (a
  // raster scene, painted or not, as <name>.tif, a ris scene GeoTIFF); body
  // {"name": "..."} (letters, digits, '-', '_', at most 64). Returns
  // {"file": "<name>.toml"}: answers name files relative to out_dir, never by
  // the server's absolute paths (state() likewise names files only).
  nlohmann::json save_scene(const std::string& body);
  nlohmann::json save_radar(const std::string& body);
  std::string scene_toml() const;
  std::string radar_toml() const;

  // Writes the run's products (as `ris simulate` does) into a new folder
  // under out_dir, products-run<N> (one an earlier server left under that
  // name is replaced), then prunes the oldest folders beyond
  // inputs.products; returns {"folder": "products-run<N>", "files": [...]},
  // each file then served by product_file.
  nlohmann::json write_products();
  std::optional<std::filesystem::path> product_file(const std::string& name) const;
  // All of them as one zip archive (InputError before write_products).
  std::vector<std::uint8_t> products_zip() const;

  // Views of the current run (ris/serve/run_views.h, pixel_inspector.h).
  std::vector<std::uint8_t> image_png(const std::string& view) const;
  std::vector<std::uint8_t> overlay_png(const std::string& view, const std::string& masks) const;
  std::string shadow_map() const;
  nlohmann::json histogram() const;
  nlohmann::json sigma0_chart() const;
  nlohmann::json inspect(const std::string& view, int x, int y) const;
  // The scene's optical or thermal view (ris/serve/sensor_view.h), kept for
  // the last (kind, minute, scene version) asked.
  std::vector<std::uint8_t> sensor_png(const std::string& kind,
                                       std::optional<int> minute_of_day) const;

  // Comparing runs (ris/serve/run_history.h, run_compare.h; docs/serve.md,
  // "Comparing two runs"). The last SLAR and SAR runs are kept (their slant
  // images); runs() lists them against the current run. A kept run's slant
  // greytones as PNG, and its slant pixel (x bin, y line) as the inspector
  // reads it (the current run's id: inspect("slant", x, y)).
  // The linked zoom's region (ris/serve/view_link.h).
  nlohmann::json link(const std::string& from, double x0, double y0, double x1, double y1) const;
  nlohmann::json runs() const;
  std::vector<std::uint8_t> kept_slant_png(std::uint64_t id) const;
  nlohmann::json inspect_kept(std::uint64_t id, int x, int y) const;
  // The current run against kept run `earlier` (InputError when it is not
  // kept or not on the same grid): {"current", "earlier", "quantity",
  // "range_db", "key", "images"}; range_db 0 is the view's default. The
  // difference view as PNG, and one pixel's difference (its "difference_db"
  // and both runs' powers).
  nlohmann::json compare(std::uint64_t earlier, const std::string& quantity, double range_db) const;
  std::vector<std::uint8_t> difference_png(std::uint64_t earlier, const std::string& quantity,
                                           double range_db) const;
  nlohmann::json compare_pixel(std::uint64_t earlier, const std::string& quantity, int x,
                               int y) const;

 private:
  struct SceneState {
    std::uint64_t version = 0;  // new for every edit: the scene picture's cache key
    std::string path;
    bool editable = false;
    toml::table doc;  // editable scenes: the description
    std::shared_ptr<const Scene> scene;
    // A description's buildings and reflectors, traced by every run.
    std::vector<CulturalObject> objects;
    // The backscatter library it was run with (an undo past an upload
    // returns to the library of the scene before).
    std::string library;
  };
  SceneState scene_from_doc(toml::table doc, const std::string& path);
  // A scene file (description or raster) as the command line loads it.
  SceneState scene_from_file(const std::string& path);
  // Makes `path` the current backscatter library (offered by its file name).
  void use_library(const std::string& path);
  std::filesystem::path store_upload(const std::string& name, const std::string& bytes,
                                     const std::vector<std::string>& extensions);
  SceneState landcover_scene(const std::filesystem::path& raster, const std::string& mapping);
  RunResult run(const SceneState& scene, const RadarParams& radar, const std::string& radar_path,
                const std::shared_ptr<const Sigma0Source>& sigma0,
                const std::string& backscatter_path, std::uint64_t seed) const;
  nlohmann::json run_summary() const;
  // The current run (kept) and `earlier` on its grid, under mutex_.
  std::pair<const KeptRun*, const KeptRun*> compared(std::uint64_t earlier) const;
  // Runs an edited scene and makes it current (the old one pushed on the
  // undo stack when push_undo).
  nlohmann::json apply_scene(SceneState next, bool push_undo);
  nlohmann::json apply_scene_doc(toml::table doc) {
    return apply_scene(scene_from_doc(std::move(doc), scene_.path), true);
  }
  std::filesystem::path save_path(const std::string& body, const std::string& what,
                                  const std::string& extension) const;
  const toml::array& objects() const;

  ServeInputs inputs_;
  std::map<std::string, std::string> radar_presets_;       // name -> path
  std::map<std::string, std::string> backscatter_files_;   // name -> path
  std::map<std::string, std::string> landcover_mappings_;  // name -> path
  std::filesystem::path work_dir_;                         // uploads (removed at the end)
  std::atomic<std::uint64_t> latest_request_{0};
  mutable std::mutex mutex_;
  // Under mutex_:
  SceneState scene_;
  std::vector<SceneState> undo_;  // scenes are immutable: states share them
  toml::table radar_doc_;
  std::string radar_path_;  // where radar_doc_ came from (named in messages)
  RadarParams radar_;
  std::string backscatter_name_;
  std::shared_ptr<const Sigma0Source> sigma0_;
  bool allow_extrapolation_ = false;  // every model of the library (simulate key)
  std::uint64_t uploads_ = 0;
  std::uint64_t seed_ = 1;
  RunResult result_;
  std::uint64_t run_id_ = 0;
  RunHistory history_;  // the last runs' slant images, for comparing
  bool last_film_only_ = false;
  double last_seconds_ = 0.0;  // the last run or re-render, request parsing included
  std::vector<std::string> warnings_;
  std::map<std::string, std::filesystem::path> products_;
  std::vector<std::filesystem::path> written_product_dirs_;  // by this session
  std::uint64_t scene_versions_ = 0;
  // The scene picture of scene_.version (it changes only with an edit; the
  // page shows it beside every run).
  mutable std::uint64_t scene_png_version_ = 0;
  mutable std::vector<std::uint8_t> scene_png_;
  mutable std::string sensor_png_key_;
  mutable std::vector<std::uint8_t> sensor_png_;
};

}  // namespace ris
