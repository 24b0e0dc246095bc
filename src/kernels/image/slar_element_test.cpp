#include "kernels/image/slar_element.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "ris/geometry/line_scan.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris::detail {
namespace {

// One random line: elements in order of range with a few reversals
// (layover), spans mostly under a bin (some zero, some over several bins),
// the first and last ones beyond the swath's ends, every kind of flag.
struct RandomLine {
  int n = 0;
  std::vector<std::uint8_t> flags;
  std::vector<float> range, near_end, far_end, incidence, local_incidence, area;
  std::vector<std::uint16_t> category;

  RandomLine(int samples, std::uint32_t seed) : n(samples) {
    const auto size = static_cast<std::size_t>(n);
    flags.resize(size);
    for (auto* v : {&range, &near_end, &far_end, &incidence, &local_incidence, &area}) {
      v->resize(size);
    }
    category.resize(size);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    double r = -1.5;
    for (std::size_t j = 0; j < size; ++j) {
      r += u(rng) < 0.05 ? -0.4 : 0.21 + 0.05 * u(rng);
      const double kind = u(rng);
      const double span = kind < 0.05 ? 0.0 : (kind < 0.12 ? 1.0 + 3.0 * u(rng) : 0.45 * u(rng));
      const double t = u(rng);
      range[j] = static_cast<float>(r);
      near_end[j] = static_cast<float>(r - t * span);
      far_end[j] = static_cast<float>(r + (1.0 - t) * span);
      if (u(rng) < 0.1) std::swap(near_end[j], far_end[j]);  // facing away
      incidence[j] = static_cast<float>(0.3 + 0.9 * u(rng));
      local_incidence[j] = static_cast<float>(1.5 * u(rng));
      area[j] = static_cast<float>(30.0 + 10.0 * u(rng));
      category[j] = static_cast<std::uint16_t>(1 + j % 3);
      std::uint8_t f = 0;
      if (u(rng) < 0.05) f |= sample_flag::kNoData;
      if (u(rng) < 0.03) f |= sample_flag::kUnseen;
      if (u(rng) < 0.10) f |= sample_flag::kShadow;
      if (u(rng) < 0.05) f |= sample_flag::kBackFacing;
      if (u(rng) < 0.08) f |= sample_flag::kLayover;
      if (f & sample_flag::kNoData) {
        range[j] = near_end[j] = far_end[j] = local_incidence[j] = area[j] = nan;
        category[j] = 0;
      }
      flags[j] = f;
    }
  }
  LineElements elements() const {
    return {n,
            flags.data(),
            range.data(),
            near_end.data(),
            far_end.data(),
            incidence.data(),
            local_incidence.data(),
            area.data(),
            category.data()};
  }
};

// form_line_profile's outputs for one line: touch bits and counts zeroed,
// power and area filled with `fill` (form_line_profile overwrites them).
struct ProfileOut {
  std::vector<std::uint8_t> touch;
  std::vector<std::uint16_t> mapped, visible;
  std::vector<double> power, area;
  explicit ProfileOut(int bins, double fill = 0.0)
      : touch(static_cast<std::size_t>(bins), 0),
        mapped(touch.size(), 0),
        visible(touch.size(), 0),
        power(touch.size(), fill),
        area(touch.size(), fill) {}
  LineProfileRow row() {
    return {touch.data(), mapped.data(), visible.data(), power.data(), area.data()};
  }
};

// The reference: each element on its own, in order, in double precision,
// both halves through spread() (the definition in ris/image/slar_image.h).
struct Reference {
  std::vector<std::uint8_t> touch;
  std::vector<std::uint16_t> mapped, visible;
  std::vector<double> power, area;
  std::vector<float> element_power;
  LineElementTally tally;

