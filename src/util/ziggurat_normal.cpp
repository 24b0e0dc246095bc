#include "ris/util/ziggurat_normal.h"

#include <cmath>

namespace ris {

namespace {

// Marsaglia and Tsang (2000), zigset() for RNOR with 128 layers: R = 3.4426
// and the common area v = 9.91256303526217e-3 of every layer.
ZigguratTables build() {
  ZigguratTables t{};
  const double m1 = 2147483648.0;  // 2^31
  double dn = ZigguratTables::kR, tn = dn;
  const double vn = 9.91256303526217e-3;
  const double q = vn / std::exp(-0.5 * dn * dn);
  t.k[0] = static_cast<std::uint32_t>((dn / q) * m1);
  t.k[1] = 0;
  t.w[0] = q / m1;
  t.w[127] = dn / m1;
  t.f[0] = 1.0;
  t.f[127] = std::exp(-0.5 * dn * dn);
  for (int i = 126; i >= 1; --i) {
    dn = std::sqrt(-2.0 * std::log(vn / dn + std::exp(-0.5 * dn * dn)));
    t.k[i + 1] = static_cast<std::uint32_t>((dn / tn) * m1);
    tn = dn;
    t.f[i] = std::exp(-0.5 * dn * dn);
    t.w[i] = dn / m1;
  }
  return t;
}

}  // namespace

const ZigguratTables& ziggurat_tables() {
  static const ZigguratTables tables = build();
  return tables;
}

}  // namespace ris
