#include "ris/serve/server.h"

#include <httplib.h>

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>

#include "ris/serve/client_paths.h"
#include "ris/serve/request_guard.h"
#include "ris/serve/static_files.h"
#include "ris/util/error.h"
#include "serve/guarded_http_server.h"

namespace ris {
namespace {

constexpr const char* kJson = "application/json";

void send_json(httplib::Response& res, const nlohmann::json& j, int status = 200) {
  res.status = status;
  res.set_header("Cache-Control", "no-store");
  res.set_content(j.dump(), kJson);
}

void send_png(httplib::Response& res, const std::vector<std::uint8_t>& png) {
  res.set_header("Cache-Control", "no-store");
  res.set_content(reinterpret_cast<const char*>(png.data()), png.size(), "image/png");
}

void send_text(httplib::Response& res, const std::string& text, const std::string& file_name) {
  res.set_header("Cache-Control", "no-store");
  if (!file_name.empty()) {
    res.set_header("Content-Disposition", "attachment; filename=\"" + file_name + "\"");
  }
  res.set_content(text, "text/plain; charset=utf-8");
}

// Bad input (InputError) is the client's: 400 with the message the command
// line prints; anything else is ours: 500. Messages name files, never the
// server's folders (ris/serve/client_paths.h).
template <typename Call>
void answer_errors(httplib::Response& res, Call&& call) {
  try {
    call();
  } catch (const InputError& e) {
    send_json(res, {{"error", without_directories(e.what())}}, 400);
  } catch (const std::exception& e) {
    send_json(res, {{"error", "internal error: " + without_directories(e.what())}}, 500);
  }
}

// The request's body is left unread (refused, or over the cap): the client
// is told, and the connection ends after this answer.
void close_after(httplib::Response& res) {
  res.set_header("Connection", "close");
  GuardedHttpServer::close_after_response();
}

template <typename Handler>
httplib::Server::Handler guarded(Handler handler) {
  return [handler](const httplib::Request& req, httplib::Response& res) {
    answer_errors(res, [&] { handler(req, res); });
  };
}

// The body, taken as it arrives and refused (413) past the cap whether it
// comes with a Content-Length or chunked (httplib caps only the former).
std::optional<std::string> read_capped_body(const httplib::ContentReader& reader,
                                            httplib::Response& res, std::size_t cap,
                                            const char* cap_option = "--max-body-kib") {
  std::string body;
  bool over = false;
  const bool read = reader([&](const char* data, std::size_t n) {
    over = body.size() + n > cap;
    if (!over) body.append(data, n);
    return !over;
  });
  if (read) return body;
  over = over || res.status == 413;
  send_json(res,
            {{"error", over ? fmt::format("request body too large (over {} bytes, the server's "
                                          "{})",
                                          cap, cap_option)
                            : std::string("the request body could not be read")}},
            over ? 413 : 400);
  close_after(res);
  return std::nullopt;
}

// A state-changing route: its handler gets the body read under the cap.
template <typename Handler>
httplib::Server::HandlerWithContentReader with_body(Handler handler, std::size_t cap) {
  return [handler, cap](const httplib::Request& req, httplib::Response& res,
                        const httplib::ContentReader& reader) {
    const std::optional<std::string> body = read_capped_body(reader, res, cap);
    if (body) answer_errors(res, [&] { handler(req, res, *body); });
  };
}

RequestFacts facts_of(const httplib::Request& req) {
  return {req.method,
          req.path,
          req.get_header_value("Host"),
          req.get_header_value("Origin"),
          req.get_header_value("Referer"),
          req.get_header_value("Content-Type"),
          req.get_header_value("Sec-Fetch-Site")};
}

int int_param(const httplib::Request& req, const std::string& key) {
  const std::string text = req.get_param_value(key);
  int v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size()) {
    throw InputError("request", key, "expected an integer, got \"" + text + "\"");
  }
  return v;
}

// A run id (1, 2, ...).
std::uint64_t run_param(const httplib::Request& req, const std::string& key) {
  const std::string text = req.get_param_value(key);
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || v == 0) {
    throw InputError("request", key, "expected a run id (1, 2, ...), got \"" + text + "\"");
  }
  return v;
}

