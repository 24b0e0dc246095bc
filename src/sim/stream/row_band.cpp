#include "sim/stream/row_band.h"

#include <cstring>

#include "ris/util/error.h"

namespace ris::detail {

void pack_row_band(const RowBand& k, std::vector<char>& out) {
  const int head[2] = {k.r0, k.rows};
  const char* h = reinterpret_cast<const char*>(head);
  out.insert(out.end(), h, h + sizeof(head));
  const char* v = reinterpret_cast<const char*>(k.values.data());
  out.insert(out.end(), v, v + k.values.size() * sizeof(float));
  out.insert(out.end(), k.bytes.begin(), k.bytes.end());
}

RowBand unpack_row_band(const char* p, std::size_t n, int cols) {
  RowBand k;
  int head[2] = {};
  RIS_CHECK(n >= sizeof(head));
  std::memcpy(head, p, sizeof(head));
  k.r0 = head[0];
  k.rows = head[1];
  const std::size_t nc = std::size_t(k.rows) * std::size_t(cols);
  RIS_CHECK(n == sizeof(head) + nc * (sizeof(float) + 1));
  k.values.resize(nc);
  std::memcpy(k.values.data(), p + sizeof(head), nc * sizeof(float));
  k.bytes.assign(p + sizeof(head) + nc * sizeof(float), p + n);
  return k;
}

}  // namespace ris::detail
