// Command-line options shared by the commands that read an acquisition
// (geo2rdr, rdr2geo, topo, simulate): the product and which part of it.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "ris/sensor/acquisition.h"

namespace ris::app {

struct AcquisitionArgs {
  std::string path;
  std::string frequency = "A";
  int burst = -1;
  std::string swath;

  AcquisitionOptions options() const {
    AcquisitionOptions o;
    o.frequency = frequency;
    if (burst >= 0) o.burst = burst;
    o.swath = swath;
    return o;
  }
};

// required = false: the command runs without an acquisition too (simulate).
inline void add_acquisition_options(CLI::App* cmd, AcquisitionArgs& a, bool required = true) {
  auto* opt = cmd->add_option("--acquisition,-a", a.path,
                              "Radar product: NISAR RSLC .h5, Sentinel-1 .SAFE (or annotation "
                              ".xml), or a ris acquisition .toml");
  if (required) opt->required();
  cmd->add_option("--frequency", a.frequency, "NISAR frequency band: A or B")
      ->capture_default_str();
  cmd->add_option("--burst", a.burst,
                  "Sentinel-1 TOPS: one burst (0-based) instead of the debursted sub-swath");
  cmd->add_option("--swath", a.swath,
                  "Sentinel-1 .SAFE: part of the annotation's name (e.g. iw2-slc-vv)");
}

}  // namespace ris::app
