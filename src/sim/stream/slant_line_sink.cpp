#include "sim/stream/slant_line_sink.h"

#include <utility>

#include "ris/image/speckle.h"
#include "ris/util/error.h"

namespace ris::detail {

SlantLineSink::SlantLineSink(SlarSimulation& sim, const RadiometrySetup& rs,
                             SlantImageWriters writers, std::vector<double> looks,
                             std::uint64_t seed, FloatRankSelect& power, StreamTargets* targets,
                             CoherentStream* coherent)
    : sim_(sim),
      rs_(rs),
      out_(std::move(writers)),
      looks_(std::move(looks)),
      seed_(seed),
      power_(power),
      targets_(targets),
      coherent_(coherent),
      az_(rs.imaging, sim.geometry.line_spacing_m, sim.image.lines, sim.image.bins) {}

void SlantLineSink::take(StreamLineBlock& k) {
  counts_.add(k.counts);
  if (targets_) targets_->add(k.targets);
  if (coherent_) coherent_->add(std::move(k.coherent));
  samples_in_swath_ += k.prof.samples_in_swath;
  az_.push(k.prof, k.l1 - k.l0);
  emit_ready();
}

// The image lines the integrator has ready: switch corrections and noise
// (finish_slar_image), NaN for no data, fading, written out (render_slar
// + write_slar_products).
void SlantLineSink::emit_ready() {
  const int n = az_.lines_ready();
  if (n == 0) return;
  const int k0 = az_.lines_emitted();
  const int bins = sim_.image.bins;
  const std::size_t np = std::size_t(n) * std::size_t(bins);
  const SlarImage block = emit_finished_lines(az_, n, sim_, rs_.terms, mask_);
  // The point targets' measurement windows (of the mean power before NaN
  // for no data, as measure_point_targets reads it).
  if (targets_ && !coherent_) targets_->observe(k0, n, block.mean_power_w.data());
  count_and_blank_no_data(block, mask_, power_, mean_);
  if (coherent_) {  // the coherent intensity stands in for the faded mean
    speckled_.resize(np);
    coherent_->finish_lines(n, mask_.data(), block.area_m2.data(), speckled_.data());
  } else {
    speckled_ = mean_;
    const RadarParams& r = sim_.radar;
    if (r.switches.fading) apply_fading(speckled_, n, bins, looks_, r.fading, seed_, k0);
  }
  if (targets_ && coherent_) targets_->observe(k0, n, speckled_.data());  // the intensity
  out_.mean->write(mean_.data(), n);
  out_.speckled->write(speckled_.data(), n);
  out_.mask->write(mask_.data(), n);
}

void SlantLineSink::close() {
  RIS_CHECK(az_.lines_emitted() == sim_.image.lines);
  out_.mean->close();
  out_.speckled->close();
  out_.mask->close();
}

}  // namespace ris::detail
