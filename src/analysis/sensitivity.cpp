#include "ris/analysis/sensitivity.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ris/image/speckle_statistics.h"
#include "ris/sim/run.h"
#include "ris/util/error.h"

namespace ris {

namespace {

// SplitMix64: a per-cell hash for the mislabelling (Steele, Lea & Flood 2014).
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

struct Compared {
  std::int64_t pixels = 0;
  double rms_db = 0.0, bias_db = 0.0, pearson = 0.0;
};

Compared compare_mean_power(const std::vector<float>& ref, const std::vector<float>& run) {
  Compared c;
  double s = 0.0, s2 = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
  for (std::size_t i = 0; i < ref.size() && i < run.size(); ++i) {
    if (!(ref[i] > 0.0f && run[i] > 0.0f) || !std::isfinite(ref[i]) || !std::isfinite(run[i]))
      continue;
    const double x = 10.0 * std::log10(ref[i]), y = 10.0 * std::log10(run[i]);
    s += y - x, s2 += (y - x) * (y - x);
    sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y;
    ++c.pixels;
  }
  if (c.pixels == 0) return c;
  const double n = double(c.pixels);
  c.bias_db = s / n;
  c.rms_db = std::sqrt(s2 / n);
  const double vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
  c.pearson = vx > 0.0 && vy > 0.0 ? (sxy - sx * sy / n) / std::sqrt(vx * vy) : 1.0;
  return c;
}

struct Images {
  std::vector<float> mean_power;
  double enl = 0.0;
};

Images simulate(const SensitivityStudy& st, std::shared_ptr<const Scene> scene,
                const RadarParams& radar, std::uint64_t seed) {
  RunRequest r;
  r.scene = std::move(scene);
  r.scene_path = "scene";
  r.radar = radar;
  r.radar_path = radar.source_file;
  r.sigma0 = st.sigma0;
  r.backscatter_path = st.backscatter_path;
  r.seed = seed;
  RunCallbacks cb;
  cb.warning = [](const std::string&) {};
  const RunResult res = run_simulation(r, cb);
  Images out;
  const SlarImage* img = nullptr;
  std::span<const float> speckled;
  if (const SlarRun* slar = slar_image_run(res)) {
    img = &slar->sim.image;
    speckled = slar->pictures.speckled_power_w;
  } else if (const auto* ppi = std::get_if<PpiRun>(&res.run)) {
    img = &ppi->sim.bscope;
    speckled = ppi->pictures.speckled_power_w;
  } else {
    throw InputError("scene", "sensitivity", "a streamed run keeps no images to compare");
  }
  out.mean_power.assign(img->mean_power_w.begin(), img->mean_power_w.end());
  const IntensityView v{speckled, img->bins, img->lines, {}};
  try {
    out.enl = pooled_speckle(v, homogeneous_windows(v, {})).enl;
  } catch (const InputError&) {
    out.enl = 0.0;  // no homogeneous region (fading off)
  }
  return out;
}

}  // namespace

const std::vector<std::string>& sensitivity_keys() {
  static const std::vector<std::string> keys = {
      "cell_factor",  "elevation_step", "mislabel",           "frequency",
      "polarisation", "film_gamma",     "film_density_range", "seed"};
  return keys;
}

bool is_sensitivity_key(const std::string& key) {
  const auto& k = sensitivity_keys();
  return std::find(k.begin(), k.end(), key) != k.end();
}

Scene coarsened_scene(const Scene& s, int factor) {
  RIS_CHECK(factor >= 1);
  Scene out = s;
  if (factor == 1) return out;
  for (int r0 = 0; r0 < s.rows; r0 += factor) {
    for (int c0 = 0; c0 < s.cols; c0 += factor) {
      const int r1 = std::min(s.rows, r0 + factor), c1 = std::min(s.cols, c0 + factor);
      double sum = 0.0;
      int n = 0;
      std::map<std::uint16_t, int> votes;
      for (int r = r0; r < r1; ++r)
        for (int c = c0; c < c1; ++c) {
          const std::size_t i = s.index(r, c);
          if (!s.valid[i]) continue;
          sum += s.elevation_m[i];
          ++n;
          ++votes[s.category[i]];
        }
      if (n == 0) continue;
      // The most common category (the smallest id on a tie).
      std::uint16_t mode = votes.begin()->first;
      int best = 0;
      for (const auto& [c, k] : votes)
        if (k > best) best = k, mode = c;
      for (int r = r0; r < r1; ++r)
        for (int c = c0; c < c1; ++c) {
          const std::size_t i = s.index(r, c);
          if (!s.valid[i]) continue;
          out.elevation_m[i] = static_cast<float>(sum / n);
          out.category[i] = mode;
        }
    }
  }
  return out;
}

Scene quantised_scene(const Scene& s, double step_m) {
  Scene out = s;
  if (!(step_m > 0.0)) return out;
  for (float& z : out.elevation_m) z = static_cast<float>(step_m * std::round(z / step_m));
  return out;
}

Scene mislabelled_scene(const Scene& s, double fraction, std::uint64_t seed) {
  Scene out = s;
  std::vector<std::uint16_t> used;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.valid[i]) used.push_back(s.category[i]);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  if (used.size() < 2 || !(fraction > 0.0)) return out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.valid[i]) continue;
    const std::uint64_t h = mix(seed ^ mix(i));
    // The top 53 bits as a uniform number in [0, 1): below `fraction`, the
    // cell is mislabelled (so a larger fraction mislabels a superset).
    if (double(h >> 11) * 0x1.0p-53 >= fraction) continue;
    // Another of the scene's categories, chosen by the hash's low bits.
    const auto self = std::lower_bound(used.begin(), used.end(), s.category[i]) - used.begin();
    const std::size_t k =
        (static_cast<std::size_t>(self) + 1 + (h & 0xffff) % (used.size() - 1)) % used.size();
    out.category[i] = used[k];
  }
  return out;
}

