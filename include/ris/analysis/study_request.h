// One `ris study` run as a user asks for it, from the command line
// (apps/ris/cmd_study.cpp) or from Python (ris.study): the inputs given, the
// study file's where one is not given, else the defaults; checked before
// anything is simulated, then run. Both callers go through here, so the same
// inputs give the same products, byte for byte.
//
// Example:
//   ris::StudyRequest q;
//   q.study_file = "data/studies/seed-fig7.toml";
//   q.bands = "8.6 GHz:HH, 8.6 GHz:VV";        // wins over the file's
//   const ris::ResolvedStudy s = ris::resolve_study(q);
//   const ris::StudyResult r = ris::run_resolved_study(s);
//   ris::write_study_products("study", r, s.info, s.style);
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ris/analysis/study.h"
#include "ris/analysis/study_config.h"
#include "ris/image/contact_sheet.h"

namespace ris {

struct StudyRequest {
  std::string study_file;  // a study file (docs/study.md), or ""
  // Unset: the study file's, else the default (the standard scene, the
  // figure-7 radar data/radars/seed-fig7.toml, the standard library, the
  // default bands, seed 1).
  std::optional<std::string> scene, radar, backscatter, bands;
  std::optional<std::uint64_t> seed;
  std::optional<double> range_lo_fraction, range_hi_fraction;  // both or neither
  std::optional<std::string> incidence_bin;                    // an angle with its unit
  bool null_check = true;
  int panel_px = 360;  // the contact sheet's panels, longer side
  int threads = 0;     // 0: all cores
  // Errors name the command line's options ("--panel-size") or, false,
  // Python's arguments ("panel_size").
  bool command_line_keys = true;
  std::function<void(std::string_view, double)> progress;
};

struct ResolvedStudy {
  StudyConfig config;  // the study file's (empty without one)
  StudyRunInfo info;   // the scene, radar and backscatter paths and the seed
  std::vector<StudyBand> bands;
  StudyOptions options;
  ContactSheetStyle style;
  int threads = 0;
};

// The option or argument `snake_name` ("panel_size") as the request's
// caller spells it: "--panel-size" or "panel_size".
std::string study_key(const StudyRequest& request, std::string_view snake_name);

// The inputs merged and checked (threads, panel size, bands, window): an
// InputError naming the option or argument, before any file but the study
// file is read.
ResolvedStudy resolve_study(const StudyRequest& request);

// Loads the radar, scene and backscatter and runs the study (run_study).
StudyResult run_resolved_study(const ResolvedStudy& study);

}  // namespace ris
