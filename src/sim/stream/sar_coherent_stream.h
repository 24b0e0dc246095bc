// Internal: the coherent SAR (ris/sim/sar_coherent.h) in a streamed run
// (ris/sim/slar_stream.h), with the in-memory run's bytes.
//
// Its image sums scatterers windowed by the compressed impulse response: a
// pixel of line k takes the range-compressed lines k - S .. k + S (S: the
// azimuth kernel's half-length, CoherentResponse::support_a) and the point
// targets whose response reaches it (their lines within S + 1 of k). So a
// block of lines [l0, l1) is computed over its lines plus a halo of
// halo_lines() = S + 2 lines each side (clipped to the image), read from
// the scene and run through the line engine like its own lines (along a
// grid axis over the block's window, off the axes by
// src/sim/stream/slar_stream_oblique.h: the caller's RunLines), keeping each
// element's power and slant range (LineKeep with line0: the block's
// arrays). Its own lines' profiles, counts, scene maps (or per-sample map
// values off the axes) and targets go on as in the incoherent stream; the
// halo's are dropped (the neighbouring blocks own them). Then per look, as coherent_sar_intensity
// does and with the same code (src/sim/modes/sar_coherent_parts.h): range compression of every line
// read, azimuth compression and thermal noise of its own lines, the lit point targets in target
// order, and the looks' mean intensity (double) of its own lines: the block's result (8 bytes a
// line x bin, sent to rank 0 under MPI).
//
// Rank 0 keeps the blocks' intensities in line order (add) and, as the
// azimuth integrator emits the mean image's lines (their mask and area),
// applies the range and area switches and NaN for no data
// (finish_lines): the speckled power of the products. Every random number
// is keyed by (seed, sample or bin, line, look), so the bytes do not depend
// on the block length, the threads or the ranks (tested).
#pragma once

#include <complex>
#include <cstdint>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

#include "ris/image/greytone_terms.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/sim/slar_simulation.h"
#include "sim/modes/sar_coherent_parts.h"
#include "sim/stream/slar_stream_targets.h"

namespace ris::detail {

// A block's own lines' intensity (the looks' mean, before the switches),
// lines x bins.
struct CoherentBlock {
  std::vector<double> intensity;
};
void pack_coherent_block(const CoherentBlock& b, std::vector<char>& out);
CoherentBlock unpack_coherent_block(const char*& p, const char* end);

class CoherentStream {
 public:
  // sim: the run's radar, layout (geometry), image layout and noise (after
  // complete_slar_setup).
  CoherentStream(const SlarSimulation& sim, std::uint64_t seed);

  int halo_lines() const { return h_.support_a + 2; }
  // The lines a block of lines [l0, l1) reads and runs: with its halo.
  std::pair<int, int> lines_read(int l0, int l1) const;

  // Runs lines [a, b) through the line engine into prof's rows (prof:
  // the lines read, allocated), counts into counts, with keep (the block's
  // element power, slant range and targets). own: the block's own lines,
  // whose scene maps are kept (the halo's are dropped: the neighbouring
  // blocks own them). Along a grid axis SlarLineEngine::run over the
  // block's window, off the axes ObliqueBlockLines::run.
  using RunLines = std::function<void(int a, int b, bool own, SlarLineProfiles& prof,
                                      SlarLineCounts& counts, const LineKeep& keep)>;

  // Block [l0, l1) on this rank: run over lines_read (its own lines and the
  // halo, each a call), its own lines' profiles into prof (allocated here)
  // and counts into counts; targets (optional): its own lines' targets into
  // bt; its intensity into out.
  void run_block(const RunLines& run, int l0, int l1, const StreamTargets* targets,
                 SlarLineProfiles& prof, SlarLineCounts& counts, BlockTargets& bt,
                 CoherentBlock& out);

  // Rank 0, blocks in line order: their intensities kept until finished.
  void add(CoherentBlock&& b);
  // Rank 0: the next n lines (in order from line 0), with the mean image's
  // mask and area of those lines: the coherent intensity (W, NaN for no
  // data), n x bins into out.
  void finish_lines(int n, const std::uint8_t* mask, const float* area_m2, float* out);

 private:
  // Per look: range and azimuth compression, targets, the looks' mean.
  void compress(int l0, int l1, int h0, int h1, const LinePointTargets* on_lines,
                CoherentBlock& out);

  const SlarSimulation& sim_;
  std::uint64_t seed_;
  CoherentResponse h_;
  SwitchedRadarTerms terms_;
  int lines_, bins_, samples_, looks_;
  // A block's buffers (reused): the lines read's element power, slant
  // range, profiles and range-compressed lines; its own lines' z.
  std::vector<float> element_power_, slant_range_;
  SlarLineProfiles read_prof_;
  std::vector<std::complex<float>> range_lines_, z_;
  // Rank 0: intensities of lines [next_, next_ + pending_.size() / bins).
  std::vector<double> pending_;
  std::size_t pending_at_ = 0;  // the first unfinished value in pending_
};

}  // namespace ris::detail
