#include "ris/image/slar_image.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

// Two-way gain G^2 = (peak x G_e(beta))^2 tabulated over beta in [0, 90 deg].
class TwoWayGainTable {
 public:
  static constexpr int kSteps = 9000;
  static constexpr double kStepRad = (kPi / 2.0) / kSteps;

  TwoWayGainTable(const std::function<double(double)>& relative_gain, double peak_gain,
                  const std::string& radar_file) {
    table_.resize(kSteps + 1);
    for (int i = 0; i <= kSteps; ++i) {
      const double beta = i * kStepRad;
      const double g = (relative_gain ? relative_gain(beta) : 1.0) * peak_gain;
      if (!std::isfinite(g) || g < 0.0) {
        throw InputError(radar_file, "elevation_pattern",
                         fmt::format("gain {} at look angle {:.2f} deg; expected finite and >= 0",
                                     g, rad_to_deg(beta)));
      }
      table_[static_cast<std::size_t>(i)] = g * g;
    }
  }

  double at(double beta_rad) const {
    const double pos = std::clamp(beta_rad / kStepRad, 0.0, double(kSteps));
    const int i = std::min(static_cast<int>(pos), kSteps - 1);
    const double f = pos - i;
    const double* t = table_.data() + i;
    return t[0] + f * (t[1] - t[0]);
  }

 private:
  std::vector<double> table_;
};

// Per line and bin, which kinds of element touch the bin.
constexpr std::uint8_t kTouchData = 1;
constexpr std::uint8_t kTouchVisible = 2;
constexpr std::uint8_t kTouchLayover = 4;

// Adds `power` spread uniformly over the bin-coordinate interval between x0
// and x1 (either order) to acc; the part outside [0, bins) is lost. A
// zero-length interval puts everything into its bin.
void spread(std::vector<double>& acc, std::vector<double>& acc_area, double x0, double x1,
            double power, double area, int bins) {
  const double lo = std::min(x0, x1), hi = std::max(x0, x1);
  if (hi < 0.0 || lo >= bins) return;
  const int b0 = std::max(0, static_cast<int>(std::floor(lo)));
  const int b1 = std::min(bins - 1, static_cast<int>(std::floor(hi)));
  const double width = hi - lo;
  if (b0 == b1 && width <= 0.0) {
    acc[static_cast<std::size_t>(b0)] += power;
    acc_area[static_cast<std::size_t>(b0)] += area;
    return;
  }
  const double inv_width = 1.0 / width;
  for (int b = b0; b <= b1; ++b) {
    const double f = (std::min(hi, double(b + 1)) - std::max(lo, double(b))) * inv_width;
    acc[static_cast<std::size_t>(b)] += power * f;
    acc_area[static_cast<std::size_t>(b)] += area * f;
  }
}

std::uint16_t saturating_increment(std::uint16_t v) {
  return v == std::numeric_limits<std::uint16_t>::max() ? v : static_cast<std::uint16_t>(v + 1);
}

void check_inputs(const SlarGeometry& g, const Sigma0Lut& lut, const SlarImagingParams& p,
                  const std::string& radar_file) {
  RIS_CHECK(p.range.count > 0 && p.range.bin_m > 0.0);
  RIS_CHECK(p.azimuth_beamwidth_rad > 0.0);
  // Every category that can be seen must have sigma0 (checked once, not per
  // sample: the LUT lookup itself is unchecked).
  std::vector<std::uint8_t> checked(65536, 0);
  for (std::size_t i = 0; i < g.flags.size(); ++i) {
    if (!sample_visible(g.flags[i])) continue;
    const std::uint16_t c = g.category[i];
    if (checked[c]) continue;
    checked[c] = 1;
    if (!lut.has(c)) {
      throw InputError(radar_file, "category",
                       fmt::format("no backscatter for category {} (the scene uses it)", c));
    }
  }
}

}  // namespace