// A coordinate of a region (pixels, fractional).
double coordinate_param(const httplib::Request& req, const std::string& key) {
  const std::string text = req.get_param_value(key);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v) ||
      std::abs(v) > 1e9) {
    throw InputError("request", key, "expected a pixel coordinate, got \"" + text + "\"");
  }
  return v;
}

// The difference view's symmetric range in dB: absent, the view's default
// (0); else a number in (0, 100].
double range_param(const httplib::Request& req) {
  if (!req.has_param("range_db")) return 0.0;
  const std::string text = req.get_param_value("range_db");
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !(v > 0.0) ||
      v > 100.0) {
    throw InputError("request", "range_db",
                     "expected a range in dB, above 0 and at most 100, got \"" + text + "\"");
  }
  return v;
}

std::size_t index_param(const httplib::Request& req) {
  std::size_t v = 0;
  const std::string text = req.matches[1];
  std::from_chars(text.data(), text.data() + text.size(), v);  // the route's \d+ matched
  return v;
}

std::string read_binary(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

struct HttpServer::Impl {
  Session& session;
  ServerOptions options;
  StaticFiles files;
  GuardedHttpServer http;
  std::unique_ptr<RequestGuard> guard;  // made by bind(), once the port is known

  Impl(Session& s, const ServerOptions& o)
      : session(s), options(o), files(o.web_dir), http(o.connections) {
    // httplib's own cap is the larger one; each route reads under its own.
    http.set_payload_max_length(std::max(options.max_body_bytes, options.max_upload_bytes));
    // A worker for every admitted connection and spares (a browser's
    // keep-alive connections each hold one while open; slow clients are cut
    // at their deadlines, ris/serve/connection_limits.h).
    const std::size_t workers = http.worker_count();
    http.new_task_queue = [workers] { return new httplib::ThreadPool(workers); };
    http.set_keep_alive_timeout(2);
    // Before routing, on every request: Host, Origin and content type
    // (ris/serve/request_guard.h). A refused request's body is left unread,
    // so its connection closes after the answer.
    http.set_pre_routing_handler([this](const httplib::Request& req, httplib::Response& res) {
      const RequestGuard::Refusal r = guard->refusal(facts_of(req));
      if (r.status == 0) return httplib::Server::HandlerResponse::Unhandled;
      send_json(res, {{"error", r.message}}, r.status);
      close_after(res);
      return httplib::Server::HandlerResponse::Handled;
    });
    http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (res.body.empty()) {
        const char* what = res.status == 413   ? "request body too large"
                           : res.status == 404 ? "not found"
                           : res.status == 405 ? "method not allowed"
                                               : "bad request";
        send_json(res, {{"error", what}}, res.status);
      }
    });
    add_javascript_libraries();
    add_api_routes();
    add_scene_routes();
    // The page: names looked up in the table read at start-up, never opened.
    http.Get(R"(/(.*))", [this](const httplib::Request& req, httplib::Response& res) {
      const StaticFile* f = files.find(req.matches[1]);
      if (f == nullptr) {
        send_json(res, {{"error", "not found"}}, 404);
        return;
      }
      res.set_content(f->content, f->mime.c_str());
    });
  }

  // Debian's Leaflet and Chart.js, read from where their packages put them
  // (nothing fetched, nothing copied into the repository); the page falls
  // back to plain images and canvas charts when they are missing.
  void add_javascript_libraries() {
    const std::filesystem::path& js = options.javascript_dir;
    for (const char* f :
         {"leaflet.js", "leaflet.css", "images/layers.png", "images/layers-2x.png"}) {
      files.add_optional(std::string("vendor/leaflet/") + f, js / "leaflet" / f);
    }
    files.add_optional("vendor/chart.js/chart.min.js", js / "chart.js" / "chart.min.js");
  }

  void add_api_routes() {
    Session& s = session;
    const std::size_t cap = options.max_body_bytes;
    http.Get("/api/health", [](const httplib::Request&, httplib::Response& res) {
      send_json(res, {{"ok", true}, {"version", RIS_VERSION}});
    });
    http.Get("/api/state", guarded([&s](const auto&, auto& res) { send_json(res, s.state()); }));
    http.Post("/api/simulate", with_body(
                                   [&s](const auto&, auto& res, const std::string& body) {
                                     const SimulateOutcome out = s.simulate(body);
                                     if (out.superseded) {
                                       send_json(res, {{"superseded", true}}, 409);
                                     } else {
                                       send_json(res, out.run);
                                     }
                                   },
                                   cap));
    http.Get(R"(/api/image/([a-z]+)\.png)", guarded([&s](const httplib::Request& req, auto& res) {
               send_png(res, s.image_png(req.matches[1]));
             }));
    http.Get(R"(/api/overlay/([a-z]+)\.png)", guarded([&s](const httplib::Request& req, auto& res) {
               send_png(res, s.overlay_png(req.matches[1], req.get_param_value("masks")));
             }));
    // minute=<0..1439>: the UTC time of day (default: the sensor file's).
    http.Get(R"(/api/sensor/([a-z]+)\.png)", guarded([&s](const httplib::Request& req, auto& res) {
               std::optional<int> minute;
               if (req.has_param("minute")) minute = int_param(req, "minute");
               send_png(res, s.sensor_png(req.matches[1], minute));
             }));
    http.Get("/api/shadowmap.txt",
             guarded([&s](const auto&, auto& res) { send_text(res, s.shadow_map(), ""); }));
    http.Get("/api/histogram",
             guarded([&s](const auto&, auto& res) { send_json(res, s.histogram()); }));
    http.Get("/api/sigma0",
             guarded([&s](const auto&, auto& res) { send_json(res, s.sigma0_chart()); }));
    // run=<id>: a kept earlier run's slant pixel (comparing runs).
    http.Get("/api/inspect", guarded([&s](const httplib::Request& req, auto& res) {
               const int x = int_param(req, "x");
               const int y = int_param(req, "y");
               const std::string view = req.get_param_value("view");
               if (req.has_param("run")) {
                 const std::uint64_t id = run_param(req, "run");
                 if (view != "slant") {
                   throw InputError("request", "view",
                                    "an earlier run is inspected on its slant view");
                 }
                 send_json(res, s.inspect_kept(id, x, y));
                 return;
               }
               send_json(res, s.inspect(view, x, y));
             }));
    add_compare_routes();
    http.Post("/api/products",
              with_body([&s](const auto&, auto& res,
                             const std::string&) { send_json(res, s.write_products()); },
                        cap));
    http.Get("/api/products.zip", guarded([&s](const auto&, auto& res) {
               const std::vector<std::uint8_t> zip = s.products_zip();
               res.set_header("Content-Disposition", "attachment; filename=\"products.zip\"");
               res.set_content(reinterpret_cast<const char*>(zip.data()), zip.size(),
                               "application/zip");
             }));
    // Products by name from the list just written; the name is never a path.
    http.Get(R"(/api/products/(.+))", guarded([&s](const httplib::Request& req, auto& res) {
               const auto path = s.product_file(req.matches[1]);
               if (!path) {
                 send_json(res, {{"error", "no such product (write them first)"}}, 404);
                 return;
               }
               res.set_header("Content-Disposition",
                              "attachment; filename=\"" + path->filename().string() + "\"");
               res.set_content(read_binary(*path), "application/octet-stream");
             }));
  }

  // Comparing the current run with a kept earlier one (docs/serve.md,
  // "Comparing two runs"); reads only, through the same guards.
  void add_compare_routes() {
    Session& s = session;
    http.Get("/api/runs", guarded([&s](const auto&, auto& res) { send_json(res, s.runs()); }));
    http.Get(R"(/api/runs/(\d{1,12})/slant\.png)",
             guarded([&s](const httplib::Request& req, auto& res) {
               std::uint64_t id = 0;
               const std::string text = req.matches[1];
               std::from_chars(text.data(), text.data() + text.size(), id);  // \d+ matched
               send_png(res, s.kept_slant_png(id));
             }));
    http.Get("/api/link", guarded([&s](const httplib::Request& req, auto& res) {
               send_json(res, s.link(req.get_param_value("from"), coordinate_param(req, "x0"),
                                     coordinate_param(req, "y0"), coordinate_param(req, "x1"),
                                     coordinate_param(req, "y1")));
             }));
    http.Get("/api/compare", guarded([&s](const httplib::Request& req, auto& res) {
               send_json(res, s.compare(run_param(req, "earlier"), req.get_param_value("quantity"),
                                        range_param(req)));
             }));
    http.Get("/api/compare/difference.png", guarded([&s](const httplib::Request& req, auto& res) {
               send_png(res, s.difference_png(run_param(req, "earlier"),
                                              req.get_param_value("quantity"), range_param(req)));
             }));
    http.Get("/api/compare/pixel", guarded([&s](const httplib::Request& req, auto& res) {
               send_json(res,
                         s.compare_pixel(run_param(req, "earlier"), req.get_param_value("quantity"),
                                         int_param(req, "x"), int_param(req, "y")));
             }));
  }

  void add_scene_routes() {
    Session& s = session;
    const std::size_t cap = options.max_body_bytes;
    http.Post("/api/scene/objects",
              with_body([&s](const auto&, auto& res,
                             const std::string& body) { send_json(res, s.add_object(body)); },
                        cap));
    http.Post(R"(/api/scene/objects/(\d{1,6}))",
              with_body(
                  [&s](const httplib::Request& req, auto& res, const std::string& body) {
                    send_json(res, s.update_object(index_param(req), body));
                  },
                  cap));
    http.Delete(
        R"(/api/scene/objects/(\d{1,6}))",
        with_body([&s](const httplib::Request& req, auto& res,
                       const std::string&) { send_json(res, s.delete_object(index_param(req))); },
                  cap));
    http.Post("/api/scene/paint",
              with_body([&s](const auto&, auto& res,
                             const std::string& body) { send_json(res, s.paint(body)); },
                        cap));
    http.Post("/api/scene/undo", with_body([&s](const auto&, auto& res,
                                                const std::string&) { send_json(res, s.undo()); },
                                           cap));
    http.Post("/api/scene/save",
              with_body([&s](const auto&, auto& res,
                             const std::string& body) { send_json(res, s.save_scene(body)); },
                        cap));
    http.Post("/api/radar/save",
              with_body([&s](const auto&, auto& res,
                             const std::string& body) { send_json(res, s.save_radar(body)); },
                        cap));
    // A file's bytes (application/octet-stream, request_guard.h) under the
    // upload cap; kind, name and mapping in the query.
    const std::size_t upload_cap = options.max_upload_bytes;
    http.Post(kUploadPath, [&s, upload_cap](const httplib::Request& req, httplib::Response& res,
                                            const httplib::ContentReader& reader) {
      const std::optional<std::string> body =
          read_capped_body(reader, res, upload_cap, "--max-upload-mib");
      if (!body) return;
      answer_errors(res, [&] {
        send_json(res, s.upload(req.get_param_value("kind"), req.get_param_value("name"),
                                req.get_param_value("mapping"), *body));
      });
    });
    http.Get("/api/scene.toml", guarded([&s](const auto&, auto& res) {
               send_text(res, s.scene_toml(), "scene.toml");
             }));
    http.Get("/api/radar.toml", guarded([&s](const auto&, auto& res) {
               send_text(res, s.radar_toml(), "radar.toml");
             }));
  }
};

HttpServer::HttpServer(Session& session, const ServerOptions& options)
    : impl_(std::make_unique<Impl>(session, options)) {}

HttpServer::~HttpServer() = default;

int HttpServer::bind() {
  const ServerOptions& o = impl_->options;
  int port = o.port;
  if (o.port == 0) {
    port = impl_->http.bind_to_any_port(o.host);
  } else if (!impl_->http.bind_to_port(o.host, o.port)) {
    port = -1;
  }
  if (port <= 0) {
    throw InputError("", "--host/--port",
                     fmt::format("cannot listen on {}:{} (in use, or not an address of this "
                                 "machine)",
                                 o.host, o.port));
  }
  impl_->http.widen_listen_queue();
  impl_->guard = std::make_unique<RequestGuard>(o.host, port);
  return port;
}

void HttpServer::run() {
  RIS_CHECK(impl_->guard != nullptr);  // bind() first: the checks need the port
  impl_->http.listen_after_bind();
}

void HttpServer::stop() {
  impl_->http.stop();
}

}  // namespace ris
