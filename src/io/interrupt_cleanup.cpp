#include "ris/io/interrupt_cleanup.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <pthread.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include "ris/io/atomic_file.h"

namespace ris {

namespace {

int g_pipe[2] = {-1, -1};

extern "C" void on_stop_signal(int sig) {
  const unsigned char b = static_cast<unsigned char>(sig);
  const int saved = errno;
  [[maybe_unused]] const ssize_t n = ::write(g_pipe[1], &b, 1);
  errno = saved;
}

const char* signal_name(int sig) {
  switch (sig) {
    case SIGINT:
      return "SIGINT";
    case SIGTERM:
      return "SIGTERM";
    case SIGHUP:
      return "SIGHUP";
    default:
      return "a signal";
  }
}

// What was removed, for the one line: the first few names and a count.
std::string removed_text(const std::vector<std::filesystem::path>& removed) {
  if (removed.empty()) return "nothing was being written";
  std::string names;
  for (std::size_t i = 0; i < removed.size() && i < 3; ++i) {
    names += (i > 0 ? ", " : "") + removed[i].string();
  }
  if (removed.size() > 3) names += fmt::format(" and {} more", removed.size() - 3);
  return fmt::format("removed the unfinished output{} {}", removed.size() > 1 ? "s" : "", names);
}

[[noreturn]] void stop(int sig) {
  std::signal(sig, SIG_DFL);  // a second one ends the process at once
  const std::vector<std::filesystem::path> removed = remove_staged_directories();
  const std::string line = fmt::format("ris: error: stopped by {} ({}): {}; no output written\n",
                                       signal_name(sig), sig, removed_text(removed));
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
  std::_Exit(128 + sig);
}

}  // namespace

void remove_outputs_on_interrupt() {
  static std::once_flag once;
  std::call_once(once, [] {
    std::signal(SIGXFSZ, SIG_IGN);
    if (::pipe2(g_pipe, O_CLOEXEC) != 0) return;  // no pipe: the signals keep their defaults
    std::thread([] {
      // Never this thread: a command that waits for these signals itself
      // (ris serve's sigwait) blocks them in its threads and must get them.
      sigset_t mine;
      sigemptyset(&mine);
      for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&mine, sig);
      pthread_sigmask(SIG_BLOCK, &mine, nullptr);
      unsigned char b = 0;
      for (;;) {
        const ssize_t n = ::read(g_pipe[0], &b, 1);
        if (n == 1) stop(b);
        if (n == 0 || (n < 0 && errno != EINTR)) return;
      }
    }).detach();
    struct sigaction sa = {};
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    for (const int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &sa, nullptr);
  });
}

}  // namespace ris
