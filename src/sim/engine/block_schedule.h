// Internal: blocks 0..n-1 computed over the ranks of a ProcessGroup
// (ris/util/process_group.h) and consumed on rank 0 in block order, so that
// what rank 0 writes does not depend on the number of ranks or on which rank
// computed a block (a streamed run's pass 1: ris/sim/slar_stream.h,
// docs/scale.md).
//
// Two schedules:
//  - dynamic (the default): a work queue on rank 0. Each worker holds up to
//    two assigned blocks (one computing, one queued, so it never waits for
//    an assignment); rank 0 hands the next block to the worker whose result
//    arrives, and computes a block itself when no result is waiting. Rank 0
//    also consumes (integrates and writes) every block, so it computes fewer;
//    the queue balances that.
//  - interleaved: block b on rank b mod N, no assignments sent.
// Either way rank 0 holds at most `window` blocks not yet consumed (results
// that arrived early), which bounds its memory.
//
// A worker whose compute() throws sends the message to rank 0 and waits:
// rank 0 rethrows it (InputError or std::runtime_error, naming the rank),
// unwinds (removing its staged output) and ends the run (the tool's main
// calls ProcessGroup::abort).
#pragma once

#include <fmt/format.h>

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ris/util/error.h"
#include "ris/util/process_group.h"

