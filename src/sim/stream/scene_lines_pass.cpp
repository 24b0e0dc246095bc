#include "sim/stream/scene_lines_pass.h"

#include <utility>

#include "ris/image/shadow_map.h"
#include "ris/util/error.h"
#include "sim/engine/block_pass.h"
#include "sim/stream/scene_row_passes.h"

namespace ris::detail {

SceneLineSinks open_scene_line_sinks(SceneProductWriters& w, const Scene& grid,
                                     const SlarSimulation& sim, bool spill_maps) {
  SceneLineSinks k;
  if (spill_maps) {
    // Off the axes (or lines not one per cell), the blocks' per-sample map
    // values (pass 1m's input).
    k.scene_mask = w.open_spill<std::uint8_t>(kSpillMaskFile);
    k.incidence = w.open_spill<float>(kSpillIncidenceFile);
  } else {
    const ris::BlockOrder line_order = scene_line_order(sim.track);
    k.scene_mask = w.open<std::uint8_t>("scene_mask.tif", grid.cols, grid.rows, line_order);
    k.incidence = w.open<float>("local_incidence_deg.tif", grid.cols, grid.rows, line_order);
  }
  const auto shadow = w.dir().path("shadowmap.txt");
  k.shadow_text.open(shadow, std::ios::binary);
  if (!k.shadow_text) throw InputError(shadow.string(), "", "cannot write");
  return k;
}

void scene_maps_pass(ProcessGroup& group, const BlockOrder& order, const SceneStreamReader& in,
                     int band_rows, const SlarSimulation& sim, int fail_block,
                     FloatRankSelect& elevation, SceneProductWriters* writers,
                     SceneLineSinks* sinks) {
  const bool root = group.rank() == 0;
  const Scene& grid = in.grid();
  std::unique_ptr<GeoTiffBlockWriter<std::uint8_t>> mask_out;
  std::unique_ptr<GeoTiffBlockWriter<float>> incidence_out;
  if (root) {
    sinks->scene_mask->close();
    sinks->incidence->close();
    sinks->scene_mask.reset();
    sinks->incidence.reset();
    mask_out = writers->open<std::uint8_t>("scene_mask.tif", grid.cols, grid.rows);
    incidence_out = writers->open<float>("local_incidence_deg.tif", grid.cols, grid.rows);
  }
  const std::filesystem::path dir(
      share_from_rank0(group, 0.0, root ? writers->dir().path("").string() : std::string()).second);
  SceneMapsPass pass(in, band_rows, sim, dir, fail_block, elevation, mask_out.get(),
                     incidence_out.get());
  run_pass(group, order, pass);
  pass.release();
  if (!root) return;
  mask_out->close();
  incidence_out->close();
  std::filesystem::remove(writers->dir().path(kSpillMaskFile));
  std::filesystem::remove(writers->dir().path(kSpillIncidenceFile));
}

StreamLineBlock SceneLinesPass::compute(int b) {
  const double t0 = process_cpu_seconds();
  StreamLineBlock k = blocks_.compute(b);
  cpu_.compute += process_cpu_seconds() - t0;
  ++cpu_.computed;
  return k;
}

void SceneLinesPass::consume(int, StreamLineBlock& k) {
  const double t0 = process_cpu_seconds();
  const int count = k.l1 - k.l0;
  sinks_->scene_mask->write(k.scene_mask.data(), count);
  sinks_->incidence->write(k.incidence.data(), count);
  write_shadow_text(k.prof, k.l0, k.l1);
  sinks_->image->take(k);
  bar_.advance(std::int64_t(count) * cross_cells_);
  ++consumed_;
  if (spare_.size() < 2) spare_.push_back(std::move(k));
  cpu_.consume += process_cpu_seconds() - t0;
}

// The seed's shadow map, line by line (ris/image/shadow_map.h).
void SceneLinesPass::write_shadow_text(const SlarLineProfiles& prof, int l0, int l1) {
  text_.clear();
  for (int line = l0; line < l1; ++line) {
    for (int b = 0; b < prof.bins; ++b) {
      const std::size_t i = prof.index(line, b);
      text_.push_back(shadow_map_char(prof.mapped_count[i], prof.visible_count[i]));
    }
    text_.push_back('\n');
  }
  sinks_->shadow_text.write(text_.data(), static_cast<std::streamsize>(text_.size()));
}

}  // namespace ris::detail
