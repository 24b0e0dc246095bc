// The line-block kernels' vector versions (the widest clone this CPU runs:
// AVX-512, AVX2 or the baseline's SSE2) against their scalar twins, byte
// for byte, on rows with no-data cells in every position.
#include "kernels/sim/line_block_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "kernels/simd/cpu.h"
#include "ris/geometry/line_scan.h"

namespace ris::kernels {
namespace {

const char* clone_name() {
  return cpu_has_avx512() ? "avx512f" : (cpu_has_avx2() ? "avx2" : "baseline");
}

template <typename T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

struct Rows {
  std::vector<float> z, zn, zs;
  std::vector<std::uint8_t> v, vn, vs;
  std::vector<std::uint16_t> cat;
  Rows(int cols, std::mt19937& rng, double p_nodata) {
    std::uniform_real_distribution<float> h(-20.0f, 900.0f);
    std::bernoulli_distribution gap(p_nodata);
    for (auto* a : {&z, &zn, &zs}) {
      a->resize(static_cast<std::size_t>(cols));
      for (float& x : *a) x = h(rng);
    }
    for (auto* a : {&v, &vn, &vs}) {
      a->resize(static_cast<std::size_t>(cols));
      for (auto& x : *a) x = gap(rng) ? 0 : 1;
    }
    cat.resize(static_cast<std::size_t>(cols));
    for (auto& c : cat) c = static_cast<std::uint16_t>(rng() % 300);
  }
  CellRow row(int cols) const {
    return {cols, z.data(), v.data(), cat.data(), zn.data(), vn.data(), zs.data(), vs.data()};
  }
};

struct Terrain {
  std::vector<float> h, gx, gy;
  std::vector<std::uint16_t> cat;
  std::vector<std::uint8_t> flags, unseen;
  explicit Terrain(int n)
      : h(static_cast<std::size_t>(n)),
        gx(h.size()),
        gy(h.size()),
        cat(h.size()),
        flags(h.size()),
        unseen(h.size()) {
    for (std::size_t j = 0; j < unseen.size(); ++j)
      unseen[j] = j % 11 == 0 ? sample_flag::kUnseen : 0;
  }
  LineTerrainOut out() {
    return {h.data(), gx.data(), gy.data(), cat.data(), flags.data(), unseen.data()};
  }
};

TEST(LineBlockKernels, GatherRowVectorGivesTheScalarBytes) {
  RecordProperty("clone", clone_name());
  std::mt19937 rng(7);
  int compared = 0;
  for (int cols : {1, 2, 3, 8, 9, 10, 16, 17, 31, 64, 257}) {
    for (double p : {0.0, 0.05, 0.5}) {
      const Rows in(cols, rng, p);
      for (bool reverse : {false, true}) {
        Terrain vec(cols), ref(cols);
        gather_row(in.row(cols), 6.1, 7.3, reverse, vec.out());
        gather_row_scalar(in.row(cols), 6.1, 7.3, reverse, ref.out());
        EXPECT_TRUE(same_bytes(vec.h, ref.h) && same_bytes(vec.gx, ref.gx) &&
                    same_bytes(vec.gy, ref.gy) && same_bytes(vec.cat, ref.cat) &&
                    same_bytes(vec.flags, ref.flags))
            << "cols " << cols << " p " << p << " reverse " << reverse;
        compared += cols;
      }
    }
  }
  EXPECT_GT(compared, 2000);
}

TEST(LineBlockKernels, MapRowVectorGivesTheScalarBytes) {
  RecordProperty("clone", clone_name());
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> r(900.0f, 2100.0f), inc(0.0f, 1.6f);
  const std::uint8_t kinds[] = {0,
                                sample_flag::kNoData,
                                sample_flag::kUnseen,
                                sample_flag::kShadow,
                                sample_flag::kLayover,
                                sample_flag::kBackFacing,
                                sample_flag::kShadow | sample_flag::kLayover};
  for (int n : {1, 7, 8, 9, 24, 100, 333}) {
    std::vector<std::uint8_t> flags(static_cast<std::size_t>(n)), valid(flags.size());
    std::vector<float> range(flags.size()), local(flags.size());
    for (std::size_t j = 0; j < flags.size(); ++j) {
      flags[j] = kinds[rng() % std::size(kinds)];
      valid[j] = rng() % 6 == 0 ? 0 : 1;
      range[j] = j % 13 == 5 ? std::nanf("") : r(rng);
      local[j] = inc(rng);
    }
    for (bool reverse : {false, true}) {
      std::vector<std::uint8_t> mask_v(flags.size()), mask_s(flags.size());
      std::vector<float> deg_v(flags.size()), deg_s(flags.size());
      map_row(n, reverse, 1000.0, 2000.0, flags.data(), range.data(), local.data(), valid.data(),
              mask_v.data(), deg_v.data());
      map_row_scalar(n, reverse, 1000.0, 2000.0, flags.data(), range.data(), local.data(),
                     valid.data(), mask_s.data(), deg_s.data());
      EXPECT_TRUE(same_bytes(mask_v, mask_s)) << n << " " << reverse;
      EXPECT_TRUE(same_bytes(deg_v, deg_s)) << n << " " << reverse;
    }
  }
}

TEST(LineBlockKernels, TileTransposesGiveTheScalarBytes) {
  RecordProperty("clone", clone_name());
  std::mt19937 rng(3);
  const int rows8 = 24, cols8 = 16, tile_rows = 20;
  const std::size_t len = 30, stride = 21;
  const std::size_t src_n = static_cast<std::size_t>(rows8) * stride;
  const std::size_t tile_n = static_cast<std::size_t>(tile_rows) * len;
  std::vector<float> z(src_n);
  std::vector<std::uint16_t> cat(src_n);
  std::vector<std::uint8_t> v(src_n);
  for (std::size_t i = 0; i < src_n; ++i) {
    z[i] = static_cast<float>(rng()) * 1e-6f;
    cat[i] = static_cast<std::uint16_t>(rng());
    v[i] = static_cast<std::uint8_t>(rng());
  }
  std::vector<float> tz_v(tile_n, -1.0f), tz_s = tz_v;
  std::vector<std::uint16_t> tc_v(tile_n, 9), tc_s = tc_v;
  std::vector<std::uint8_t> tv_v(tile_n, 9), tv_s = tv_v;
  transpose_into_tile(rows8, cols8, tile_rows, len, stride, z.data(), cat.data(), v.data(),
                      tz_v.data(), tc_v.data(), tv_v.data());
  transpose_into_tile_scalar(rows8, cols8, tile_rows, len, stride, z.data(), cat.data(), v.data(),
                             tz_s.data(), tc_s.data(), tv_s.data());
  EXPECT_TRUE(same_bytes(tz_v, tz_s) && same_bytes(tc_v, tc_s) && same_bytes(tv_v, tv_s));

  std::vector<std::uint8_t> m_v(src_n, 7), m_s = m_v;
  std::vector<float> d_v(src_n, -2.0f), d_s = d_v;
  transpose_from_tile(rows8, cols8, tile_rows, len, stride, tv_s.data(), tz_s.data(), m_v.data(),
                      d_v.data());
  transpose_from_tile_scalar(rows8, cols8, tile_rows, len, stride, tv_s.data(), tz_s.data(),
                             m_s.data(), d_s.data());
  EXPECT_TRUE(same_bytes(m_v, m_s) && same_bytes(d_v, d_s));
  // And back: the inverse restores the block (validity and elevation).
  for (int r = 0; r < rows8; ++r)
    for (int c = 0; c < cols8; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * stride + static_cast<std::size_t>(c);
      ASSERT_EQ(m_v[i], v[i]);
      ASSERT_EQ(std::memcmp(&d_v[i], &z[i], sizeof(float)), 0);
    }
}

}  // namespace
}  // namespace ris::kernels
