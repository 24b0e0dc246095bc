// Internal: a stream pass declared once, as an object. Every pass of a
// streamed run (lines, scene maps, geocoding, pictures, rays, scope) is a
// loop over blocks whose four steps a pass object says:
//
//   compute(b)         -> Block, on any rank (the work: read, simulate);
//   pack(block, bytes)    appends a block's bytes, on the rank that computed it;
//   unpack(p, n)       -> Block, on rank 0 (the bytes a worker sent);
//   consume(b, block)     on rank 0, b = 0, 1, ..., blocks() - 1 in order
//                         (integrate, write).
//
// run_pass hands such an object to the block schedule (block_schedule.h):
// in one process compute and consume alternate, under MPI the blocks are
// computed over the ranks and consumed on rank 0 in block order, so what
// rank 0 writes does not depend on the number of ranks (docs/scale.md).
// A new pass is one such class; the schedule, the MPI protocol, the fault
// plan's kill and the error path are not written again.
#pragma once

#include <concepts>
#include <cstddef>
#include <vector>

#include "ris/util/process_group.h"
#include "sim/engine/block_schedule.h"

namespace ris::detail {

template <class P>
concept BlockPass = requires(P& p, const P& cp, int b, typename P::Block& block,
                             const typename P::Block& cblock, std::vector<char>& bytes,
                             const char* at, std::size_t n) {
  { cp.blocks() } -> std::convertible_to<int>;
  { p.compute(b) } -> std::same_as<typename P::Block>;
  {cp.pack(cblock, bytes)};
  { p.unpack(at, n) } -> std::same_as<typename P::Block>;
  {p.consume(b, block)};
};

// The pass's blocks through the schedule: computed over g's ranks, consumed
// on rank 0 in block order.
template <BlockPass P>
void run_pass(ProcessGroup& g, const BlockOrder& order, P& pass) {
  using Block = typename P::Block;
  run_blocks_in_order<Block>(
      g, pass.blocks(), order, [&](int b) { return pass.compute(b); },
      [&](const Block& k, std::vector<char>& out) { pass.pack(k, out); },
      [&](const char* p, std::size_t n) { return pass.unpack(p, n); },
      [&](int b, Block& k) { pass.consume(b, k); });
}

}  // namespace ris::detail
