// The scene-query stage (sim/engine/scene_query.h): its contributions, to
// the line being formed or to any other, give the same bytes for every
// thread count and engine block size; point targets, placed by it, too.
#include "sim/engine/scene_query.h"
#include "build_paths.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "ris/geometry/line_scan.h"
#include "ris/perf/bench_setup.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/sim/slar_run_setup.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/units.h"
#include "sim/engine/slar_line_engine.h"
#include "sim/engine/slar_line_stages.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

using test::same_bytes;

RadarParams rugged_radar(const Scene& s, double heading_deg, bool sar) {
  const RadarParams base =
      load_radar(std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml");
  RadarParams r = bench_radar(base, s, deg_to_rad(heading_deg));
  r.track.altitude_m = 600.0;  // steep enough for shadow over 30 m of relief
  r.track.near_edge_ground_m = 1500.0;
  r = bench_radar(r, s, deg_to_rad(heading_deg));
  if (sar) {  // incoherent SAR: a range window wider than the bins
    r.mode = RadarMode::sar;
    r.sar.range_resolution_m = 2.5 * r.range_bin_m;
    r.sar.azimuth_resolution_m = 14.0;
    r.sar.range_looks = 1;
    r.sar.azimuth_looks = 2;
    r.sar.nesz = 1e-3;
  }
  return r;
}

// Targets in the open, beside and behind the tower, near the no-data hole.
std::vector<PointTarget> targets_on(const Scene& s) {
  std::vector<PointTarget> out;
  int index = 0;
  for (const auto& [r, c] :
       {std::pair{10, 20}, std::pair{30, 55}, std::pair{30, 75}, std::pair{45, 50},
        std::pair{19, 43}, std::pair{55, 85}, std::pair{30, 56}, std::pair{31, 55}}) {
    PointTarget t;
    t.name = fmt::format("t{}", index);
    const auto [x, y] = s.world_from_grid(c + 0.5, r + 0.5);
    t.x_m = x;
    t.y_m = y;
    t.height_m = 2.0;
    t.rcs_m2 = 300.0 + 50.0 * index;
    t.source_file = "targets.toml";
    t.index = index++;
    out.push_back(t);
  }
  return out;
}

// Point targets go through the scene-query stage in every SLAR and
// incoherent SAR run: the image, the point powers and the targets seen and
// hidden are the same bytes for 1 and 2 threads and any engine block size,
// along rows (heading 0) and columns (heading 90: column tiles).
TEST(SceneQuery, PointTargetsSameBytesForAnyThreadsAndBlockSize) {
  const Scene s = test::rugged_test_scene();
  const test::CosineSigma0Source src({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const int saved = omp_get_max_threads();
  for (double heading_deg : {0.0, 90.0}) {
    for (bool sar : {false, true}) {
      const RadarParams r = rugged_radar(s, heading_deg, sar);
      SlarOptions o;
      o.targets = targets_on(s);
      omp_set_num_threads(1);
      const SlarSimulation ref = simulate_slar(s, r, src, o);
      EXPECT_FALSE(ref.image.point_power_w.empty());
      for (int threads : {1, 2}) {
        for (int block_lines : {1, 3, 7, 16, 64, 1000}) {
          omp_set_num_threads(threads);
          o.engine_block_lines = block_lines;
          const SlarSimulation got = simulate_slar(s, r, src, o);
          const std::string what = fmt::format("heading {} sar {} threads {} block_lines {}",
                                               heading_deg, sar, threads, block_lines);
          EXPECT_TRUE(same_bytes(ref.image.mean_power_w, got.image.mean_power_w)) << what;
          EXPECT_TRUE(same_bytes(ref.image.point_power_w, got.image.point_power_w)) << what;
          EXPECT_EQ(ref.hidden_targets, got.hidden_targets) << what;
          EXPECT_EQ(ref.point_returns.size(), got.point_returns.size()) << what;
        }
      }
    }
  }
  omp_set_num_threads(saved);
}

// A cross-line effect for the test: from every tenth sample of each line
// that is lit (not shadowed, in front of the track), contributions at the
// bin of its slant range to its own line and to lines -2, +1, +3 and +9
// away, with powers that differ by source. With `cancel` the contributions
// 1 and 3 lines ahead are +1e17 and -1e17 W (numbers, not powers): a line's
// sum then depends on the order of addition far above its last bit, so a
// test sees any order that is not the fixed one. Each emitted contribution
// is recorded in its source line's slot (written by the thread forming that
// line only).
class GhostQuery final : public detail::SceneQueryStage {
 public:
  GhostQuery(int lines, bool cancel) : emitted_(static_cast<std::size_t>(lines)), cancel_(cancel) {}
  void query(const detail::LineQuery& q,
             std::vector<detail::LineContribution>& out) const override {
    std::vector<detail::LineContribution>& mine = emitted_[static_cast<std::size_t>(q.line)];
    mine.clear();
    for (int j = 0; j < q.n; j += 10) {
      const std::size_t jj = static_cast<std::size_t>(j);
      if (!sample_visible(q.s.flags[jj])) continue;  // shadow, no data, unseen: none
      const double pos = (q.s.range[jj] - q.ctx.near_m) * q.ctx.inv_dr;
      if (!(pos >= 0.0 && pos < q.ctx.bins)) continue;
      for (int dl : {0, -2, 1, 3, 9}) {
        const int line = q.line + dl;
        if (line < 0 || line >= static_cast<int>(emitted_.size())) continue;
        double power = 1e-13 * (1.0 + 0.37 * ((j + 7 * q.line) % 11)) / (1.0 + dl * dl);
        if (cancel_ && (dl == 1 || dl == 3)) power = dl == 1 ? 1e17 : -1e17;
        detail::LineContribution c;
        c.line = line;
        c.bin = static_cast<int>(pos) / 4;  // many sources on few bins
        c.source = static_cast<std::uint64_t>(j);
        c.power_w = power;
        out.push_back(c);
        mine.push_back(c);
      }
    }
  }
  // Every contribution emitted, by (target line, bin): the sum in double.
  std::map<std::pair<int, int>, double> sums() const {
    std::map<std::pair<int, int>, double> out;
    for (const auto& line : emitted_) {
      for (const detail::LineContribution& c : line) out[{c.line, c.bin}] += c.power_w;
    }
    return out;
  }

 private:
  mutable std::vector<std::vector<detail::LineContribution>> emitted_;
  bool cancel_ = false;
};

struct EngineRun {
  SlarLineProfiles prof;
  std::vector<detail::LineContribution> carried;
  double range_window_bins = 0.0;
};

// The direct engine over lines [line0, line1) of the run, with (or
// without) the ghost stage, at block_lines lines per block; carry: its
// contributions to other lines handed out (a streamed block) rather than
// added (in memory).
EngineRun run_engine(const Scene& s, const RadarParams& radar_in, int line0, int line1,
                     int block_lines, const GhostQuery* ghost, bool carry) {
  const test::CosineSigma0Source src({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  SlarSimulation sim;
  sim.radar = radar_in;
  sim.derived = derive(sim.radar);
  sim.track = resolve_track(sim.radar.track, s, sim.radar.source_file);
  sim.geometry = slar_geometry_layout(s, sim.track, sim.radar.azimuth_line_spacing_m);
  RadiometrySetup rs = prepare_radiometry(s, sim.radar, sim.derived, src, "cosine");
  complete_slar_setup(sim, rs, s);
  const SlarLineEngine engine(s, sim.geometry, rs.lut, rs.imaging, sim.radar.source_file);
  EngineRun out;
  out.range_window_bins = rs.imaging.range_window_bins;
  out.prof.allocate(line1 - line0, rs.imaging.range.count, line0);
  const detail::SceneQueryStage* stages[] = {ghost};
  detail::LineKeep keep;
  if (ghost) keep.queries = stages;
  if (carry) keep.carried = &out.carried;
  keep.block_lines = block_lines;
  SlarLineCounts counts;
  engine.run(line0, line1, SceneWindow::whole(s), out.prof, SceneMapsWindow{}, counts, &keep);
  return out;
}

// The run's lines in chunks of `chunk` lines as a streamed run's blocks
// (under MPI, any rank's): each chunk an engine call handing its carried
// contributions out, then all of them gathered and each chunk's added
// (what the sink does): the power rows of every line, in line order.
std::vector<float> chunked_power(const Scene& s, const RadarParams& r, int lines, int chunk,
                                 const GhostQuery& ghost) {
  std::vector<EngineRun> runs;
  std::vector<detail::LineContribution> all;
  for (int c0 = 0; c0 < lines; c0 += chunk) {
    runs.push_back(run_engine(s, r, c0, std::min(lines, c0 + chunk), 5, &ghost, true));
    all.insert(all.end(), runs.back().carried.begin(), runs.back().carried.end());
  }
  std::vector<float> power;
  for (EngineRun& run : runs) {
    const int c0 = run.prof.line0;
    const auto rest = detail::add_carried_contributions(all, c0, c0 + run.prof.lines,
                                                        run.range_window_bins, run.prof);
    for (const detail::LineContribution& c : rest) {
      EXPECT_TRUE(c.line < c0 || c.line >= c0 + run.prof.lines);
    }
    power.insert(power.end(), run.prof.power_w.begin(), run.prof.power_w.end());
  }
  return power;
}

// What the stage emitted is what the profiles gained (SLAR: no range
// window; float profiles, so within their rounding).
void expect_gained_what_emitted(const EngineRun& plain, const EngineRun& with,
                                const GhostQuery& ghost, int lines) {
  EXPECT_TRUE(same_bytes(plain.prof.area_m2, with.prof.area_m2));
  const auto sums = ghost.sums();
  int checked = 0;
  for (int line = 0; line < lines; ++line) {
    for (int b = 0; b < with.prof.bins; ++b) {
      const std::size_t i = with.prof.index(line, b);
      const auto it = sums.find({line, b});
      const double want = double(plain.prof.power_w[i]) + (it == sums.end() ? 0.0 : it->second);
      EXPECT_NEAR(with.prof.power_w[i], want, 1e-6 * std::abs(want) + 1e-30) << line << " " << b;
      if (it != sums.end()) ++checked;
    }
  }
  EXPECT_GT(checked, 100);
}

// Contributions across lines (backwards, forwards, past a block's end) give
// the same profiles for 1 and 2 threads and any block size, SLAR and SAR
// (the range window over carried rows); the run cut into chunks (a streamed
// run's blocks, under MPI on any rank) with the carried contributions
// gathered and added by the sink gives the same bytes; and the profiles gain
// what the stage emitted.
TEST(SceneQuery, CrossLineContributionsSameBytesForAnyThreadsBlocksAndChunks) {
  const Scene s = test::rugged_test_scene();
  const int saved = omp_get_max_threads();
  for (double heading_deg : {0.0, 90.0}) {
    for (bool sar : {false, true}) {
      for (bool cancel : {false, true}) {
        const RadarParams r = rugged_radar(s, heading_deg, sar);
        const Track t = resolve_track(r.track, s, r.source_file);
        const int lines = slar_geometry_layout(s, t, r.azimuth_line_spacing_m).lines;
        const GhostQuery ghost(lines, cancel);
        omp_set_num_threads(1);
        const EngineRun plain = run_engine(s, r, 0, lines, 16, nullptr, false);
        const EngineRun ref = run_engine(s, r, 0, lines, 16, &ghost, false);
        EXPECT_TRUE(ref.carried.empty());
        EXPECT_FALSE(same_bytes(plain.prof.power_w, ref.prof.power_w));
        const std::vector<float> ref_power(ref.prof.power_w.begin(), ref.prof.power_w.end());
        for (int threads : {1, 2}) {
          omp_set_num_threads(threads);
          const std::string what = fmt::format("heading {} sar {} cancel {} threads {}",
                                               heading_deg, sar, cancel, threads);
          for (int block_lines : {1, 2, 5, 16, 33, 1000}) {
            const EngineRun got = run_engine(s, r, 0, lines, block_lines, &ghost, false);
            EXPECT_TRUE(same_bytes(ref.prof.power_w, got.prof.power_w))
                << what << " block_lines " << block_lines;
            EXPECT_TRUE(same_bytes(ref.prof.area_m2, got.prof.area_m2))
                << what << " block_lines " << block_lines;
          }
          for (int chunk : {7, 20, 64}) {
            EXPECT_TRUE(same_bytes(ref_power, chunked_power(s, r, lines, chunk, ghost)))
                << what << " chunk " << chunk;
          }
        }
        if (!sar && !cancel) expect_gained_what_emitted(plain, ref, ghost, lines);
      }
    }
  }
  omp_set_num_threads(saved);
}

// The fixed order: by target line, bin, stage, source, source line, seq.
TEST(SceneQuery, ContributionOrderIsTotal) {
  detail::LineContribution a, b;
  a.line = 3;
  b.line = 4;
  EXPECT_TRUE(detail::contribution_before(a, b));
  EXPECT_FALSE(detail::contribution_before(b, a));
  b = a;
  b.seq = 1;
  EXPECT_TRUE(detail::contribution_before(a, b));
  b = a;
  b.source = 2;
  b.bin = a.bin - 1;
  EXPECT_TRUE(detail::contribution_before(b, a));
  EXPECT_FALSE(detail::contribution_before(a, a));
}

}  // namespace
}  // namespace ris
