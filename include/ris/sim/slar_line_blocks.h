// The SLAR geometry, image-formation and scene-map stages fused per block of
// azimuth lines, for a track along a grid axis (direct sampling, one line per
// cell row or column): each line's geometry lives only in per-thread scratch
// (no ~31 bytes/sample geometry buffers for the whole scene, no separate
// slope raster), its elements go straight into the line's range profile
// (ris/image/slar_image.h SlarLineProfiles), and its cells' scene-grid mask
// and local incidence are written as the line is done.
//
// It does exactly what compute_slar_geometry + form_slar_image +
// scene_geometry_maps do, in the same arithmetic, so the products are the
// same bytes (tested against that stage path: slar_line_blocks_test.cpp,
// tests/slar_stage_reference.h); every simulate_slar run goes through it.
// A run that needs the per-sample geometry of the whole run (the coherent
// SAR, SlarOptions::keep_geometry, lines not one per cell row or column)
// keeps it through the engine's kept-geometry sink (SlarEngineKeep), and
// point targets are placed per line as each line is formed.
//
// A block only needs the scene cells of its lines plus one cell of halo (for
// the slope), given as a SceneWindow; this is what lets a scene larger than
// memory stream through in blocks (ris/sim/slar_stream.h).
//
// Example:
//   ris::SlarLineEngine engine(scene, layout, lut, imaging, radar_file);
//   ris::SlarLineProfiles prof;  prof.allocate(layout.lines, imaging.range.count);
//   ris::SceneGeometryMaps maps = ...;  // rows x cols
//   engine.run(0, layout.lines, ris::SceneWindow::whole(scene), prof, maps_window, counts);
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"
#include "ris/sim/point_target.h"
#include "ris/sim/slar_line_parts.h"

namespace ris {

namespace detail {
struct LineKeep;      // sim/engine/slar_line_stages.h: the kept-geometry sink and point targets
struct ExtraChannel;  // sim/engine/slar_line_engine.h: a channel beyond the first
}  // namespace detail

// Whether the fused path reproduces the reference stages for this layout:
// direct sampling with one line per row (track along y) or column.
bool fused_slar_applies(const Scene& scene, const SlarGeometry& layout);

// Whether form_slar_image_fused runs this layout: fused_slar_applies, or a
// heading off the grid axes (bilinear sampling; in memory only: it is not a
// SlarLineEngine, whose lines are cell rows or columns).
bool fused_slar_image_applies(const Scene& scene, const SlarGeometry& layout);

class SlarLineEngine {
 public:
  // scene: its grid (rows, cols, cell size, origin); its arrays are not read
  // (data comes in SceneWindows). layout: slar_geometry_layout(). Every
  // category a window holds must be in lut (checked by the caller).
  SlarLineEngine(const Scene& scene, const SlarGeometry& layout, const Sigma0Lut& lut,
                 const SlarImagingParams& params, const std::string& radar_file);

  // The scene rows x cols range a block of lines [line0, line1) reads,
  // including the one-cell slope halo, clipped to the scene.
  void window_for_lines(int line0, int line1, int& row0, int& rows, int& col0, int& cols) const;
  // The row (track along y) or column (along x) of cells line `line` runs
  // over; -1 when none.
  int cell_of_line(int line) const;

  // Processes lines [line0, line1) (OpenMP over lines, per-thread scratch):
  // fills their rows of `prof` and the cells of `maps` those lines cover
  // (none when maps.mask is null); adds to counts. `in` must hold
  // window_for_lines(line0, line1). keep (optional): what the run keeps
  // beyond the profiles (form_slar_image_fused's SlarEngineKeep).
  // sample_maps (optional): every sample's scene-map value of the lines,
  // as the kept geometry gives them to scene_geometry_maps. channels: the
  // run's channels after the first, whose profiles the same lines fill.
  void run(int line0, int line1, const SceneWindow& in, SlarLineProfiles& prof,
           const SceneMapsWindow& maps, SlarLineCounts& counts,
           const detail::LineKeep* keep = nullptr, const SampleMapRows* sample_maps = nullptr,
           std::span<const detail::ExtraChannel> channels = {}) const;

