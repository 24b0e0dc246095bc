// A quad-polarised SLC set (HH, HV, VH, VV on one grid) and the covariance
// images made from it: single-look C3, boxcar averaging, multilooking, C3 to
// T3 (docs/polarimetry.md).
//
// Inputs:
//   four GeoTIFFs (or any GDAL raster) with one complex band each, in the
//   order HH, HV, VH, VV: same size and, when georeferenced, the same
//   geotransform (otherwise refused naming both files);
//   a NISAR / UAVSAR RSLC HDF5 product: the four layers
//   science/<band>/{SLC,RSLC}/swaths/frequency<F>/{HH,HV,VH,VV} (a missing
//   layer is refused naming the ones the file holds).
//
// Example:
//   ris::QuadPolSlc s = ris::read_quad_pol_rasters({"hh.tif", "hv.tif", "vh.tif", "vv.tif"});
//   ris::CovarianceImage c3 = ris::boxcar_average(ris::single_look_c3(s), 7, 7);
//   ris::CovarianceImage t3 = ris::to_t3(c3);
#pragma once

#include <array>
#include <complex>
#include <string>
#include <vector>

#include "ris/backscatter/polarimetric_matrix.h"
#include "ris/io/raster_io.h"

namespace ris {

struct QuadPolSlc {
  int cols = 0, rows = 0;
  std::vector<std::complex<float>> hh, hv, vh, vv;  // rows x cols each
  std::array<std::string, 4> sources;               // HH, HV, VH, VV as opened
  Georef georef;
  bool has_geotransform = false;
  std::string format;  // "rasters" or "nisar-rslc"
};

QuadPolSlc read_quad_pol_rasters(const std::array<std::string, 4>& paths);
// frequency: "A" or "B" (the product's frequencyA / frequencyB).
QuadPolSlc read_quad_pol_nisar(const std::string& path, const std::string& frequency = "A");

// One Hermitian 3 x 3 matrix per pixel (C3 or T3), rows x cols.
struct CovarianceImage {
  int cols = 0, rows = 0;
  std::vector<Hermitian3> m;
  bool is_t3 = false;
};

// k_L k_L^H per pixel (HV as (HV + VH) / 2).
CovarianceImage single_look_c3(const QuadPolSlc& s);
// The mean over a window_rows x window_cols box centred on each pixel (both
// odd), the box cut at the image's edges (the mean of the pixels inside):
// PolSARpro's and OTB's speckle averaging before a decomposition. Separable
// sums in double (rows, then columns).
CovarianceImage boxcar_average(const CovarianceImage& c, int window_rows, int window_cols);
// Multilooking: the mean of each looks_rows x looks_cols block, the output
// (rows / looks_rows) x (cols / looks_cols) (a partial last block dropped).
CovarianceImage multilook(const CovarianceImage& c, int looks_rows, int looks_cols);
CovarianceImage to_t3(const CovarianceImage& c3);
CovarianceImage to_c3(const CovarianceImage& t3);

}  // namespace ris
