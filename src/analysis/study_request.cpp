// resolve_study and run_resolved_study (ris/analysis/study_request.h): what
// `ris study` and ris.study do with their inputs, in one place.
#include "ris/analysis/study_request.h"

#include <fmt/format.h>
#include <omp.h>

#include <filesystem>
#include <memory>
#include <stdexcept>

#include "ris/backscatter/library.h"
#include "ris/scene/scene_builder.h"
#include "ris/scene/scene_io.h"
#include "ris/sensor/one_channel_radar.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"

namespace ris {

namespace {

std::string data_file(const std::string& relative) {
  return (data_dir() / relative).string();
}

// The window: the study file's, with what the request gives winning.
StudyWindow study_window(const StudyRequest& q, const StudyConfig& c) {
  StudyWindow w;
  if (c.range_lo_fraction) w.range_lo_fraction = *c.range_lo_fraction;
  if (c.range_hi_fraction) w.range_hi_fraction = *c.range_hi_fraction;
  if (c.incidence_bin_rad) w.incidence_bin_rad = *c.incidence_bin_rad;
  if (q.range_lo_fraction || q.range_hi_fraction) {
    const std::string key = study_key(q, "range_fraction");
    if (!q.range_lo_fraction || !q.range_hi_fraction) {
      throw InputError("", key, "expected both fractions LO,HI (e.g. 0.3333,0.6667)");
    }
    w.range_lo_fraction = *q.range_lo_fraction;
    w.range_hi_fraction = *q.range_hi_fraction;
    check_study_window(w, "", key);
  }
  if (q.incidence_bin) {
    const std::string key = study_key(q, "incidence_bin");
    try {
      w.incidence_bin_rad = parse_quantity(*q.incidence_bin, Quantity::angle);
    } catch (const std::invalid_argument& e) {
      throw InputError("", key, e.what());
    }
    check_study_window(w, "", key);
  }
  return w;
}

Scene load_study_scene(const std::string& path) {
  if (std::filesystem::path(path).extension() == ".toml") {
    return build_scene(read_scene_description(path));
  }
  return read_scene(path);
}

}  // namespace

std::string study_key(const StudyRequest& request, std::string_view snake_name) {
  std::string key(snake_name);
  if (!request.command_line_keys) return key;
  for (char& c : key)
    if (c == '_') c = '-';
  return "--" + key;
}

ResolvedStudy resolve_study(const StudyRequest& q) {
  ResolvedStudy s;
  if (!q.study_file.empty()) s.config = read_study_config(q.study_file);
  const StudyConfig& c = s.config;
  // Given wins over the file, the file over the default.
  s.info.scene_path = q.scene   ? *q.scene
                      : c.scene ? *c.scene
                                : data_file("scenes/ku-geometric.toml");
  s.info.radar_path = q.radar ? *q.radar : c.radar ? *c.radar : data_file("radars/seed-fig7.toml");
  const std::string backscatter = q.backscatter ? *q.backscatter : c.backscatter.value_or("");
  s.info.backscatter_path = backscatter.empty() ? default_sigma0_library_path() : backscatter;
  s.info.seed = q.seed ? *q.seed : c.seed.value_or(1);

  s.threads = q.threads;
  checked_thread_count(q.threads, study_key(q, "threads"));  // the cap (resource_guard.h)
  if (q.panel_px < 16) {
    throw InputError("", study_key(q, "panel_size"),
                     fmt::format("expected 16 or more, got {}", q.panel_px));
  }
  s.style.max_panel_px = q.panel_px;
  // Bands first: a bad list fails before any expensive work.
  const std::string bands_key = study_key(q, "bands");
  s.bands = parse_study_bands(q.bands ? *q.bands : c.bands.value_or(default_study_bands_text()),
                              bands_key);
  s.options.bands_key = bands_key;
  s.options.window = study_window(q, c);
  s.options.null_check = q.null_check;
  s.options.seed = s.info.seed;
  s.options.scene_path = s.info.scene_path;
  s.options.progress = q.progress;
  return s;
}

StudyResult run_resolved_study(const ResolvedStudy& s) {
  if (s.threads > 0) omp_set_num_threads(s.threads);
  const RadarParams radar = load_one_channel_radar(s.info.radar_path, "ris study");
  const Scene scene = load_study_scene(s.info.scene_path);
  const std::unique_ptr<Sigma0Source> sigma0 = load_sigma0_source(s.info.backscatter_path);
  return run_study(scene, radar, *sigma0, s.info.backscatter_path, s.bands, s.options);
}

}  // namespace ris
