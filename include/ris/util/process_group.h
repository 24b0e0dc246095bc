// The processes one run spans: a single process (rank 0 of 1) or the ranks
// of an MPI job (`mpirun -np N ris simulate ... --stream`, docs/scale.md).
// The library sees only this interface; the MPI implementation lives in the
// command-line tool (apps/ris/mpi/), built when CMake finds MPI, so the core
// (and the Python module that links it) compiles and runs without MPI.
//
// Every call is made from the calling rank's main thread, outside OpenMP
// regions. Messages are byte buffers, tagged; reductions are of integers
// (exact, whatever the number of ranks) or gathers whose results the caller
// combines in rank order (so a float min/max or a "first cell" is the one a
// single process finds).
//
// Example:
//   ris::ProcessGroup& g = ris::process_group();
//   std::vector<std::uint64_t> counts = ...;   // this rank's part
//   g.sum(counts);                             // every rank: the sums
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ris {

class ProcessGroup {
 public:
  virtual ~ProcessGroup() = default;

  virtual int rank() const = 0;
  virtual int size() const = 0;

  // Point to point (blocking until the buffer may be reused).
  virtual void send(int to, int tag, const void* data, std::size_t bytes) = 0;
  // The same without waiting for the receiver: the group keeps `bytes` until
  // the message has gone (at most a few at a time: it waits for the oldest
  // beyond that), so the caller computes on while the receiver is busy.
  // finish_sends() waits for them all.
  virtual void send_later(int to, int tag, std::vector<char>&& bytes) = 0;
  virtual void finish_sends() = 0;
  struct Message {
    int source = -1;
    int tag = -1;
    std::vector<char> bytes;
  };
  static constexpr int kAny = -1;  // any source or tag
  // Receives the next message from `source` (kAny: any rank) with `tag`
  // (kAny: any), blocking until one arrives.
  virtual Message receive(int source, int tag) = 0;
  // Whether a message from `source` with `tag` (kAny allowed) has arrived.
  virtual bool message_waiting(int source, int tag) = 0;

  // Element-wise sums over the ranks, in place, on every rank.
  virtual void sum(std::vector<std::uint64_t>& values) = 0;
  // Every rank's buffer, indexed by rank, on every rank.
  virtual std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) = 0;
  virtual void barrier() = 0;
  // Ends every rank of the run with `exit_code` (after this rank has printed
  // its message and removed what it staged). Does not return.
  [[noreturn]] virtual void abort(int exit_code) = 0;
};

// The group this process belongs to: the one installed by the tool's main
// (an MPI job) or else the single process.
ProcessGroup& process_group();
// Installs `g` (not owned; nullptr: back to the single process).
void install_process_group(ProcessGroup* g);

}  // namespace ris
