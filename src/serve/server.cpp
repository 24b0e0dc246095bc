#include "ris/serve/server.h"

#include <httplib.h>

#include <fmt/format.h>

#include <charconv>
#include <fstream>
#include <sstream>

#include "ris/serve/static_files.h"
#include "ris/util/error.h"

namespace ris {
namespace {

constexpr const char* kJson = "application/json";
constexpr std::size_t kWorkers = 16;

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
// line prints; anything else is ours: 500.
template <typename Handler>
httplib::Server::Handler guarded(Handler handler) {
  return [handler](const httplib::Request& req, httplib::Response& res) {
    try {
      handler(req, res);
    } catch (const InputError& e) {
      send_json(res, {{"error", e.what()}}, 400);
    } catch (const std::exception& e) {
      send_json(res, {{"error", std::string("internal error: ") + e.what()}}, 500);
    }
  };
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
  httplib::Server http;

  Impl(Session& s, const ServerOptions& o) : session(s), options(o), files(o.web_dir) {
    http.set_payload_max_length(options.max_body_bytes);
    // Enough workers that a browser's keep-alive connections (each holds a
    // worker while open) and health checks never wait for each other.
    http.new_task_queue = [] { return new httplib::ThreadPool(kWorkers); };
    http.set_keep_alive_timeout(2);
    http.set_error_handler([](const httplib::Request&, httplib::Response& res) {
      if (res.body.empty()) {
        const char* what = res.status == 413   ? "request body too large"
                           : res.status == 404 ? "not found"
                                               : "bad request";
        send_json(res, {{"error", what}}, res.status);
      }
    });
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

  void add_api_routes() {
    Session& s = session;
    http.Get("/api/health", [](const httplib::Request&, httplib::Response& res) {
      send_json(res, {{"ok", true}, {"version", RIS_VERSION}});
    });
    http.Get("/api/state", guarded([&s](const auto&, auto& res) { send_json(res, s.state()); }));
    http.Post("/api/simulate", guarded([&s](const httplib::Request& req, auto& res) {
                const SimulateOutcome out = s.simulate(req.body);
                if (out.superseded) {
                  send_json(res, {{"superseded", true}}, 409);
                } else {
                  send_json(res, out.run);
                }
              }));
    http.Get(R"(/api/image/([a-z]+)\.png)", guarded([&s](const httplib::Request& req, auto& res) {
               send_png(res, s.image_png(req.matches[1]));
             }));
    http.Get(R"(/api/overlay/([a-z]+)\.png)", guarded([&s](const httplib::Request& req, auto& res) {
               send_png(res, s.overlay_png(req.matches[1], req.get_param_value("masks")));
             }));
    http.Get("/api/shadowmap.txt",
             guarded([&s](const auto&, auto& res) { send_text(res, s.shadow_map(), ""); }));
    http.Get("/api/histogram",
             guarded([&s](const auto&, auto& res) { send_json(res, s.histogram()); }));
    http.Get("/api/sigma0",
             guarded([&s](const auto&, auto& res) { send_json(res, s.sigma0_chart()); }));
    http.Get("/api/inspect", guarded([&s](const httplib::Request& req, auto& res) {
               send_json(res, s.inspect(req.get_param_value("view"), int_param(req, "x"),
                                        int_param(req, "y")));
             }));
    http.Post("/api/products",
              guarded([&s](const auto&, auto& res) { send_json(res, s.write_products()); }));
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

  void add_scene_routes() {
    Session& s = session;
    http.Post("/api/scene/objects", guarded([&s](const httplib::Request& req, auto& res) {
                send_json(res, s.add_object(req.body));
              }));
    http.Post(R"(/api/scene/objects/(\d{1,6}))",
              guarded([&s](const httplib::Request& req, auto& res) {
                send_json(res, s.update_object(index_param(req), req.body));
              }));
    http.Delete(R"(/api/scene/objects/(\d{1,6}))",
                guarded([&s](const httplib::Request& req, auto& res) {
                  send_json(res, s.delete_object(index_param(req)));
                }));
    http.Post("/api/scene/paint", guarded([&s](const httplib::Request& req, auto& res) {
                send_json(res, s.paint(req.body));
              }));
    http.Post("/api/scene/undo",
              guarded([&s](const auto&, auto& res) { send_json(res, s.undo()); }));
    http.Post("/api/scene/save", guarded([&s](const httplib::Request& req, auto& res) {
                send_json(res, s.save_scene(req.body));
              }));
    http.Post("/api/radar/save", guarded([&s](const httplib::Request& req, auto& res) {
                send_json(res, s.save_radar(req.body));
              }));
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
  return port;
}

void HttpServer::run() {
  impl_->http.listen_after_bind();
}

void HttpServer::stop() {
  impl_->http.stop();
}

}  // namespace ris
