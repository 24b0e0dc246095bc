// The products of `ris polsar` (ris/image/polsar/polsar_products.h).
#include "ris/image/polsar/polsar_products.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ris/image/polsar/decompositions.h"
#include "ris/io/atomic_file.h"
#include "ris/io/raster_io.h"

namespace ris {

namespace {

constexpr double kRadToDeg = 57.295779513082320877;

// The nine real bands of a Hermitian image, PolSARpro's order and names.
void write_matrix_bands(const CovarianceImage& c, char letter, const std::filesystem::path& path,
                        const Georef* georef) {
  const std::size_t n = c.m.size();
  struct Element {
    int r, c;
    bool imag;
  };
  const std::array<Element, 9> kElements = {{{0, 0, false},
                                             {0, 1, false},
                                             {0, 1, true},
                                             {0, 2, false},
                                             {0, 2, true},
                                             {1, 1, false},
                                             {1, 2, false},
                                             {1, 2, true},
                                             {2, 2, false}}};
  std::vector<std::vector<float>> data(9, std::vector<float>(n));
  std::vector<BandView<float>> bands;
  for (std::size_t b = 0; b < 9; ++b) {
    const Element e = kElements[b];
    for (std::size_t i = 0; i < n; ++i) {
      const Complex v = c.m[i](e.r, e.c);
      data[b][i] = static_cast<float>(e.imag ? v.imag() : v.real());
    }
    std::string name = fmt::format("{}{}{}", letter, e.r + 1, e.c + 1);
    if (e.r != e.c) name += e.imag ? "_imag" : "_real";
    bands.push_back({data[b].data(), name});
  }
  write_geotiff_bands<float>(path, bands, c.cols, c.rows, georef);
}

struct Range {
  double min = INFINITY, max = -INFINITY, sum = 0.0;
  std::size_t n = 0;
  void add(double v) {
    if (!std::isfinite(v)) return;
    min = std::min(min, v);
    max = std::max(max, v);
    sum += v;
    ++n;
  }
  nlohmann::json json() const {
    if (n == 0) return nullptr;
    return {{"min", min}, {"max", max}, {"mean", sum / static_cast<double>(n)}};
  }
};

}  // namespace

nlohmann::json write_polsar_products(const QuadPolSlc& s, const PolsarWindow& window,
                                     const std::filesystem::path& out_dir) {
  const CovarianceImage c3 = boxcar_average(single_look_c3(s), window.rows, window.cols);
  const CovarianceImage t3 = to_t3(c3);
  const std::vector<CloudePottier> hal = cloude_pottier_image(t3);
  const std::vector<FreemanDurden> fd = freeman_durden_image(c3);
  const Georef* georef = s.has_geotransform ? &s.georef : nullptr;
  const std::size_t n = c3.m.size();

  StagedDirectory dir(out_dir);
  write_matrix_bands(c3, 'C', dir.path("c3.tif"), georef);
  write_matrix_bands(t3, 'T', dir.path("t3.tif"), georef);
  std::vector<float> h(n), a(n), alpha(n), odd(n), dbl(n), vol(n);
  Range hr, ar, alr, oddr, dblr, volr;
  for (std::size_t i = 0; i < n; ++i) {
    h[i] = static_cast<float>(hal[i].entropy);
    a[i] = static_cast<float>(hal[i].anisotropy);
    alpha[i] = static_cast<float>(hal[i].alpha_rad * kRadToDeg);
    odd[i] = static_cast<float>(fd[i].surface);
    dbl[i] = static_cast<float>(fd[i].double_bounce);
    vol[i] = static_cast<float>(fd[i].volume);
    hr.add(h[i]);
    ar.add(a[i]);
    alr.add(alpha[i]);
    oddr.add(odd[i]);
    dblr.add(dbl[i]);
    volr.add(vol[i]);
  }
  write_geotiff_bands<float>(
      dir.path("h_a_alpha.tif"),
      {{h.data(), "entropy"}, {a.data(), "anisotropy"}, {alpha.data(), "alpha_deg"}}, s.cols,
      s.rows, georef);
  write_geotiff_bands<float>(
      dir.path("freeman_durden.tif"),
      {{odd.data(), "Freeman_Odd"}, {dbl.data(), "Freeman_Dbl"}, {vol.data(), "Freeman_Vol"}},
      s.cols, s.rows, georef);
  const std::vector<std::uint8_t> rgb = pauli_rgb(t3);
  write_png_rgb(dir.path("pauli.png"), rgb.data(), s.cols, s.rows);

  nlohmann::json j;
  j["inputs"] = {{"format", s.format},
                 {"HH", s.sources[0]},
                 {"HV", s.sources[1]},
                 {"VH", s.sources[2]},
                 {"VV", s.sources[3]}};
  j["size"] = {{"cols", s.cols}, {"rows", s.rows}};
  j["window"] = {{"rows", window.rows}, {"cols", window.cols}};
  j["conventions"] = {
      {"basis", "k_L = [HH, sqrt2 HV, VV]; k_P = [HH+VV, HH-VV, 2 HV] / sqrt2; HV = (HV+VH)/2"},
      {"averaging", "boxcar mean over the window, cut at the image edges"},
      {"alpha", "degrees, mean alpha sum p_i acos|e_i[0]| (Cloude & Pottier 1997)"},
      {"entropy", "log base 3"},
      {"freeman_durden",
       "Freeman & Durden 1998 with PolSARpro's branch on Re C13 and clipping to the span range"},
      {"pauli_png", "red sqrt T22, green sqrt T33, blue sqrt T11, dB, 2-98 % stretch per colour"}};
  j["products"] = {"c3.tif",    "t3.tif",       "h_a_alpha.tif", "freeman_durden.tif",
                   "pauli.png", "metadata.json"};
  j["statistics"] = {{"entropy", hr.json()},       {"anisotropy", ar.json()},
                     {"alpha_deg", alr.json()},    {"freeman_odd", oddr.json()},
                     {"freeman_dbl", dblr.json()}, {"freeman_vol", volr.json()}};
  write_text_file_atomic(dir.path("metadata.json"), j.dump(1) + "\n");
  dir.commit();
  return j;
}

}  // namespace ris