SlarImage form_slar_image(const SlarGeometry& g, const Sigma0Lut& lut, const SlarImagingParams& p,
                          const std::string& radar_file) {
  check_inputs(g, lut, p, radar_file);
  SlarImage img;
  img.lines = g.lines;
  img.bins = p.range.count;
  img.range = p.range;
  img.line_spacing_m = g.line_spacing_m;
  const std::size_t n_pix =
      static_cast<std::size_t>(img.lines) * static_cast<std::size_t>(img.bins);
  img.mean_power_w.assign(n_pix, 0.0f);
  img.area_m2.assign(n_pix, 0.0f);
  img.mask.assign(n_pix, 0);
  img.mapped_count.assign(n_pix, 0);
  img.visible_count.assign(n_pix, 0);

  const TwoWayGainTable gain2(p.elevation_gain, p.peak_gain, radar_file);
  // P_t lambda^2 / (4 pi)^3: the radar equation's constant part.
  const double k_radar =
      p.transmit_power_w * p.wavelength_m * p.wavelength_m / std::pow(4.0 * kPi, 3.0);
  const double near = p.range.near_m, dr = p.range.bin_m, inv_dr = 1.0 / dr;
  const int bins = img.bins;

  // Per-line range profiles before azimuth integration and per-line touch bits.
  std::vector<float> line_power(n_pix, 0.0f);
  std::vector<float> line_area(n_pix, 0.0f);
  std::vector<std::uint8_t> touch(n_pix, 0);
  std::int64_t in_swath = 0;

#pragma omp parallel reduction(+ : in_swath)
  {
    // Per-thread scratch, allocated once.
    std::vector<double> acc(static_cast<std::size_t>(bins));
    std::vector<double> acc_area(static_cast<std::size_t>(bins));
#pragma omp for schedule(dynamic, 8)
    for (int line = 0; line < g.lines; ++line) {
      std::fill(acc.begin(), acc.end(), 0.0);
      std::fill(acc_area.begin(), acc_area.end(), 0.0);
      const std::size_t row = img.index(line, 0);
      for (int j = 0; j < g.samples; ++j) {
        const std::size_t i = g.index(line, j);
        const std::uint8_t f = g.flags[i];
        if (f & (sample_flag::kNoData | sample_flag::kUnseen)) continue;
        const double R = g.slant_range_m[i];
        const bool visible = sample_visible(f);
        // Centre counts (the seed's shadow map).
        const double pos = (R - near) * inv_dr;
        if (pos >= 0.0 && pos < bins) {
          const std::size_t k = row + static_cast<std::size_t>(pos);
          img.mapped_count[k] = saturating_increment(img.mapped_count[k]);
          if (visible) img.visible_count[k] = saturating_increment(img.visible_count[k]);
          ++in_swath;
        }
        // The element's slant-range span and the bins it touches.
        const double r_a = g.range_near_end_m[i], r_b = g.range_far_end_m[i];
        const double lo = (std::min({r_a, r_b, R}) - near) * inv_dr;
        const double hi = (std::max({r_a, r_b, R}) - near) * inv_dr;
        if (hi < 0.0 || lo >= bins) continue;
        const int b0 = std::max(0, static_cast<int>(std::floor(lo)));
        const int b1 = std::min(bins - 1, static_cast<int>(std::floor(hi)));
        std::uint8_t bits = kTouchData;
        if (visible) bits |= kTouchVisible;
        if (visible && (f & sample_flag::kLayover)) bits |= kTouchLayover;
        for (int b = b0; b <= b1; ++b) touch[row + static_cast<std::size_t>(b)] |= bits;
        if (!visible) continue;
        // Radar equation (MODEL.md section 3, seed equations 1 and 3-5).
        const double r2 = R * R;
        const double power = k_radar * gain2.at(g.incidence_rad[i]) *
                             double(lut.at(g.category[i], g.local_incidence_rad[i])) *
                             double(g.area_m2[i]) / (r2 * r2);
        // Half the element (near end to centre, centre to far end) each.
        const double half_area = 0.5 * double(g.area_m2[i]);
        spread(acc, acc_area, (r_a - near) * inv_dr, pos, 0.5 * power, half_area, bins);
        spread(acc, acc_area, pos, (r_b - near) * inv_dr, 0.5 * power, half_area, bins);
      }
      for (int b = 0; b < bins; ++b) {
        const std::size_t bb = static_cast<std::size_t>(b);
        line_power[row + bb] = static_cast<float>(acc[bb]);
        line_area[row + bb] = static_cast<float>(acc_area[bb]);
      }
    }
  }
  img.samples_in_swath = in_swath;
  if (in_swath == 0) {
    // Where the scene is, for the message.
    float r_min = std::numeric_limits<float>::infinity(), r_max = -r_min;
    for (std::size_t i = 0; i < g.flags.size(); ++i) {
      if (g.flags[i] & (sample_flag::kNoData | sample_flag::kUnseen)) continue;
      r_min = std::min(r_min, g.slant_range_m[i]);
      r_max = std::max(r_max, g.slant_range_m[i]);
    }
    throw InputError(radar_file, "sweep_delay",
                     fmt::format("the swath (slant range {:.1f} to {:.1f} m) misses the scene, "
                                 "which spans slant range {:.1f} to {:.1f} m; expected a sweep "
                                 "delay and length (or near range and range bins) that overlap it",
                                 p.range.near_m, p.range.far_m(), r_min, r_max));
  }

  // Azimuth: per bin, a running sum over lines. Line j stands for the strip
  // [j - 1/2, j + 1/2] (in line units); the pixel on line k integrates the
  // piecewise-constant profile over [k - half, k + half], half = w / (2 ds).
  const int n = g.lines;
#pragma omp parallel
  {
    std::vector<double> cum(static_cast<std::size_t>(n) + 1);
    std::vector<double> cum_area(static_cast<std::size_t>(n) + 1);
    std::vector<int> cum_data(static_cast<std::size_t>(n) + 1);
    std::vector<int> cum_visible(static_cast<std::size_t>(n) + 1);
    std::vector<int> cum_layover(static_cast<std::size_t>(n) + 1);
#pragma omp for schedule(static)
    for (int b = 0; b < bins; ++b) {
      cum[0] = cum_area[0] = 0.0;
      cum_data[0] = cum_visible[0] = cum_layover[0] = 0;
      for (int j = 0; j < n; ++j) {
        const std::size_t k = img.index(j, b), jj = static_cast<std::size_t>(j);
        cum[jj + 1] = cum[jj] + double(line_power[k]);
        cum_area[jj + 1] = cum_area[jj] + double(line_area[k]);
        cum_data[jj + 1] = cum_data[jj] + ((touch[k] & kTouchData) ? 1 : 0);
        cum_visible[jj + 1] = cum_visible[jj] + ((touch[k] & kTouchVisible) ? 1 : 0);
        cum_layover[jj + 1] = cum_layover[jj] + ((touch[k] & kTouchLayover) ? 1 : 0);
      }
      // Integral of the profile from -1/2 to x (line units), clamped.
      const auto integral = [n](const std::vector<double>& c, double x) {
        const double y = std::clamp(x + 0.5, 0.0, double(n));
        const int i = std::min(static_cast<int>(y), n - 1);
        const double f = y - i;
        const std::size_t ii = static_cast<std::size_t>(i);
        return c[ii] + f * (c[ii + 1] - c[ii]);
      };
      const double half =
          0.5 * slar_footprint_m(p.range.centre_m(b), p.azimuth_beamwidth_rad) / g.line_spacing_m;
      for (int k = 0; k < n; ++k) {
        const double a = k - half, e = k + half;
        const std::size_t pix = img.index(k, b);
        img.mean_power_w[pix] = static_cast<float>(integral(cum, e) - integral(cum, a));
        img.area_m2[pix] = static_cast<float>(integral(cum_area, e) - integral(cum_area, a));
        // Lines whose strip overlaps the footprint: j + 1/2 > a and j - 1/2 < e.
        const int j_lo = std::max(0, static_cast<int>(std::floor(a - 0.5)) + 1);
        const int j_hi = std::min(n - 1, static_cast<int>(std::ceil(e + 0.5)) - 1);
        const std::size_t lo = static_cast<std::size_t>(j_lo),
                          hi = static_cast<std::size_t>(j_hi) + 1;
        const int data = cum_data[hi] - cum_data[lo];
        const int visible = cum_visible[hi] - cum_visible[lo];
        const int layover = cum_layover[hi] - cum_layover[lo];
        std::uint8_t m = 0;
        if (data == 0) m |= pixel_flag::kNoData;
        if (data > 0 && visible == 0) m |= pixel_flag::kShadow;
        if (layover > 0) m |= pixel_flag::kLayover;
        img.mask[pix] = m;
      }
    }
  }
  return img;
}

}  // namespace ris