  Reference(const SlarElementContext& c, const RandomLine& l)
      : touch(static_cast<std::size_t>(c.bins)),
        mapped(touch.size()),
        visible(touch.size()),
        power(touch.size()),
        area(touch.size()),
        element_power(static_cast<std::size_t>(l.n)) {
    const int bins = c.bins;
    for (std::size_t j = 0; j < element_power.size(); ++j) {
      const std::uint8_t f = l.flags[j];
      tally.nodata += (f & sample_flag::kNoData) ? 1 : 0;
      tally.shadow += (f & sample_flag::kShadow) ? 1 : 0;
      tally.back_facing += (f & sample_flag::kBackFacing) ? 1 : 0;
      tally.layover += (f & sample_flag::kLayover) ? 1 : 0;
      if (f & (sample_flag::kNoData | sample_flag::kUnseen)) continue;
      const bool vis = sample_visible(f);
      tally.r_min_m = std::min(tally.r_min_m, l.range[j]);
      tally.r_max_m = std::max(tally.r_max_m, l.range[j]);
      const double pos = (double(l.range[j]) - c.near_m) * c.inv_dr;
      if (pos >= 0.0 && pos < bins) {
        const auto k = static_cast<std::size_t>(pos);
        ++mapped[k];
        if (vis) ++visible[k];
        ++tally.in_swath;
      }
      const double p =
          radar_power_w(c.k_radar, c.gain2->at(l.incidence[j]),
                        c.lut->at(l.category[j], l.local_incidence[j]), l.area[j], l.range[j]);
      if (vis) element_power[j] = static_cast<float>(p);
      const double xa = (double(l.near_end[j]) - c.near_m) * c.inv_dr;
      const double xb = (double(l.far_end[j]) - c.near_m) * c.inv_dr;
      const double lo = std::min({xa, xb, pos}), hi = std::max({xa, xb, pos});
      if (hi < 0.0 || lo >= bins) continue;
      std::uint8_t bits = slar_touch::kData;
      if (vis) bits |= slar_touch::kVisible;
      if (vis && (f & sample_flag::kLayover)) bits |= slar_touch::kLayover;
      for (int b = first_bin(lo); b <= last_bin(hi, bins); ++b) {
        touch[static_cast<std::size_t>(b)] |= bits;
      }
      if (!vis) continue;
      spread(power.data(), area.data(), xa, pos, 0.5 * p, 0.5 * l.area[j], bins);
      spread(power.data(), area.data(), pos, xb, 0.5 * p, 0.5 * l.area[j], bins);
    }
  }
};

double gaussian_gain(double beta) {
  return std::exp(-std::pow((beta - 1.1) / 0.4, 2));
}

// A 40-bin profile with bins 1 m wide from range 0, categories 1-3 with the
// cosine law, and an elevation pattern (gaussian_gain) or none.
struct ProfileSetup {
  static constexpr int kBins = 40;
  static constexpr std::array<std::uint16_t, 3> kCategories = {1, 2, 3};
  SlarImagingParams p;
  Sigma0Lut lut;
  TwoWayGainTable gain2;
  SlarElementContext ctx;
  explicit ProfileSetup(bool pattern)
      : p(params(pattern)),
        lut(Sigma0Lut::build(test::CosineSigma0Source(), {}, kCategories, "test")),
        gain2(p.elevation_gain, p.peak_gain, "test"),
        ctx(element_context(p, gain2, lut, kBins)) {}
  static SlarImagingParams params(bool pattern) {
    SlarImagingParams q;
    q.range = {0.0, 1.0, kBins};
    q.transmit_power_w = 1000.0;
    q.wavelength_m = 0.03;
    if (pattern) {
      q.peak_gain = 300.0;
      q.elevation_gain = gaussian_gain;
    }
    return q;
  }
};

// One random line of n elements under a ProfileSetup, with its scratch.
struct LineCase {
  ProfileSetup setup;
  RandomLine line;
  LineElementScratch scratch;
  LineCase(bool pattern, int n, std::uint32_t seed)
      : setup(pattern), line(n, seed), scratch(n, ProfileSetup::kBins) {}
};

// Bin coordinates are the ranges themselves (near 0, 1 m bins), so single
// and double precision put every element in the same bins: touch bits and
// counts must agree exactly, powers to float rounding.
TEST(SlarElement, LineProfileMatchesElementByElementReference) {
  const ProfileSetup setup(true);
  const int bins = ProfileSetup::kBins;
  const SlarElementContext& ctx = setup.ctx;
  ASSERT_EQ(ctx.inv_dr, 1.0);

  const int n = 203;  // not a multiple of the 8-element blocks
  LineElementScratch scratch(n, bins);
  int general = 0;
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {  // scratch reused line after line
    const RandomLine line(n, seed);
    const Reference ref(ctx, line);
    ProfileOut out(bins, -1.0);
    std::vector<float> element_power(static_cast<std::size_t>(n), -1.0f);
    const LineElementTally t =
        form_line_profile(ctx, line.elements(), scratch, out.row(), element_power.data());
    const auto& [touch, mapped, visible, power, area] = out;
    general += scratch.n_general;
    EXPECT_EQ(t.in_swath, ref.tally.in_swath);
    EXPECT_EQ(t.nodata, ref.tally.nodata);
    EXPECT_EQ(t.shadow, ref.tally.shadow);
    EXPECT_EQ(t.back_facing, ref.tally.back_facing);
    EXPECT_EQ(t.layover, ref.tally.layover);
    EXPECT_EQ(t.r_min_m, ref.tally.r_min_m);
    EXPECT_EQ(t.r_max_m, ref.tally.r_max_m);
    // The element power in single precision (element_power_ratio: the
    // float gain table, five roundings) against the double reference: a few
    // float ulps (measured <= 7.3e-7 relative); 0 exactly where not visible.
    for (std::size_t j = 0; j < element_power.size(); ++j) {
      const float r = ref.element_power[j];
      if (r == 0.0f) {
        EXPECT_EQ(element_power[j], 0.0f) << "seed " << seed << " element " << j;
      } else {
        EXPECT_NEAR(element_power[j] / r, 1.0f, 2e-6f) << "seed " << seed << " element " << j;
      }
    }
    EXPECT_EQ(touch, ref.touch) << "seed " << seed;
    EXPECT_EQ(mapped, ref.mapped) << "seed " << seed;
    EXPECT_EQ(visible, ref.visible) << "seed " << seed;
    const double p_max = *std::max_element(ref.power.begin(), ref.power.end());
    const double a_max = *std::max_element(ref.area.begin(), ref.area.end());
    ASSERT_GT(p_max, 0.0);
    for (std::size_t b = 0; b < power.size(); ++b) {
      // The fractions in float: ~1e-7 of an element's power.
      EXPECT_NEAR(power[b], ref.power[b], 1e-6 * p_max) << "seed " << seed << " bin " << b;
      EXPECT_NEAR(area[b], ref.area[b], 1e-6 * a_max) << "seed " << seed << " bin " << b;
    }
  }
  EXPECT_GT(general, 20);  // the spread() path ran too
}

// A span of a line (the oblique fused path clips lines to the scene) sums
// as the whole line with the samples outside it unseen (the stage path):
// the same bytes.
TEST(SlarElement, SpanOfALineGivesTheWholeLinesBytes) {
  LineCase c(true, 203, 11);
  const int bins = ProfileSetup::kBins;
  const SlarElementContext& ctx = c.setup.ctx;
  const RandomLine& line = c.line;
  LineElementScratch& scratch = c.scratch;
  for (const int begin : {1, 2, 3, 6}) {
    const int end = line.n - begin;
    RandomLine whole = line;
    for (int j = 0; j < whole.n; ++j) {
      if (j < begin || j >= end) whole.flags[static_cast<std::size_t>(j)] |= sample_flag::kUnseen;
    }
    ProfileOut w(bins), sp(bins);
    const LineElementTally tw = form_line_profile(ctx, whole.elements(), scratch, w.row(), nullptr);
    LineElements span = line.elements();
    const auto shift = static_cast<std::size_t>(begin);
    span.samples = end - begin;
    span.flags += shift;
    span.slant_range_m += shift;
    span.near_end_m += shift;
    span.far_end_m += shift;
    span.incidence_rad += shift;
    span.local_incidence_rad += shift;
    span.area_m2 += shift;
    span.category += shift;
    span.first_index = begin;
    const LineElementTally ts = form_line_profile(ctx, span, scratch, sp.row(), nullptr);
    EXPECT_EQ(ts.in_swath, tw.in_swath);
    EXPECT_EQ(sp.power, w.power) << "begin " << begin;
    EXPECT_EQ(sp.area, w.area) << "begin " << begin;
    EXPECT_EQ(sp.touch, w.touch);
    EXPECT_EQ(sp.mapped, w.mapped);
    EXPECT_EQ(sp.visible, w.visible);
  }
}

// A uniform elevation pattern reads no look angle (the fused path leaves it
// unset): NaN there changes nothing.
TEST(SlarElement, UniformGainIgnoresTheLookAngle) {
  LineCase c(false, 100, 3);
  ProfileOut out(ProfileSetup::kBins);
  form_line_profile(c.setup.ctx, c.line.elements(), c.scratch, out.row(), nullptr);
  const std::vector<double> expected = out.power;
  std::fill(c.line.incidence.begin(), c.line.incidence.end(),
            std::numeric_limits<float>::quiet_NaN());
  form_line_profile(c.setup.ctx, c.line.elements(), c.scratch, out.row(), nullptr);
  EXPECT_EQ(out.power, expected);
  EXPECT_GT(*std::max_element(out.power.begin(), out.power.end()), 0.0);
}

}  // namespace
}  // namespace ris::detail