namespace ris::detail {

enum class BlockSchedule { dynamic, interleaved };

// How an MPI run hands out its blocks: RIS_MPI_SCHEDULE=interleaved or
// dynamic (the default; docs/scale.md).
inline BlockSchedule block_schedule_from_environment() {
  const char* v = std::getenv("RIS_MPI_SCHEDULE");
  if (v == nullptr || std::string(v).empty() || std::string(v) == "dynamic")
    return BlockSchedule::dynamic;
  if (std::string(v) == "interleaved") return BlockSchedule::interleaved;
  throw InputError("", "RIS_MPI_SCHEDULE",
                   fmt::format("expected dynamic or interleaved, got '{}'", v));
}

// How a pass hands out its blocks: the schedule, and the block whose worker
// the run's fault plan kills (FaultPlan::kill_block, ris/sim/fault_plan.h;
// -1: none).
struct BlockOrder {
  BlockSchedule schedule = BlockSchedule::dynamic;
  int kill_block = -1;
};

namespace block_tags {
inline constexpr int kAssign = 101;  // rank 0 -> worker: an int block, -1 = no more
inline constexpr int kResult = 102;  // worker -> rank 0: int block, then the packed result
inline constexpr int kError = 103;   // worker -> rank 0: int exit class (1 input, 3 other), text
}  // namespace block_tags

// compute(b) -> Result on any rank; pack(const Result&, std::vector<char>&)
// appends its bytes; unpack(const char*, std::size_t) -> Result;
// consume(b, Result&) on rank 0, b = 0, 1, ..., n - 1.
template <class Result, class Compute, class Pack, class Unpack, class Consume>
void run_blocks_in_order(ProcessGroup& g, int n, const BlockOrder& order, Compute compute,
                         Pack pack, Unpack unpack, Consume consume) {
  using namespace block_tags;
  const BlockSchedule schedule = order.schedule;
  const int ranks = g.size();
  if (ranks == 1) {
    for (int b = 0; b < n; ++b) {
      Result r = compute(b);
      consume(b, r);
    }
    return;
  }
  if (g.rank() != 0) {
    // A worker: its blocks, computed and sent in turn. The fault plan's
    // kill_block (a test's hook: a rank killed from outside, docs/scale.md)
    // makes the worker given block b die of SIGKILL before computing it.
    const int kill_block = order.kill_block;
    int next_static = g.rank();
    for (;;) {
      int b = -1;
      if (schedule == BlockSchedule::dynamic) {
        const ProcessGroup::Message m = g.receive(0, kAssign);
        RIS_CHECK(m.bytes.size() == sizeof(int));
        std::memcpy(&b, m.bytes.data(), sizeof(int));
      } else if (next_static < n) {
        b = next_static;
        next_static += ranks;
      }
      if (b < 0) {
        g.finish_sends();
        return;
      }
      if (b == kill_block) std::raise(SIGKILL);
      std::vector<char> bytes(sizeof(int));
      std::memcpy(bytes.data(), &b, sizeof(int));
      try {
        const Result r = compute(b);
        pack(r, bytes);
      } catch (const std::exception& e) {
        const int kind = dynamic_cast<const InputError*>(&e) != nullptr ? 1 : 3;
        std::vector<char> msg(sizeof(int));
        std::memcpy(msg.data(), &kind, sizeof(int));
        const std::string text = e.what();
        msg.insert(msg.end(), text.begin(), text.end());
        g.send(0, kError, msg.data(), msg.size());
        // Rank 0 ends the run (ProcessGroup::abort) once it has cleaned up.
        for (;;) g.receive(0, ProcessGroup::kAny);
      }
      // Without waiting for rank 0 (busy with a block of its own, maybe):
      // on to the next block.
      g.send_later(0, kResult, std::move(bytes));
    }
  }
  // Rank 0.
  const int window = 2 * ranks + 2;
  std::map<int, Result> ready;
  int next_assign = 0;   // dynamic: the next block not yet handed out
  std::deque<int> idle;  // dynamic: workers waiting for a block
  std::vector<bool> stopped(static_cast<std::size_t>(ranks), false);
  const auto owner = [&](int b) { return b % ranks; };
  const auto assign = [&](int w, int limit) {
    int b = -1;
    if (next_assign < n) {
      if (next_assign >= limit) return false;  // beyond the window: later
      b = next_assign++;
    } else if (stopped[static_cast<std::size_t>(w)]) {
      return true;
    } else {
      stopped[static_cast<std::size_t>(w)] = true;
    }
    g.send(w, kAssign, &b, sizeof(int));
    return true;
  };
  // One message from `source` (kAny: any worker): a result kept for later
  // or a worker's failure rethrown here.
  const auto receive_one = [&](int source, int limit) {
    ProcessGroup::Message m = g.receive(source, ProcessGroup::kAny);
    if (m.tag == kError) {
      int kind = 3;
      std::memcpy(&kind, m.bytes.data(), sizeof(int));
      const std::string text(m.bytes.begin() + sizeof(int), m.bytes.end());
      const std::string what =
          "rank " + std::to_string(m.source) + " of " + std::to_string(ranks) + " failed: " + text;
      if (kind == 1) throw InputError("", "", what);
      throw std::runtime_error(what);
    }
    RIS_CHECK(m.tag == kResult && m.bytes.size() >= sizeof(int));
    int b = -1;
    std::memcpy(&b, m.bytes.data(), sizeof(int));
    ready.emplace(b, unpack(m.bytes.data() + sizeof(int), m.bytes.size() - sizeof(int)));
    if (schedule == BlockSchedule::dynamic && !assign(m.source, limit)) idle.push_back(m.source);
  };
  if (schedule == BlockSchedule::dynamic) {
    for (int depth = 0; depth < 2; ++depth)
      for (int w = 1; w < ranks; ++w)
        if (!assign(w, window)) idle.push_back(w);
  }
  for (int b = 0; b < n; ++b) {
    const int limit = b + window;
    while (!idle.empty() && assign(idle.front(), limit)) idle.pop_front();
    while (ready.find(b) == ready.end()) {
      if (schedule == BlockSchedule::interleaved) {
        if (owner(b) == 0) {
          ready.emplace(b, compute(b));
        } else {
          receive_one(owner(b), limit);
        }
        continue;
      }
      if (g.message_waiting(ProcessGroup::kAny, ProcessGroup::kAny)) {
        receive_one(ProcessGroup::kAny, limit);
      } else if (next_assign < std::min(n, limit)) {
        const int mine = next_assign++;
        ready.emplace(mine, compute(mine));
      } else {
        receive_one(ProcessGroup::kAny, limit);
      }
    }
    auto it = ready.find(b);
    consume(b, it->second);
    ready.erase(it);
  }
  // Every worker told there is no more (dynamic); none is left computing.
  while (!idle.empty()) {
    RIS_CHECK(assign(idle.front(), n));
    idle.pop_front();
  }
}

}  // namespace ris::detail
