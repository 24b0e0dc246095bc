// The tool built with MPI (Debian's OpenMPI): the ranks of MPI_COMM_WORLD as
// a ProcessGroup. MPI is started only when a launcher started this process
// (its environment says so), so `ris` run by hand never initialises MPI.
#include <fmt/format.h>
#include <mpi.h>
#include <pthread.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "process_group_start.h"
#include "ris/io/atomic_file.h"
#include "ris/util/error.h"

namespace ris::app {

namespace {

// Set by mpirun/mpiexec (OpenMPI), PMIx launchers (srun --mpi=pmix) and PMI
// launchers (MPICH, srun --mpi=pmi2).
bool started_by_mpi_launcher() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(v) != nullptr) return true;
  }
  return false;
}

std::atomic<int> g_rank{-1}, g_size{0};  // for the message of stop_cleanly_on_signal

// When a rank fails or is killed (the OOM killer, a test's SIGKILL),
// OpenMPI's mpirun ends the others with SIGTERM, and SIGKILL a second later
// (odls_base_sigkill_timeout); Ctrl-C on mpirun does the same. By default
// that leaves rank 0's hidden staging folder behind. So SIGTERM and SIGINT
// are blocked in every thread (before MPI and OpenMP start theirs) and one
// thread waits for them: it removes the staging folders (every file staged
// so far) and ends the process. Not a signal handler: removing folders is
// not async-signal-safe, a thread may do it.
void stop_cleanly_on_signal() {
  sigset_t stop;
  sigemptyset(&stop);
  sigaddset(&stop, SIGTERM);
  sigaddset(&stop, SIGINT);
  sigaddset(&stop, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &stop, nullptr);
  std::signal(SIGXFSZ, SIG_IGN);  // past `ulimit -f`: an error, not a silent death
  std::thread([stop] {
    int sig = 0;
    if (sigwait(&stop, &sig) != 0) return;
    remove_staged_directories();
    if (g_rank.load() == 0) {
      std::fputs(fmt::format("ris (rank 0 of {}): error: stopped by signal {} ({}): the MPI "
                             "launcher ends every rank when one fails or is killed (its message "
                             "names the rank); no output written, the staging folder removed\n",
                             g_size.load(), sig,
                             sig == SIGTERM  ? "SIGTERM"
                             : sig == SIGHUP ? "SIGHUP"
                                             : "SIGINT")
                     .c_str(),
                 stderr);
      std::fflush(stderr);
    }
    std::_Exit(128 + sig);
  }).detach();
}

// An error in an MPI call (a peer's connection lost when its node dies,
// before the launcher has stopped this rank): MPI_ERRORS_ARE_FATAL would
// abort at once and leave the staging folder; this handler removes it
// first, says so, then aborts every rank.
void on_mpi_error(MPI_Comm*, int* code, ...) {
  remove_staged_directories();
  char text[MPI_MAX_ERROR_STRING] = {};
  int length = 0;
  MPI_Error_string(*code, text, &length);
  std::fputs(fmt::format("ris (rank {} of {}): error: MPI: {}; no output written, the staging "
                         "folder removed\n",
                         g_rank.load(), g_size.load(), std::string(text, std::size_t(length)))
                 .c_str(),
             stderr);
  std::fflush(stderr);
  MPI_Abort(MPI_COMM_WORLD, 3);
}

int checked_count(std::size_t bytes) {
  RIS_CHECK(bytes <= std::size_t(std::numeric_limits<int>::max()));
  return static_cast<int>(bytes);
}

class MpiProcessGroup final : public ProcessGroup {
 public:
  MpiProcessGroup(int& argc, char**& argv) {
    int provided = 0;
    // Serialized: the main thread (outside OpenMP regions) and the progress
    // thread below, one at a time (mu_).
    MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    g_size = size_;
    g_rank = rank_;
    MPI_Errhandler on_error = MPI_ERRHANDLER_NULL;
    MPI_Comm_create_errhandler(on_mpi_error, &on_error);
    MPI_Comm_set_errhandler(MPI_COMM_WORLD, on_error);
    if (provided >= MPI_THREAD_SERIALIZED) progress_ = std::thread([this] { progress_loop(); });
  }
  ~MpiProcessGroup() override {
    {
      const std::lock_guard<std::mutex> lock(mu_);
      stop_ = true;
    }
    wake_.notify_all();
    if (progress_.joinable()) progress_.join();
    barrier();  // napping while rank 0 finishes (MPI_Finalize may spin)
    MPI_Finalize();
  }
  MpiProcessGroup(const MpiProcessGroup&) = delete;
  MpiProcessGroup& operator=(const MpiProcessGroup&) = delete;

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  void send(int to, int tag, const void* data, std::size_t bytes) override {
    const std::lock_guard<std::mutex> lock(mu_);
    MPI_Send(data, checked_count(bytes), MPI_BYTE, to, tag, MPI_COMM_WORLD);
  }

  void send_later(int to, int tag, std::vector<char>&& bytes) override {
    const std::lock_guard<std::mutex> lock(mu_);
    drop_sent(false);
    while (pending_.size() >= kMaxPending) drop_sent(true);
    pending_.emplace_back();
    Pending& p = pending_.back();
    p.bytes = std::move(bytes);
    MPI_Isend(p.bytes.data(), checked_count(p.bytes.size()), MPI_BYTE, to, tag, MPI_COMM_WORLD,
              &p.request);
    wake_.notify_all();
  }

  void finish_sends() override {
    const std::lock_guard<std::mutex> lock(mu_);
    while (!pending_.empty()) drop_sent(true);
  }

