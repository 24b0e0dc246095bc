// An acquisition: the orbit, the radar grid and the Earth model of a real (or
// planned) radar product, read from the product's own metadata so that
// geometry computed by ris lines up with its image pixel for pixel.
//
// Readers (one file each, src/sensor/acquisition_*.cpp):
// - NISAR / UAVSAR RSLC HDF5 (science/LSAR/{SLC,RSLC}/...), through GDAL's
//   multidimensional API (acquisition_nisar.cpp);
// - Sentinel-1 SAFE (a .SAFE folder or one annotation XML), the whole
//   sub-swath on a debursted grid or one burst (acquisition_sentinel1.cpp);
// - ris's own TOML: state vectors, or a generated circular orbit or
//   constant-height flight line, plus the grid (acquisition_toml.cpp,
//   docs/geometry.md, data/acquisitions/).
// Sentinel-1 GRD annotations (ground-range pixels) are refused naming
// adsHeader.productType. Every value the product readers take is checked
// finite and in a physical range, and HDF5 dataset sizes before they are
// read (ris/sensor/product_values.h, docs/limits.md); an acquisition path
// that is a FIFO or device is refused before it is opened.
// Doppler is zero (zero-Doppler grids: NISAR, Sentinel-1 SLC, ISCE3's
// default); a product that declares otherwise is read as zero-Doppler and
// says so in `notes`.
//
// Example:
//   ris::Acquisition acq = ris::read_acquisition("winnipeg.h5");
//   double t_s = acq.grid.time_of_line(10.0);
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "ris/sensor/orbit.h"
#include "ris/sensor/radar_grid.h"
#include "ris/util/ellipsoid.h"

namespace ris {

struct Acquisition {
  std::string source;   // the path read
  std::string format;   // "nisar-rslc", "sentinel-1-safe", "ris-toml"
  std::string mission;  // "UAVSAR", "S1A", ...
  std::string polarisation;
  Orbit orbit;
  RadarGrid grid;
  Ellipsoid ellipsoid = Ellipsoid::wgs84();
  std::vector<std::string> notes;  // what the reader assumed or chose
};

struct AcquisitionOptions {
  // NISAR: "A" or "B" (default A). Ignored by the other readers.
  std::string frequency = "A";
  // Sentinel-1 IW/EW: one burst (0-based) instead of the whole sub-swath.
  std::optional<int> burst;
  // Sentinel-1 SAFE folder: the annotation to read ("iw1-slc-vv", or any
  // part of its file name); required only when the folder holds several.
  std::string swath;
};

// Picks the reader from the path: *.h5 / *.hdf5 -> NISAR, *.SAFE or *.xml ->
// Sentinel-1, *.toml -> ris TOML. Throws InputError naming the file and key.
Acquisition read_acquisition(const std::filesystem::path& path,
                             const AcquisitionOptions& options = {});

Acquisition read_nisar_rslc(const std::filesystem::path& path, const AcquisitionOptions& options);
Acquisition read_sentinel1(const std::filesystem::path& path, const AcquisitionOptions& options);
Acquisition read_acquisition_toml(const std::filesystem::path& path);

}  // namespace ris
