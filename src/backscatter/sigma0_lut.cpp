#include "ris/backscatter/sigma0_lut.h"

#include <fmt/format.h>

#include <cmath>
#include <exception>
#include <vector>

#include "ris/scene/scene.h"
#include "ris/util/error.h"

namespace ris {

Sigma0Lut Sigma0Lut::build(const Sigma0Source& source, const RadarBand& band,
                           std::span<const std::uint16_t> categories,
                           const std::string& source_name) {
  Sigma0Lut lut;
  std::uint16_t max_category = 0;
  for (std::uint16_t c : categories) {
    if (c != kNoDataCategory) max_category = std::max(max_category, c);
  }
  lut.offset_.assign(static_cast<size_t>(max_category) + 1, -1);
  std::vector<std::uint16_t> order;  // tabulated categories, in first-seen order
  for (std::uint16_t c : categories) {
    if (c == kNoDataCategory || lut.offset_[c] >= 0) continue;
    if (!source.has_category(c)) {
      throw InputError(source_name, "",
                       fmt::format("no backscatter for category {} (the scene uses it; add it to "
                                   "the backscatter file)",
                                   c));
    }
    if (order.empty()) lut.any_category_ = c;
    lut.offset_[c] = static_cast<std::int32_t>(order.size()) * (kSteps + 1);
    order.push_back(c);
    // The first evaluation, here in category order, is where a model checks
    // the band (an InputError is thrown from this thread, as before).
    (void)source.sigma0(c, 0.0, band);
  }
  // The samples in parallel, in blocks of angles of one category (the models
  // are const and thread-safe; a large scene's categories cost ~1 ms each on
  // one thread), then checked in order.
  constexpr int kBlock = 512;
  const int blocks_per_category = (kSteps + 1 + kBlock - 1) / kBlock;
  const int n_blocks = static_cast<int>(order.size()) * blocks_per_category;
  std::vector<double> s0(order.size() * (kSteps + 1));
  std::exception_ptr error;
#pragma omp parallel for schedule(dynamic)
  for (int b = 0; b < n_blocks; ++b) {
    const std::size_t ci = static_cast<std::size_t>(b / blocks_per_category);
    const int i0 = (b % blocks_per_category) * kBlock;
    const int i1 = std::min(kSteps + 1, i0 + kBlock);
    double theta[kBlock];
    for (int i = i0; i < i1; ++i) theta[i - i0] = std::min(i * kStepRad, kPi / 2.0);
    try {
      source.sigma0_curve(order[ci], theta, static_cast<std::size_t>(i1 - i0), band,
                          s0.data() + ci * (kSteps + 1) + static_cast<std::size_t>(i0));
    } catch (...) {
#pragma omp critical(ris_sigma0_lut_error)
      if (!error) error = std::current_exception();
    }
  }
  if (error) std::rethrow_exception(error);
  lut.table_.resize(s0.size());
  for (std::size_t k = 0; k < s0.size(); ++k) {
    if (!std::isfinite(s0[k]) || s0[k] < 0.0) {
      const std::uint16_t c = order[k / (kSteps + 1)];
      const double theta = std::min(static_cast<int>(k % (kSteps + 1)) * kStepRad, kPi / 2.0);
      throw InputError(source_name, "",
                       fmt::format("category {} gives sigma0 = {} at {:.2f} deg; expected a "
                                   "finite value >= 0",
                                   c, s0[k], rad_to_deg(theta)));
    }
    lut.table_[k] = static_cast<float>(s0[k]);
  }
  return lut;
}

}  // namespace ris