  Message receive(int source, int tag) override {
    const std::lock_guard<std::mutex> lock(mu_);
    MPI_Status st;
    for (int found = 0;;) {
      MPI_Iprobe(source == kAny ? MPI_ANY_SOURCE : source, tag == kAny ? MPI_ANY_TAG : tag,
                 MPI_COMM_WORLD, &found, &st);
      if (found) break;
      nap();
    }
    int count = 0;
    MPI_Get_count(&st, MPI_BYTE, &count);
    Message m;
    m.source = st.MPI_SOURCE;
    m.tag = st.MPI_TAG;
    m.bytes.resize(static_cast<std::size_t>(count));
    MPI_Recv(m.bytes.data(), count, MPI_BYTE, m.source, m.tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return m;
  }

  bool message_waiting(int source, int tag) override {
    const std::lock_guard<std::mutex> lock(mu_);
    int flag = 0;
    MPI_Iprobe(source == kAny ? MPI_ANY_SOURCE : source, tag == kAny ? MPI_ANY_TAG : tag,
               MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
    return flag != 0;
  }

  void sum(std::vector<std::uint64_t>& values) override {
    const std::lock_guard<std::mutex> lock(mu_);
    // In pieces of at most INT_MAX elements (MPI counts are int).
    constexpr std::size_t kPiece = std::size_t(1) << 28;
    for (std::size_t at = 0; at < values.size(); at += kPiece) {
      const std::size_t n = std::min(kPiece, values.size() - at);
      MPI_Request r = MPI_REQUEST_NULL;
      MPI_Iallreduce(MPI_IN_PLACE, values.data() + at, static_cast<int>(n), MPI_UINT64_T, MPI_SUM,
                     MPI_COMM_WORLD, &r);
      wait_napping(r);
    }
  }

  std::vector<std::vector<char>> all_gather(const std::vector<char>& mine) override {
    const std::lock_guard<std::mutex> lock(mu_);
    const int n = checked_count(mine.size());
    std::vector<int> counts(static_cast<std::size_t>(size_)), offsets(counts.size());
    MPI_Request req = MPI_REQUEST_NULL;
    MPI_Iallgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD, &req);
    wait_napping(req);
    std::size_t total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
      offsets[r] = checked_count(total);
      total += static_cast<std::size_t>(counts[r]);
    }
    std::vector<char> all(std::max<std::size_t>(total, 1));
    MPI_Iallgatherv(mine.data(), n, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE,
                    MPI_COMM_WORLD, &req);
    wait_napping(req);
    std::vector<std::vector<char>> out(counts.size());
    for (std::size_t r = 0; r < counts.size(); ++r) {
      const auto* p = all.data() + offsets[r];
      out[r].assign(p, p + counts[r]);
    }
    return out;
  }

  void barrier() override {
    const std::lock_guard<std::mutex> lock(mu_);
    MPI_Request r = MPI_REQUEST_NULL;
    MPI_Ibarrier(MPI_COMM_WORLD, &r);
    wait_napping(r);
  }

  [[noreturn]] void abort(int exit_code) override {
    const std::lock_guard<std::mutex> lock(mu_);
    MPI_Abort(MPI_COMM_WORLD, exit_code);
    std::_Exit(exit_code);
  }

 private:
  struct Pending {
    MPI_Request request = MPI_REQUEST_NULL;
    std::vector<char> bytes;
  };
  static constexpr std::size_t kMaxPending = 2;

  // Waiting without spinning: OpenMPI's blocking calls poll at full speed,
  // which on shared or oversubscribed cores takes the CPU from the ranks
  // that compute (a worker waits through rank 0's serial passes). These
  // test every 100 us and sleep in between (each test also moves pending
  // transfers).
  static void nap() { std::this_thread::sleep_for(std::chrono::microseconds(100)); }
  static void wait_napping(MPI_Request& r) {
    for (int done = 0;;) {
      MPI_Test(&r, &done, MPI_STATUS_IGNORE);
      if (done) return;
      nap();
    }
  }

  // Drops the sends that have gone, oldest first; wait: at least the oldest.
  void drop_sent(bool wait) {
    while (!pending_.empty()) {
      int done = 0;
      if (wait) {
        wait_napping(pending_.front().request);
        done = 1;
        wait = false;
      } else {
        MPI_Test(&pending_.front().request, &done, MPI_STATUS_IGNORE);
      }
      if (!done) return;
      pending_.pop_front();
    }
  }

  // While sends are pending, MPI_Test every 200 us: the progress a
  // rendezvous transfer needs from the sender (copy-in/copy-out shared
  // memory, TCP) while the main thread computes a block and makes no MPI
  // call. Sleeps otherwise.
  void progress_loop() {
    std::unique_lock<std::mutex> lock(mu_);
    while (!stop_) {
      if (pending_.empty()) {
        wake_.wait(lock);
        continue;
      }
      drop_sent(false);
      lock.unlock();
      std::this_thread::sleep_for(std::chrono::microseconds(200));
      lock.lock();
    }
  }

  int rank_ = 0, size_ = 1;
  std::deque<Pending> pending_;
  std::mutex mu_;  // one MPI call at a time (MPI_THREAD_SERIALIZED)
  std::condition_variable wake_;
  bool stop_ = false;
  std::thread progress_;
};

}  // namespace

std::unique_ptr<ProcessGroup> join_process_group(int& argc, char**& argv) {
  if (!started_by_mpi_launcher()) return nullptr;
  stop_cleanly_on_signal();
  return std::make_unique<MpiProcessGroup>(argc, argv);
}

}  // namespace ris::app
