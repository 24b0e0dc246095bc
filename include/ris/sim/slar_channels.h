// The channel axis: several channels (each a radar, so a frequency,
// polarisation, power or gain of its own, and a backscatter source) imaged
// over one geometry in one pass of the line engine. Each line's look
// geometry, shadow and layover are computed once; each channel forms its own
// range profile from them (radar equation, gain, sigma0 look-up) and its own
// image (azimuth integration, switch corrections, SAR noise). Each channel's
// simulation is the one simulate_slar gives for that channel alone, byte for
// byte (tested: slar_channels_test.cpp); the geometry is paid once
// (`ris bench` prints the cost of 4 channels against 1).
//
// The channels must share the geometry: the same track (altitude, heading,
// position, look side), azimuth line spacing and range bins (near range, bin
// length and count: the same sweep delay, pulse and sampling), mode SLAR or
// incoherent SAR. Point targets and the coherent SAR are single-channel for
// now (InputError). ris study runs its bands this way (issue 31).
//
// Example:
//   std::vector<ris::SlarChannel> ch{{radar_x, lib.get(), ""}, {radar_c, lib.get(), ""}};
//   std::vector<ris::SlarSimulation> sims = ris::simulate_slar_channels(scene, ch, {});
#pragma once

#include <span>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

struct SlarChannel {
  RadarParams radar;
  const Sigma0Source* sigma0 = nullptr;
  // Names the backscatter source in messages; empty: SlarOptions'.
  std::string backscatter_file;
};

// One simulation per channel, in the channels' order. options apply to the
// run (progress, reference height) and to the first channel (keep_geometry,
// targets); the other channels keep no per-sample geometry. Throws
// InputError naming the channel's radar file and key for a channel whose
// geometry differs from the first's, and everything simulate_slar refuses.
std::vector<SlarSimulation> simulate_slar_channels(const Scene& scene,
                                                   std::span<const SlarChannel> channels,
                                                   const SlarOptions& options = {});

}  // namespace ris
