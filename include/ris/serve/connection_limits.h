// The bounds on the connections of `ris serve` (docs/serve.md, "Threat
// model"; docs/limits.md): how many at once, in total and from one client
// address, and how long a connection may take to send a request's headers,
// its body and to read the answer. A slow client (slowloris: a byte every
// few seconds) is cut at its deadline instead of holding a worker for ever,
// and there are always more workers than admitted connections, so
// /api/health answers while the bound is reached.
//
// Example:
//   ris::ServerOptions o;  o.connections.max_total = 32;
//   o.connections.header_deadline = std::chrono::seconds(2);
#pragma once

#include <chrono>
#include <cstddef>

namespace ris {

struct ConnectionLimits {
  // Connections served at once; one more is answered 503 and closed.
  std::size_t max_total = 128;
  // From one client address (on the loopback every client is 127.0.0.1, so
  // this is above the 60 slow connections the tests hold with /api/health
  // still answered).
  std::size_t max_per_client = 64;
  // From a request's first byte (or the connection's start) to its last
  // header line; then the body; then from the first byte of the answer to its
  // last. A handler's own work (a run) is not counted.
  std::chrono::milliseconds header_deadline{10'000};
  std::chrono::milliseconds body_deadline{30'000};
  std::chrono::milliseconds write_deadline{30'000};
};

}  // namespace ris