 private:
  const Scene& scene_;
  SlarGeometry g_;
  const Sigma0Lut& lut_;
  SlarImagingParams params_;
  TwoWayGainTable gain2_;
  bool cross_is_x_ = true;
  bool u_grows_with_index_ = true;
};

// Throws the InputError of a swath that misses the scene (no sample in
// it; counts: the slant-range extent of the samples with data):
// ris/image/swath_miss.h, naming view_key (the keys that place the radar)
// when no sample with data is in view at all.
void check_swath_hits_scene(std::int64_t samples_in_swath, const SlantRangeBins& range,
                            const SlarLineCounts& counts, const std::string& radar_file,
                            const std::string& view_key = "track");

// The geometry's sample counts from the engine's.
void set_sample_counts(SlarGeometry& g, const SlarLineCounts& counts);

// The image of an engine run's line profiles (all lines, from line 0):
// azimuth integration over line_spacing_m; the profiles' counts move into it.
SlarImage slar_image_from_profiles(SlarLineProfiles& prof, const SlarImagingParams& p,
                                   double line_spacing_m);

// What an in-memory engine run keeps or adds beyond the image and the scene
// maps: the kept-geometry sink (the per-sample geometry of the whole run, as
// compute_slar_geometry makes it), each element's power (the coherent SAR's
// input) and point targets (as form_slar_image adds
// point_returns_on_lines's returns).
struct SlarEngineKeep {
  bool geometry = false;       // layout's per-sample arrays, allocated and filled
  bool element_power = false;  // SlarImage::element_power_w
  const std::vector<PointTarget>* targets = nullptr;  // added on their lines
  // With targets: the returns seen and the names of those hidden, as
  // point_returns_on_lines gives them (SlarImage::point_power_w in the
  // same order).
  std::vector<PointReturn>* point_returns = nullptr;
  std::vector<std::string>* hidden_targets = nullptr;
  // Lines per engine block (0: the engine's choice; any value gives the same
  // bytes, which the determinism tests check). Oblique tracks keep theirs.
  int block_lines = 0;
};

// The whole engine run for an in-memory scene: fills `maps` (rows x cols),
// sets layout's counts, returns the image as form_slar_image does (same
// InputError for a swath that misses the scene). Every category of a valid
// cell must be in lut. Oblique tracks (bilinear sampling) run line by line
// too, with the scene maps scattered per line: the same bytes as the stage
// path (tested), with whole-scene slope rasters (8 bytes per cell) but no
// per-sample geometry buffers unless kept. A track along a grid axis whose
// lines are not one per cell row or column (fused_slar_image_applies false)
// needs keep.geometry: its maps are made from the kept geometry
// (scene_geometry_maps).
//
// channels (the channel axis, ris/sim/slar_channels.h): more channels over
// the same lines, each with its own sigma0 look-up and imaging parameters
// (radar equation, gain, SAR windows) on the first channel's range bins;
// each channel's image is what a run of that channel alone gives (same
// bytes), from one pass of the geometry.
struct SlarImageChannel {
  const Sigma0Lut* lut = nullptr;
  const SlarImagingParams* params = nullptr;
  SlarImage* image = nullptr;  // written
  // Keep its SlarImage::element_power_w too (with keep.element_power: a
  // quad-pol SAR's HV and VV).
  bool keep_element_power = false;
};
SlarImage form_slar_image_fused(const Scene& scene, SlarGeometry& layout, SceneGeometryMaps& maps,
                                const Sigma0Lut& lut, const SlarImagingParams& params,
                                const std::string& radar_file, const SlarEngineKeep& keep = {},
                                std::span<const SlarImageChannel> channels = {});

}  // namespace ris
