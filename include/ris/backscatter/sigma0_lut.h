// sigma0 tabulated against local incidence for the categories of one run.
//
// Built once from a Sigma0Source for one band; lookups are branch-light,
// allocation-free and inline, for the per-sample hot loop. Samples are spaced
// kStepRad (0.05 deg) apart from 0 to 90 deg and interpolated linearly: the
// error is h^2 f'' / 8, at most 1.3e-4 relative for the shipped libraries'
// models between 1 and 85 deg (tested below 1e-3), and building the table
// (one model evaluation per angle and category, a fixed cost of every run)
// is 5 times cheaper than at 0.01 deg.
//
// Example:
//   ris::Sigma0Lut lut = ris::Sigma0Lut::build(source, band, scene_categories, "crops.toml");
//   float s0 = lut.at(category, incidence_rad);
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/util/units.h"

namespace ris {

class Sigma0Lut {
 public:
  static constexpr int kSteps = 1800;  // intervals over [0, pi/2]: 0.05 deg
  static constexpr double kStepRad = (kPi / 2.0) / kSteps;

  Sigma0Lut() = default;

  // Tabulates every category in `categories` (duplicates allowed). A category
  // the source lacks is an InputError naming source_name and the category.
  static Sigma0Lut build(const Sigma0Source& source, const RadarBand& band,
                         std::span<const std::uint16_t> categories, const std::string& source_name);

  // Whether the category was tabulated.
  bool has(std::uint16_t category) const {
    return category < offset_.size() && offset_[category] >= 0;
  }

  // sigma0 (linear) at local incidence incidence_rad; angles beyond [0, pi/2]
  // are clamped. The category must have been tabulated (has() true).
  float at(std::uint16_t category, float incidence_rad) const {
    return interpolate(table_.data(), offset_[category], incidence_rad);
  }

  // at() on the raw table, for loops that look up many elements: the
  // category's curve starts at data() + offsets()[category] (kSteps + 1
  // samples). 32-bit offsets and selects rather than std::clamp, so that
  // GCC vectorises such a loop (gathers by 32-bit index).
  const float* data() const { return table_.data(); }
  std::size_t size() const { return table_.size(); }  // values in data()
  const std::int32_t* offsets() const { return offset_.data(); }
  static constexpr float kInvStep = static_cast<float>(1.0 / kStepRad);
  static float interpolate(const float* table, std::int32_t offset, float incidence_rad) {
    float pos = incidence_rad * kInvStep;
    pos = pos < 0.0f ? 0.0f : pos;
    pos = pos > static_cast<float>(kSteps) ? static_cast<float>(kSteps) : pos;
    int i = static_cast<int>(pos);
    i = i < kSteps - 1 ? i : kSteps - 1;
    const float f = pos - static_cast<float>(i);
    const std::int32_t k = offset + i;
    return table[k] + f * (table[k + 1] - table[k]);
  }

  // A tabulated category (the first), for lookups whose result is discarded
  // (a vectorised loop's lanes of elements that are not visible); 0 when
  // none is tabulated (then nothing may be looked up).
  std::uint16_t any_category() const { return any_category_; }
  bool empty() const { return table_.empty(); }

 private:
  std::vector<float> table_;  // (kSteps + 1) samples per tabulated category
  // By category id; -1 when absent. At most 65536 x 1801 samples: 32 bits.
  std::vector<std::int32_t> offset_;
  std::uint16_t any_category_ = 0;
};

}  // namespace ris
