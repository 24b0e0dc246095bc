// Internal: the line engine (sim/engine/slar_line_engine.h)'s per-line stages,
// shared by every line source (along a grid axis: slar_line_blocks.cpp; any
// other heading: slar_oblique_lines.cpp): per-thread line scratch, the
// line's look geometry, and radiometry and image formation of the line's
// elements into its range profile. They run the same code as the stage path
// (compute_slar_geometry + form_slar_image), so the products are the same
// bytes.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "kernels/image/slar_element.h"
#include "ris/geometry/line_scan.h"
#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"
#include "ris/sim/point_target.h"
#include "ris/sim/slar_line_parts.h"
#include "sim/engine/scene_query.h"

namespace ris::detail {

// One thread's line scratch, allocated once per run() call and thread.
struct LineScratch {
  std::vector<float> u, height, dz_dx, dz_dy, range, incidence, local_incidence, area, near_end,
      far_end, dh_du;
  std::vector<std::uint16_t> category;
  std::vector<std::uint8_t> flags;
  std::vector<std::uint8_t> unseen;      // kUnseen where u <= 0 (the same for every line)
  std::vector<std::uint8_t> none_valid;  // a row of no-data cells, beyond the scene's edge
  std::vector<float> none_z;
  SlarLineAccumulator acc;
  LineElementScratch elements;
  // The scene-query stage's lists (sim/engine/scene_query.h): a line's
  // contributions, and those for other lines this thread carries.
  std::vector<LineContribution> contributions, carried;
  LineScratch(const SlarGeometry& g, int bins)
      : u(static_cast<std::size_t>(g.samples)),
        height(u.size()),
        dz_dx(u.size()),
        dz_dy(u.size()),
        range(u.size()),
        incidence(u.size()),
        local_incidence(u.size()),
        area(u.size()),
        near_end(u.size()),
        far_end(u.size()),
        dh_du(u.size()),
        category(u.size()),
        flags(u.size()),
        unseen(u.size()),
        none_valid(u.size(), 0),
        none_z(u.size(), 0.0f),
        acc(bins),
        elements(g.samples, bins) {
    for (int j = 0; j < g.samples; ++j) {
      u[static_cast<std::size_t>(j)] = float(g.sample_u_m(j));
      unseen[static_cast<std::size_t>(j)] = g.sample_u_m(j) > 0.0 ? 0 : sample_flag::kUnseen;
    }
  }
};

// The point targets of an engine run: the candidates (ris/sim/point_target.h)
// sorted by line, and per candidate whether its line's terrain leaves it lit
// and the power it returns (written by the thread that forms its line).
struct LinePointTargets {
  std::vector<PointCandidate> by_line;
  std::vector<std::uint8_t> lit;
  std::vector<double> power_w;
  // Sorts the candidates by line (stable: target order within a line, the
  // order the stage path adds them in) and sizes lit and power_w.
  explicit LinePointTargets(std::vector<PointCandidate> candidates);
};

// What a run keeps beyond the profiles and the scene maps (the kept-geometry
// sink); a null member is not kept. Each line's part is written by the
// thread that forms the line.
struct LineKeep {
  // The per-sample geometry of the whole run, as compute_slar_geometry
  // makes it: arrays allocated (allocate_samples), one row per line.
  SlarGeometry* geometry = nullptr;
  // P_i of each element, lines x samples, zero-filled (the coherent SAR's
  // input, SlarImage::element_power_w).
  float* element_power_w = nullptr;
  // Point targets added to their lines' profiles.
  LinePointTargets* targets = nullptr;
  // With element_power_w: each element's slant range too (null: not
  // kept), in the same layout (the coherent SAR's range compression reads
  // both; a streamed block keeps them, src/sim/stream/sar_coherent_stream.h).
  float* slant_range_m = nullptr;
  // The line of the arrays' first row (a block's first line; 0: the run's).
  int line0 = 0;
  // The run's scene-query stages beyond the point targets (which `targets`
  // makes the first): sim/engine/scene_query.h.
  std::span<const SceneQueryStage* const> queries = {};
  // Where the query stages' contributions to other lines go, sorted, for
  // the caller to add once it holds every block's (a streamed run's pass:
  // add_carried_contributions). Null: the engine call adds them itself (an
  // in-memory run, whose one call forms every line; none may aim outside
  // the call's lines).
  std::vector<LineContribution>* carried = nullptr;
  // Lines per engine block (0: the engine's choice). Any value gives the
  // same bytes; the determinism tests vary it.
  int block_lines = 0;
};

// The look geometry, element ends, cast shadow and layover of a line whose
// terrain is in the scratch (MODEL.md section 2; the code the stage path
// runs: ris/geometry/line_scan.h).
void line_geometry(const SlarGeometry& g, const LineLookFrame& frame, bool need_incidence,
                   LineScratch& s);

// Image formation's per-line step (as form_slar_image): the line's elements
// into its range profile row; counts into `counts`. Returns the number of
// elements whose centre falls in a bin. first_sample: the line's sample
// index of the scratch's element 0, when it holds a span of the line
// (LineElements::first_index; the same bytes as the whole line then).
// keep (optional): the run's kept-geometry sink; g: the run's layout (its
// line numbering and samples), needed with keep or queries. queries: the
// run's scene-query stages (point targets first), run after the line's
// elements and before the range window (sim/engine/scene_query.h); their
// contributions to other lines go to s.carried.
std::int64_t accumulate_line(const SlarElementContext& ctx, int samples, LineScratch& s,
                             SlarLineProfiles& prof, int line, SlarLineCounts& counts,
                             double range_window_bins, int first_sample = 0,
                             const LineKeep* keep = nullptr, const SlarGeometry* g = nullptr,
                             std::span<const SceneQueryStage* const> queries = {});

// A channel of a run beyond its first (the channel axis: another frequency,
// polarisation or backscatter source over the same geometry,
// ris/sim/slar_channels.h): its element context (radar equation, gain
// table, sigma0 look-up), its range window and its profiles, which each line
// fills after the first channel's from the same per-line geometry in the
// scratch. The range bins are the first channel's. No kept geometry and no
// point targets (the first channel keeps what is kept).
// The most channels whose element powers one run keeps (a quad-pol SAR's
// HV and VV beside HH).
inline constexpr std::size_t kMaxKeptChannels = 8;

struct ExtraChannel {
  const SlarElementContext* ctx = nullptr;
  double range_window_bins = 0.0;
  SlarLineProfiles* prof = nullptr;
  // Each element's power for this channel, in LineKeep::element_power_w's
  // layout (null: not kept; a quad-pol SAR keeps every channel's).
  float* element_power_w = nullptr;
};

// The further channels' per-line step (the channel axis), right after the
// first channel's accumulate_line on the same line and scratch: their
// power from the same elements (scatter_channel_elements; contexts: the
// channels' element contexts, in order; s.elements.reserve_channels done),
// each channel's range window and row of its profiles; the area, touch
// bits and centre counts are the first channel's row (the geometry's). The
// same bytes as accumulate_line with each channel's context would give, at
// a fraction of its work.
// keep and g: where the channels' element powers go (LineKeep's rows).
void accumulate_channel_lines(std::span<const ExtraChannel> channels,
                              std::span<const SlarElementContext* const> contexts, int samples,
                              LineScratch& s, const SlarLineProfiles& first, int line,
                              int first_sample, const LineKeep* keep = nullptr,
                              const SlarGeometry* g = nullptr);

// The kept-geometry sink's step: the line's samples [first, first + n) from
// the scratch into row `line` of `kept`, the samples outside unseen (NaN,
// category 0, kUnseen: as the stage path leaves a sample without terrain).
void keep_line_geometry(SlarGeometry& kept, int line, int first, int n, const LineScratch& s);

// The fused run for a heading off the grid axes (slar_oblique_lines.cpp):
// fills prof (allocated), maps (sized to the scene) and counts.
// keep (optional): the kept-geometry sink and point targets. channels: the
// run's channels after the first (sim/engine/slar_line_engine.h).
void run_oblique_lines(const Scene& scene, const SlarGeometry& g, const Sigma0Lut& lut,
                       const SlarImagingParams& p, const std::string& radar_file,
                       SlarLineProfiles& prof, SceneGeometryMaps& maps, SlarLineCounts& counts,
                       const LineKeep* keep = nullptr, std::span<const ExtraChannel> channels = {});

}  // namespace ris::detail
