// Subcommands register themselves here; main() builds the CLI11 app from the
// registry, so adding a command means adding one file under apps/ris/.
//
// Example (in apps/ris/cmd_hello.cpp):
//   namespace {
//   void add_hello(CLI::App& app) {
//     auto* cmd = app.add_subcommand("hello", "Say hello");
//     cmd->callback([] { fmt::print("hello\n"); });
//   }
//   const ris::app::Registration reg{"hello", add_hello};
//   }
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>
#include <vector>

namespace ris::app {

using AddCommand = std::function<void(CLI::App&)>;

struct Registration {
  Registration(std::string name, AddCommand add);
};

// Every registered command, sorted by name for a stable help listing.
std::vector<std::pair<std::string, AddCommand>>& registered_commands();

// The standard scene and radar files, resolved against the installed data dir.
std::string default_scene_path();
std::string default_radar_path();
std::string data_path(const std::string& relative);

}  // namespace ris::app
