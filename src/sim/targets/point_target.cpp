#include "ris/sim/point_target.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "ris/geometry/terrain_sample.h"
#include "ris/io/config_table.h"
#include "ris/util/error.h"

namespace ris {

std::vector<PointTarget> point_targets_from_toml(const toml::table& doc,
                                                 const std::string& source_file) {
  ConfigTable root(doc, source_file, "");
  std::vector<PointTarget> out;
  int i = 0;
  for (ConfigTable& t : root.table_array("target")) {
    PointTarget p;
    p.source_file = source_file;
    p.index = i;
    p.name = t.get_string_or("name", fmt::format("target {}", i));
    const std::vector<double> xy = t.get_quantity_array("position", Quantity::length);
    if (xy.size() != 2 || !std::isfinite(xy[0]) || !std::isfinite(xy[1])) {
      t.fail("position", "expected [x, y] in scene metres (2 finite values)");
    }
    p.x_m = xy[0];
    p.y_m = xy[1];
    p.height_m = t.get_quantity_or("height", Quantity::length, 0.0);
    if (!(p.height_m >= 0.0) || !std::isfinite(p.height_m)) {
      t.fail("height", fmt::format("expected a height above the terrain >= 0, got {}", p.height_m));
    }
    const bool has_lin = t.has("rcs"), has_db = t.has("rcs_db");
    if (has_lin == has_db) {
      t.fail("rcs", "give exactly one of rcs (m^2) and rcs_db (dBsm)");
    }
    if (has_lin) {
      p.rcs_m2 = t.get_double("rcs");
      if (!(p.rcs_m2 > 0.0) || !std::isfinite(p.rcs_m2)) {
        t.fail("rcs", fmt::format("expected a radar cross-section > 0 m^2, got {}", p.rcs_m2));
      }
    } else {
      const double db = t.get_double("rcs_db");
      if (!std::isfinite(db)) t.fail("rcs_db", "expected a finite number of dBsm");
      p.rcs_m2 = std::pow(10.0, db / 10.0);
    }
    t.finish();
    out.push_back(p);
    ++i;
  }
  root.finish();
  if (out.empty()) {
    throw InputError(source_file, "target", "no [[target]] table: expected at least one target");
  }
  return out;
}

std::vector<PointTarget> load_point_targets(const std::string& path) {
  return point_targets_from_toml(parse_toml_file(path), path);
}

double terrain_height_at(const Scene& scene, double x_m, double y_m) {
  const TerrainSample ts = bilinear_terrain_sample(scene, nullptr, x_m, y_m);
  return ts.valid ? double(ts.height_m) : std::numeric_limits<double>::quiet_NaN();
}

void check_point_target_on_scene(const PointTarget& t, const Scene& grid, double terrain_height_m) {
  const auto [x0, y1] = grid.world_from_grid(0.0, 0.0);
  const auto [x1, y0] = grid.world_from_grid(grid.cols, grid.rows);
  const std::string key = fmt::format("target[{}].position", t.index);
  if (!(t.x_m >= x0 && t.x_m <= x1 && t.y_m >= y0 && t.y_m <= y1)) {
    throw InputError(t.source_file, key,
                     fmt::format("target \"{}\" at ({:.1f}, {:.1f}) m is off the scene, which "
                                 "spans x {:.1f} to {:.1f} m and y {:.1f} to {:.1f} m",
                                 t.name, t.x_m, t.y_m, x0, x1, y0, y1));
  }
  if (!std::isfinite(terrain_height_m)) {
    throw InputError(t.source_file, key,
                     fmt::format("target \"{}\" at ({:.1f}, {:.1f}) m stands on a no-data cell "
                                 "of the scene",
                                 t.name, t.x_m, t.y_m));
  }
}

void check_point_targets_on_scene(const std::vector<PointTarget>& targets, const Scene& scene) {
  for (const PointTarget& t : targets)
    check_point_target_on_scene(t, scene, terrain_height_at(scene, t.x_m, t.y_m));
}

bool point_lit_on_samples(const SlarGeometry& g, int first, int n, const std::uint8_t* flags,
                          const float* height_m, double u_m, double h_m) {
  // Shadowed when a nearer sample has a larger look angle from nadir, compared
  // as in ris/geometry/line_scan.h: psi_j > psi_p <=> u_j D_p - u_p D_j > 0.
  const double H = g.altitude_m;
  const double d_p = H - h_m;
  constexpr std::uint8_t kSkip = sample_flag::kNoData | sample_flag::kUnseen;
  for (int k = 0; k < n; ++k) {
    const double u = g.sample_u_m(first + k);
    if (u >= u_m) break;
    const std::size_t i = static_cast<std::size_t>(k);
    if (flags[i] & kSkip) continue;
    if (u * d_p - u_m * (H - double(height_m[i])) > 0.0) return false;
  }
  return true;
}

bool point_lit_on_line(const SlarGeometry& g, int line, double u_m, double h_m) {
  const std::size_t i = g.index(line, 0);
  return point_lit_on_samples(g, 0, g.samples, g.flags.data() + i, g.height_m.data() + i, u_m, h_m);
}

PointCandidate point_candidate(std::size_t target, int line, double along_m, double u_m, double h_m,
                               double altitude_m, double rcs_m2) {
  PointCandidate c;
  c.target = target;
  c.u_m = u_m;
  c.h_m = h_m;
  c.ret.line = line;
  c.ret.along_m = along_m;
  c.ret.slant_range_m = std::hypot(u_m, altitude_m - h_m);
  c.ret.look_rad = std::atan2(u_m, altitude_m - h_m);
  c.ret.rcs_m2 = rcs_m2;
  c.ret.target = target;
  return c;
}

std::vector<PointCandidate> point_candidates(const std::vector<PointTarget>& targets,
                                             const Scene& scene, const SlarGeometry& g) {
  std::vector<PointCandidate> out;
  const double H = g.altitude_m;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const PointTarget& t = targets[k];
    const auto [s, u] = g.track.along_cross(t.x_m, t.y_m);
    const int line = static_cast<int>(std::floor(s / g.line_spacing_m));
    const double h = terrain_height_at(scene, t.x_m, t.y_m) + t.height_m;
    if (!(line >= 0 && line < g.lines && u > 0.0 && std::isfinite(h) && h < H)) continue;
    out.push_back(point_candidate(k, line, s, u, h, H, t.rcs_m2));
  }
  return out;
}

std::vector<PointReturn> seen_point_returns(const std::vector<PointTarget>& targets,
                                            const std::vector<PointCandidate>& candidates,
                                            const std::vector<std::uint8_t>& lit,
                                            std::vector<std::string>* hidden) {
  RIS_CHECK(lit.size() == candidates.size());
  std::vector<PointReturn> out;
  std::size_t c = 0;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const bool candidate = c < candidates.size() && candidates[c].target == k;
    if (candidate && lit[c]) {
      out.push_back(candidates[c].ret);
    } else if (hidden) {
      hidden->push_back(targets[k].name);
    }
    if (candidate) ++c;
  }
  return out;
}

std::vector<PointReturn> point_returns_on_lines(const std::vector<PointTarget>& targets,
                                                const Scene& scene, const SlarGeometry& g,
                                                std::vector<std::string>* hidden) {
  const std::vector<PointCandidate> candidates = point_candidates(targets, scene, g);
  std::vector<std::uint8_t> lit(candidates.size());
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    lit[c] = point_lit_on_line(g, candidates[c].ret.line, candidates[c].u_m, candidates[c].h_m);
  }
  return seen_point_returns(targets, candidates, lit, hidden);
}

}  // namespace ris
