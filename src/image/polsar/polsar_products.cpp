// The products of `ris polsar` (ris/image/polsar/polsar_products.h).
#include "ris/image/polsar/polsar_products.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "ris/image/polsar/decompositions.h"
#include "ris/image/polsar/pol_synthesis.h"
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

// C11, C12 and C22 of a two-channel covariance (top-left 2 x 2).
void write_c2_bands(const CovarianceImage& c, const std::filesystem::path& path,
                    const Georef* georef) {
  const std::size_t n = c.m.size();
  std::vector<std::vector<float>> d(4, std::vector<float>(n));
  for (std::size_t i = 0; i < n; ++i) {
    d[0][i] = static_cast<float>(c.m[i](0, 0).real());
    d[1][i] = static_cast<float>(c.m[i](0, 1).real());
    d[2][i] = static_cast<float>(c.m[i](0, 1).imag());
    d[3][i] = static_cast<float>(c.m[i](1, 1).real());
  }
  write_geotiff_bands<float>(path,
                             {{d[0].data(), "C11"},
                              {d[1].data(), "C12_real"},
                              {d[2].data(), "C12_imag"},
                              {d[3].data(), "C22"}},
                             c.cols, c.rows, georef);
}

// The dual- and compact-pol products (ris/image/polsar/pol_synthesis.h).
nlohmann::json write_synthesis_products(const QuadPolSlc& s, const PolsarWindow& window,
                                        const StagedDirectory& dir, const Georef* georef) {
  const auto c2_of = [&](TwoChannelMode mode) {
    return boxcar_c2(synthesise_two_channel(s, mode), window.rows, window.cols);
  };
  write_c2_bands(c2_of(TwoChannelMode::dual_h), dir.path("dual_h_c2.tif"), georef);
  write_c2_bands(c2_of(TwoChannelMode::dual_v), dir.path("dual_v_c2.tif"), georef);
  const TwoChannelSlc compact = synthesise_two_channel(s, TwoChannelMode::compact_ctlr);
  write_geotiff(dir.path("compact_rh.tif"), compact.a.data(), s.cols, s.rows, georef, std::nullopt,
                {}, "RH (transmit right-circular, receive H)");
  write_geotiff(dir.path("compact_rv.tif"), compact.b.data(), s.cols, s.rows, georef, std::nullopt,
                {}, "RV (transmit right-circular, receive V)");
  const CovarianceImage c2 = boxcar_c2(compact, window.rows, window.cols);
  write_c2_bands(c2, dir.path("compact_c2.tif"), georef);
  const std::size_t n = c2.m.size();
  constexpr std::size_t kBands = 9;
  std::vector<std::vector<float>> d(kBands, std::vector<float>(n));
  std::array<Range, kBands> r;
  for (std::size_t i = 0; i < n; ++i) {
    const StokesMChi p = stokes_m_chi(c2.m[i]);
    const std::array<double, kBands> v = {p.g0,  p.g1,   p.g2,    p.g3, p.m, p.chi_rad * kRadToDeg,
                                          p.odd, p.even, p.volume};
    for (std::size_t b = 0; b < kBands; ++b) {
      d[b][i] = static_cast<float>(v[b]);
      r[b].add(v[b]);
    }
  }
  const std::array<const char*, kBands> names = {"g0",      "g1",  "g2",   "g3",    "m",
                                                 "chi_deg", "odd", "even", "volume"};
  std::vector<BandView<float>> bands;
  nlohmann::json stats;
  for (std::size_t b = 0; b < kBands; ++b) {
    bands.push_back({d[b].data(), names[b]});
    stats[names[b]] = r[b].json();
  }
  write_geotiff_bands<float>(dir.path("m_chi.tif"), bands, s.cols, s.rows, georef);
  return {{"products",
           {"dual_h_c2.tif", "dual_v_c2.tif", "compact_rh.tif", "compact_rv.tif", "compact_c2.tif",
            "m_chi.tif"}},
          {"dual_h", "transmit H, receive H and V: (HH, HV)"},
          {"dual_v", "transmit V, receive V and H: (VV, VH)"},
          {"compact",
           "CTLR (Raney 2007): transmit (1, -i)/sqrt2, RH = (HH - i VH)/sqrt2, RV = (HV - i "
           "VV)/sqrt2; names transmit first"},
          {"stokes",
           "g0 = <|RH|^2 + |RV|^2>, g1 = <|RH|^2 - |RV|^2>, g2 = 2 Re <RH RV*>, "
           "g3 = -2 Im <RH RV*>"},
          {"m_chi",
           "Raney et al. 2012: sin 2chi = -g3 / (m g0); odd = m g0 (1 + sin 2chi) / 2, even = "
           "m g0 (1 - sin 2chi) / 2, volume = g0 (1 - m)"},
          {"statistics", stats}};
}

}  // namespace

nlohmann::json write_polsar_products(const QuadPolSlc& s, const PolsarWindow& window,
                                     const std::filesystem::path& out_dir, bool syntheses) {
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
  if (syntheses) {
    j["syntheses"] = write_synthesis_products(s, window, dir, georef);
    for (const auto& f : j["syntheses"]["products"]) j["products"].push_back(f);
  }
  write_text_file_atomic(dir.path("metadata.json"), j.dump(1) + "\n");
  dir.commit();
  return j;
}

}  // namespace ris
