#include "serve/guarded_http_server.h"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>

namespace ris {
namespace {

using Clock = std::chrono::steady_clock;

// Waits are cut in slices this long, so a stopping server is noticed.
constexpr std::chrono::milliseconds kPollSlice{200};
// After an answer that left the request's body unread: how long the rest is
// read and dropped (so the client reads the answer instead of a reset).
constexpr std::chrono::milliseconds kLingerTime{500};

std::string address_text(const sockaddr_storage& a, int& port) {
  char text[INET6_ADDRSTRLEN] = "";
  port = -1;
  if (a.ss_family == AF_INET) {
    const auto& v4 = reinterpret_cast<const sockaddr_in&>(a);
    inet_ntop(AF_INET, &v4.sin_addr, text, sizeof text);
    port = ntohs(v4.sin_port);
  } else if (a.ss_family == AF_INET6) {
    const auto& v6 = reinterpret_cast<const sockaddr_in6&>(a);
    inet_ntop(AF_INET6, &v6.sin6_addr, text, sizeof text);
    port = ntohs(v6.sin6_port);
  }
  return text;
}

std::string peer_address(int sock, int& port) {
  sockaddr_storage a{};
  socklen_t len = sizeof a;
  if (getpeername(sock, reinterpret_cast<sockaddr*>(&a), &len) != 0) return "";
  return address_text(a, port);
}

// One connection's socket for httplib: buffered reads (httplib reads header
// lines a byte at a time) and writes, each bounded by the per-call timeout
// and by the phase's absolute deadline.
class DeadlineStream : public httplib::Stream {
 public:
  DeadlineStream(int sock, const ConnectionLimits& limits, Clock::duration per_call,
                 const std::atomic<socket_t>& listening)
      : sock_(sock), limits_(limits), per_call_(per_call), listening_(listening) {}

  // Phases: the headers (from now: the wait for the first byte counts), the
  // body (httplib's setup_request hook, called once the headers are in).
  void begin_request() {
    read_deadline_ = Clock::now() + limits_.header_deadline;
    writing_ = false;
  }
  void begin_body() { read_deadline_ = Clock::now() + limits_.body_deadline; }
  void request_close() { close_requested_ = true; }
  // Between requests: true when the next one starts within `idle`.
  bool next_request_within(Clock::duration idle) const {
    return buffered() > 0 || wait(POLLIN, Clock::now() + idle);
  }
  bool close_requested() const { return close_requested_; }
  // A read or write ran out of time: the connection is done (httplib may
  // still answer 400 and wait for another request on it).
  bool timed_out() const { return timed_out_; }

  bool is_readable() const override { return buffered() > 0 || wait(POLLIN, read_deadline_); }
  bool is_writable() const override { return wait(POLLOUT, write_deadline()); }

  ssize_t read(char* ptr, size_t size) override {
    if (buffered() == 0) {
      if (!wait(POLLIN, read_deadline_)) return -1;
      if (size >= sizeof buffer_) return receive(ptr, size);
      const ssize_t n = receive(buffer_, sizeof buffer_);
      if (n <= 0) return n;
      begin_ = 0;
      end_ = static_cast<std::size_t>(n);
    }
    const std::size_t n = std::min(size, buffered());
    std::memcpy(ptr, buffer_ + begin_, n);
    begin_ += n;
    return static_cast<ssize_t>(n);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (!writing_) {
      writing_ = true;
      write_deadline_ = Clock::now() + limits_.write_deadline;
    }
    if (!wait(POLLOUT, write_deadline_)) return -1;
    ssize_t n = 0;
    do {
      n = ::send(sock_, ptr, size, MSG_NOSIGNAL);
    } while (n < 0 && errno == EINTR);
    return n;
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    ip = peer_address(sock_, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    sockaddr_storage a{};
    socklen_t len = sizeof a;
    ip =
        getsockname(sock_, reinterpret_cast<sockaddr*>(&a), &len) == 0 ? address_text(a, port) : "";
  }
  socket_t socket() const override { return sock_; }

 private:
  std::size_t buffered() const { return end_ - begin_; }
  Clock::time_point write_deadline() const {
    return writing_ ? write_deadline_ : Clock::now() + limits_.write_deadline;
  }

  ssize_t receive(char* ptr, std::size_t size) const {
    ssize_t n = 0;
    do {
      n = ::recv(sock_, ptr, size, 0);
    } while (n < 0 && errno == EINTR);
    return n;
  }

  // True once the socket is ready for `events`; false at the deadline, after
  // the per-call timeout, or when the server stops listening.
  bool wait(short events, Clock::time_point deadline) const {
    const Clock::time_point until = std::min(deadline, Clock::now() + per_call_);
    while (listening_.load() != INVALID_SOCKET) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now());
      if (left.count() <= 0) {
        timed_out_ = true;
        return false;
      }
      pollfd p{sock_, events, 0};
      const int r = ::poll(&p, 1, static_cast<int>(std::min(left, kPollSlice).count()));
      if (r > 0) return true;
      if (r < 0 && errno != EINTR) return false;
    }
    return false;
  }

