#include "ris/util/float_select.h"

#include "ris/kernels/vector_clones.h"

namespace ris::detail {

// The counts over the whole chunk in one loop (one horizontal sum per chunk;
// per group of 32 the three sums cost as much as the compares), then groups
// of 32 keys tested for any key inside the bracket in a fixed-length loop
// (so that GCC vectorises it), the few groups holding one copied element by
// element. Integer compares only: the clones give the same counts.
RIS_VECTOR_CLONES void count_bracket_chunk(const std::uint32_t* keys, std::size_t n,
                                           std::uint32_t key_lo, std::uint32_t key_hi,
                                           BracketCount& c) {
  std::uint32_t kept = 0, below = 0;
  for (std::size_t j = 0; j < n; ++j) {
    kept += static_cast<std::uint32_t>(keys[j] != kRejectedKey);
    below += static_cast<std::uint32_t>(keys[j] < key_lo);
  }
  c.kept += kept;
  c.below += below;
  // (key - key_lo) <= width unsigned: key_lo <= key <= key_hi in one compare.
  const std::uint32_t width = key_hi - key_lo;
  // Branch-free: every key is stored, the end advances past those inside (a
  // quarter of a hit group's keys: a branch on each mispredicted often).
  const auto copy_inside = [&](std::size_t j0, std::size_t j1) {
    const std::size_t old = c.inside.size();
    c.inside.resize(old + (j1 - j0));
    std::uint32_t* out = c.inside.data() + old;
    std::size_t m = 0;
    for (std::size_t j = j0; j < j1; ++j) {
      out[m] = keys[j];
      m += static_cast<std::size_t>(keys[j] - key_lo <= width);
    }
    c.inside.resize(old + m);
  };
  constexpr std::size_t kGroup = 32;
  std::size_t g = 0;
  for (; g + kGroup <= n; g += kGroup) {
    std::uint32_t any = 0;
    for (std::size_t j = g; j < g + kGroup; ++j)
      any |= static_cast<std::uint32_t>(keys[j] - key_lo <= width);
    if (any) copy_inside(g, g + kGroup);
  }
  copy_inside(g, n);
}

}  // namespace ris::detail
