// The HTTP server of `ris serve`: the JSON API and the page (docs/serve.md),
// on cpp-httplib's thread pool. Runs, edits and image reads take the
// session's lock one at a time; /api/health takes none, so a slow render
// never blocks a health check.
//
// Only the server's own page and non-browser clients are obeyed
// (ris/serve/request_guard.h): a foreign Host, Origin, Referer or
// Sec-Fetch-Site gives 403, a state-changing request that is not JSON 415.
// Connections are bounded in number and time (ris/serve/connection_limits.h):
// over the bound 503.
//
// Errors: bad input gives HTTP 400 and {"error": "<the CLI's message>"}
// (files named without their folders); a body over the cap 413, chunked or
// not; an unknown path 404; a simulate request overtaken by a newer one 409
// {"superseded": true}.
//
// Example:
//   ris::HttpServer server(session, {.host = "127.0.0.1", .port = 0, .web_dir = dir});
//   int port = server.bind();
//   std::thread t([&] { server.run(); });   ...   server.stop();  t.join();
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

#include "ris/serve/connection_limits.h"
#include "ris/serve/session.h"

namespace ris {

struct ServerOptions {
  std::string host = "127.0.0.1";
  int port = 8765;                                       // 0: any free port (bind() returns it)
  std::size_t max_body_bytes = 1 << 20;                  // request bodies above: HTTP 413
  std::size_t max_upload_bytes = std::size_t{64} << 20;  // POST /api/upload bodies above: 413
  // Where Debian's libjs-leaflet and libjs-chart.js put their files; the page
  // is served without them (plain images, a note) when they are missing.
  std::filesystem::path javascript_dir = "/usr/share/javascript";
  std::filesystem::path web_dir;  // the page's files (ris/serve/static_files.h)
  ConnectionLimits connections;
};

class HttpServer {
 public:
  HttpServer(Session& session, const ServerOptions& options);
  ~HttpServer();
  HttpServer(const HttpServer&) = delete;
  HttpServer& operator=(const HttpServer&) = delete;

  // Binds the address; returns the port. Throws InputError (key --host or
  // --port) when the address cannot be bound.
  int bind();
  // Serves until stop() (from any thread); returns then. After bind().
  void run();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ris