  int sock_;
  const ConnectionLimits& limits_;
  Clock::duration per_call_;
  const std::atomic<socket_t>& listening_;
  Clock::time_point read_deadline_{};
  Clock::time_point write_deadline_{};
  bool writing_ = false;
  bool close_requested_ = false;
  mutable bool timed_out_ = false;
  char buffer_[4096];
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
};

// The stream of the connection this worker thread serves (handlers run on it).
thread_local DeadlineStream* t_stream = nullptr;

// Reads and drops what the client still sends, for a short while, after our
// side is shut for writing: a close with unread data would reset the
// connection and the client could lose the answer.
void linger_and_close(int sock) {
  ::shutdown(sock, SHUT_WR);
  const Clock::time_point until = Clock::now() + kLingerTime;
  char sink[4096];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - Clock::now());
    pollfd p{sock, POLLIN, 0};
    if (left.count() <= 0 || ::poll(&p, 1, static_cast<int>(left.count())) <= 0) break;
    if (::recv(sock, sink, sizeof sink, 0) <= 0) break;
  }
  ::close(sock);
}

void refuse_connection(int sock) {
  static const std::string body =
      R"({"error": "too many connections: the server's bound is reached, try again"})";
  const std::string answer =
      "HTTP/1.1 503 Service Unavailable\r\nContent-Type: application/json\r\n"
      "Connection: close\r\nRetry-After: 1\r\nContent-Length: " +
      std::to_string(body.size()) + "\r\n\r\n" + body;
  [[maybe_unused]] const ssize_t n =
      ::send(sock, answer.data(), answer.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
}

}  // namespace

void GuardedHttpServer::widen_listen_queue() {
  // listen() again on a listening socket only changes its queue length.
  if (svr_sock_.load() != INVALID_SOCKET) ::listen(svr_sock_.load(), SOMAXCONN);
}

void GuardedHttpServer::close_after_response() {
  if (t_stream != nullptr) t_stream->request_close();
}

bool GuardedHttpServer::admit(const std::string& client) {
  std::lock_guard lock(mutex_);
  std::size_t& mine = per_client_[client];
  if (open_ >= limits_.max_total || mine >= limits_.max_per_client) {
    if (mine == 0) per_client_.erase(client);
    return false;
  }
  ++open_;
  ++mine;
  return true;
}

void GuardedHttpServer::release(const std::string& client) {
  std::lock_guard lock(mutex_);
  --open_;
  if (--per_client_[client] == 0) per_client_.erase(client);
}

bool GuardedHttpServer::process_and_close_socket(socket_t sock) {
  int port = 0;
  const std::string client = peer_address(sock, port);
  if (!admit(client)) {
    refuse_connection(sock);
    return false;
  }
  serve_connection(sock);
  release(client);
  return true;
}

// httplib's keep-alive loop (process_server_socket), on a DeadlineStream.
void GuardedHttpServer::serve_connection(socket_t sock) {
  const auto per_call =
      std::chrono::seconds(read_timeout_sec_) + std::chrono::microseconds(read_timeout_usec_);
  DeadlineStream stream(sock, limits_, per_call, svr_sock_);
  t_stream = &stream;
  const std::function<void(httplib::Request&)> headers_read = [&stream](httplib::Request&) {
    stream.begin_body();
  };
  for (std::size_t left = keep_alive_max_count_; left > 0; --left) {
    // Idle between requests: at most the keep-alive timeout.
    const bool first = left == keep_alive_max_count_;
    if (!first && !stream.next_request_within(std::chrono::seconds(keep_alive_timeout_sec_))) {
      break;
    }
    if (svr_sock_.load() == INVALID_SOCKET) break;
    stream.begin_request();
    bool closed = false;
    if (!process_request(stream, left == 1, closed, headers_read) || closed ||
        stream.close_requested() || stream.timed_out()) {
      break;
    }
  }
  t_stream = nullptr;
  if (stream.close_requested()) {
    linger_and_close(sock);
  } else {
    ::shutdown(sock, SHUT_RDWR);
    ::close(sock);
  }
}

}  // namespace ris
