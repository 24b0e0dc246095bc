// cpp-httplib's server with the connection bounds it lacks (Debian's 0.11.4):
// its read timeout restarts at every byte, so a client that trickles a byte
// every few seconds holds a worker thread for ever, and with a fixed pool 17
// such clients stopped the whole server (issue 37). This subclass takes over
// each accepted connection (process_and_close_socket, the virtual httplib
// calls on a worker): it admits it against ConnectionLimits (total and per
// client address; over them: 503 and closed at once), then serves its
// requests through its own Stream, whose reads and writes stop at absolute
// deadlines (headers, body, answer) and when the server stops. httplib still
// parses and routes every request (process_request).
//
// A private header of src/serve/ (it includes httplib.h, whose definitions
// stay on this library).
#pragma once

#include <httplib.h>

#include <cstddef>
#include <map>
#include <mutex>
#include <string>

#include "ris/serve/connection_limits.h"

namespace ris {

class GuardedHttpServer : public httplib::Server {
 public:
  explicit GuardedHttpServer(const ConnectionLimits& limits) : limits_(limits) {}

  // Workers enough that an admitted connection never waits for one and a
  // refused one is answered at once.
  std::size_t worker_count() const { return limits_.max_total + kSpareWorkers; }

  // After binding: a listen queue of SOMAXCONN instead of httplib's compiled
  // 5, so a burst of connections (slow ones included) is queued by the
  // kernel instead of dropped and retried a second later.
  void widen_listen_queue();

  // From a handler on this server's worker: close the connection once the
  // answer is sent (the request's body was left unread: refused or too long).
  static void close_after_response();

 private:
  static constexpr std::size_t kSpareWorkers = 8;

  bool process_and_close_socket(socket_t sock) override;
  bool admit(const std::string& client);
  void release(const std::string& client);
  void serve_connection(socket_t sock);

  ConnectionLimits limits_;
  std::mutex mutex_;
  std::size_t open_ = 0;                           // under mutex_
  std::map<std::string, std::size_t> per_client_;  // under mutex_
};

}  // namespace ris
