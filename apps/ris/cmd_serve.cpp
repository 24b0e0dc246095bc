// `ris serve`: the interactive workstation, a web page to simulate, explore
// and build scenes with a person in the loop (docs/serve.md).
//
//   ris serve [--scene S] [--radar R] [--backscatter B] [--out DIR]
//             [--host 127.0.0.1] [--port 8765] [--max-body-kib N]
//             [--max-upload-mib N] [--javascript-dir D]
//             [--max-product-runs N] [--max-product-mib N] [--open]
//
// Binds the loopback address unless --host says otherwise (the page has no
// authentication: any other host prints a warning). Prints the URL to open;
// Ctrl-C (SIGINT) or SIGTERM stops it cleanly. Saved scenes and radars and
// written products go under --out.
#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <pthread.h>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <thread>

#include "command_registry.h"
#include "ris/serve/server.h"
#include "ris/serve/session.h"
#include "ris/util/data_dir.h"
#include "ris/util/memory_reuse.h"
#include "run_input_options.h"
#include "seed_option.h"

namespace ris::app {
namespace {

struct ServeArgs {
  ServeInputs inputs;
  ServerOptions server;
  std::size_t max_body_kib = 1024;
  std::size_t max_product_mib = 1024;
  std::size_t max_upload_mib = 64;
  bool open = false;
};

bool is_loopback(const std::string& host) {
  return host == "127.0.0.1" || host == "localhost" || host == "::1";
}

void run_serve(ServeArgs& a) {
  a.inputs.data_dir = data_dir();
  a.server.web_dir = data_dir() / "serve";
  a.server.max_body_bytes = a.max_body_kib * 1024;
  a.server.max_upload_bytes = a.max_upload_mib << 20;
  a.inputs.products.max_bytes = std::uintmax_t{a.max_product_mib} << 20;
  if (!is_loopback(a.server.host)) {
    spdlog::warn(
        "listening on {}: the page has no authentication; anyone who can reach this "
        "address can run simulations and write files under {}",
        a.server.host, a.inputs.out_dir.string());
  }
  // SIGINT and SIGTERM go to one thread that waits for them (sigwait), so
  // the server's threads, started after this, never take them.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  // Runs happen on whichever HTTP worker takes the request: one arena, so
  // they reuse each other's freed buffers (memory stays at one run's size).
  share_freed_memory_between_threads(1);

  Session session(a.inputs);
  HttpServer server(session, a.server);
  const int port = server.bind();
  const std::string url = fmt::format("http://{}:{}/", a.server.host, port);
  fmt::print("ris serve: open {}  (Ctrl-C stops)\n", url);
  std::fflush(stdout);
  if (a.open) {
    const std::string cmd = "xdg-open '" + url + "' >/dev/null 2>&1 &";
    if (std::system(cmd.c_str()) != 0) spdlog::warn("could not start a browser; open {}", url);
  }
  std::thread waiter([&server, stop_signals] {
    int sig = 0;
    sigwait(&stop_signals, &sig);
    server.stop();
  });
  server.run();
  // Stopped by something other than a signal: wake the waiter.
  pthread_kill(waiter.native_handle(), SIGTERM);
  waiter.join();
  fmt::print("ris serve: stopped\n");
}

void add_serve(CLI::App& app) {
  auto args = std::make_shared<ServeArgs>();
  ServeInputs& in = args->inputs;
  auto* cmd = app.add_subcommand(
      "serve", "Serve the interactive page: simulate, inspect and edit scenes in a browser");
  add_run_input_options(cmd, in.scene_path, in.radar_path, in.backscatter_path,
                        "Scene: a .toml description (editable) or a raster");
  cmd->add_option("--out", in.out_dir, "Folder for saved scenes, radars and products")
      ->capture_default_str();
  add_seed_option(cmd, in.seed, "Initial fading seed");
  cmd->add_option("--host", args->server.host,
                  "Address to listen on (other than loopback: no authentication, a warning)")
      ->capture_default_str();
  cmd->add_option("--port", args->server.port, "Port (0: any free port)")->capture_default_str();
  cmd->add_option("--max-body-kib", args->max_body_kib, "Largest request body, KiB")
      ->capture_default_str()
      ->check(CLI::Range(1, 1 << 20));
  cmd->add_option("--max-upload-mib", args->max_upload_mib,
                  "Largest uploaded DEM, land cover or scene file, MiB")
      ->capture_default_str()
      ->check(CLI::Range(1, 4096));
  cmd->add_option("--javascript-dir", args->server.javascript_dir,
                  "Where Debian's libjs-leaflet and libjs-chart.js are installed (the page "
                  "works without them)")
      ->capture_default_str();
  cmd->add_option("--max-product-runs", in.products.max_folders,
                  "Products folders kept under --out (the oldest removed beyond)")
      ->capture_default_str()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--max-product-mib", args->max_product_mib,
                  "Bytes of products kept under --out, MiB (the oldest folders removed beyond)")
      ->capture_default_str()
      ->check(CLI::Range(1, 1 << 24));
  cmd->add_flag("--open", args->open, "Open the page in the default browser");
  cmd->callback([args] { run_serve(*args); });
}

const Registration reg{"serve", add_serve};

}  // namespace
}  // namespace ris::app