std::vector<SensitivityRow> run_sensitivity(const SensitivityStudy& st,
                                            const std::vector<SensitivityAxis>& axes,
                                            const std::function<void(const SensitivityRow&)>& row) {
  for (const SensitivityAxis& a : axes) {
    if (!is_sensitivity_key(a.key)) {
      throw InputError("", "--vary",
                       fmt::format("unknown key '{}'; expected one of {}", a.key,
                                   fmt::join(sensitivity_keys(), ", ")));
    }
    for (double v : a.values) {
      const bool ok = std::isfinite(v) &&
                      (a.key == "cell_factor"      ? v >= 1.0 && v == std::floor(v) && v <= 1024
                       : a.key == "mislabel"       ? v >= 0.0 && v <= 1.0
                       : a.key == "elevation_step" ? v >= 0.0
                       : a.key == "polarisation"   ? v >= 0.0 && v <= 3.0 && v == std::floor(v)
                       : a.key == "seed"           ? v >= 0.0 && v == std::floor(v)
                                                   : v > 0.0);
      if (!ok) {
        throw InputError("", "--vary", fmt::format("{} = {} is out of range", a.key, v));
      }
    }
  }
  const Images ref = simulate(st, st.scene, st.radar, st.seed);
  std::vector<SensitivityRow> rows;
  for (const SensitivityAxis& a : axes) {
    for (double v : a.values) {
      std::shared_ptr<const Scene> scene = st.scene;
      RadarParams radar = st.radar;
      std::uint64_t seed = st.seed;
      if (a.key == "cell_factor") {
        scene = std::make_shared<Scene>(coarsened_scene(*st.scene, static_cast<int>(v)));
      } else if (a.key == "elevation_step") {
        scene = std::make_shared<Scene>(quantised_scene(*st.scene, v));
      } else if (a.key == "mislabel") {
        scene = std::make_shared<Scene>(mislabelled_scene(*st.scene, v, st.mislabel_seed));
      } else if (a.key == "frequency") {
        radar = radar_at_band(st.radar, v, st.radar.polarisation);
      } else if (a.key == "polarisation") {
        radar = radar_at_band(st.radar, st.radar.frequency_hz,
                              static_cast<Polarisation>(static_cast<int>(v)));
      } else if (a.key == "film_gamma") {
        radar.film.gamma = v;
      } else if (a.key == "film_density_range") {
        radar.film.density_range = v;
      } else if (a.key == "seed") {
        seed = static_cast<std::uint64_t>(v);
      }
      const Images run = simulate(st, scene, radar, seed);
      const Compared c = compare_mean_power(ref.mean_power, run.mean_power);
      SensitivityRow r{a.key, v, c.pixels, c.rms_db, c.bias_db, c.pearson, run.enl};
      rows.push_back(r);
      if (row) row(r);
    }
  }
  return rows;
}

}  // namespace ris
