// ris: the radar image simulator command-line tool.
#include <fmt/format.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>

#include "command_registry.h"
#include "mpi/process_group_start.h"
#include "ris/io/interrupt_cleanup.h"
#include "ris/io/safe_paths.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/memory_reuse.h"
#include "ris/util/process_group.h"
#include "ris/util/spelling.h"

namespace ris::app {

std::vector<std::pair<std::string, AddCommand>>& registered_commands() {
  static std::vector<std::pair<std::string, AddCommand>> commands;
  return commands;
}

Registration::Registration(std::string name, AddCommand add) {
  registered_commands().emplace_back(std::move(name), std::move(add));
}

std::string data_path(const std::string& relative) {
  return (data_dir() / relative).string();
}

std::string default_scene_path() {
  return data_path("scenes/ku-geometric.toml");
}
std::string default_radar_path() {
  return data_path("radars/seed-fig4-5.toml");
}

}  // namespace ris::app

namespace ris::app {

// A command name that is none of ris's: a usage error with a suggestion
// (CLI11 alone says "A subcommand is required" for `ris simulat`).
struct UnknownCommand : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The command words (`ris scene buidl ...`) checked against the commands
// and subcommands before CLI11 parses them: the first word that is not an
// option, and the word after a command that has subcommands of its own.
void require_known_commands(CLI::App& app, int argc, char** argv) {
  CLI::App* level = &app;
  std::string path = "ris";
  for (int i = 1; i < argc && level != nullptr; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') {
      if (level != &app) return;  // options of a command: CLI11 checks them
      continue;                   // -v, --help, --version
    }
    const std::vector<CLI::App*> subs = level->get_subcommands([](CLI::App*) { return true; });
    if (subs.empty()) return;
    std::vector<std::string> names;
    CLI::App* match = nullptr;
    for (CLI::App* sub : subs) {
      names.push_back(sub->get_name());
      if (sub->get_name() == word) match = sub;
    }
    if (match == nullptr) {
      std::string all;
      for (const std::string& n : names) all += (all.empty() ? "" : ", ") + n;
      throw UnknownCommand(
          fmt::format("'{}' is not a command of {}{}; the commands are: {} "
                      "(`{} --help` says more)",
                      word, path, ris::did_you_mean(word, names), all, path));
    }
    path += " " + word;
    level = match;
  }
}

}  // namespace ris::app

int main(int argc, char** argv) {
  ris::keep_freed_memory_for_reuse();
  // One process, one run: outputs are checked against every input it read
  // (ris/io/safe_paths.h).
  ris::track_inputs(true);
  // The MPI job this process is a rank of, when started by mpirun or srun.
  const std::unique_ptr<ris::ProcessGroup> group = ris::app::join_process_group(argc, argv);
  if (group) ris::install_process_group(group.get());
  // Ctrl-C, SIGTERM, SIGHUP: the unfinished outputs removed (an MPI rank has
  // its own, started by join_process_group).
  if (!group) ris::remove_outputs_on_interrupt();
  CLI::App app{"ris: radar image simulator (SLAR, SAR and PPI images from terrain)", "ris"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("ris ") + RIS_VERSION);
  app.footer(
      "Exit status: 0 done, 1 an input error (file, key, value, unsafe output or resource "
      "limit), 2 a usage error (the command line), 3 any other failure (docs/limits.md).");
  // Messages go to stderr as "ris: level: text"; -v is read before parsing so
  // that it applies to everything the subcommands print.
  spdlog::set_default_logger(spdlog::stderr_color_mt("ris"));
  spdlog::set_pattern(ris::process_group().size() > 1
                          ? fmt::format("ris (rank {} of {}): %^%l%$: %v",
                                        ris::process_group().rank(), ris::process_group().size())
                          : std::string("ris: %^%l%$: %v"));
  bool verbose = false;  // applied by the pre-scan below
  app.add_flag("-v,--verbose", verbose, "Print debug messages");
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "-v" || arg == "--verbose") spdlog::set_level(spdlog::level::debug);
  }
  // The other ranks of an MPI run print their errors only (rank 0 reports).
  if (ris::process_group().rank() != 0) spdlog::set_level(spdlog::level::err);

  auto& commands = ris::app::registered_commands();
  std::sort(commands.begin(), commands.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (auto& [name, add] : commands) add(app);

  // Exit status (docs/exit-codes.md): 0 done (and --help, --version); 2 a
  // usage error (CLI11's own codes, 100 and up, are folded into 2); 1 an
  // input error (a file, key, value or resource limit); 3 any other failure
  // (out of memory, an I/O error, an internal error).
  int code = 0;
  try {
    ris::app::require_known_commands(app, argc, argv);
    app.parse(argc, argv);
  } catch (const ris::app::UnknownCommand& e) {
    spdlog::error("{}", e.what());
    code = 2;
  } catch (const CLI::ParseError& e) {
    code = app.exit(e) == 0 ? 0 : 2;
  } catch (const ris::InputError& e) {
    spdlog::error("{}", e.what());
    code = 1;
  } catch (const std::bad_alloc&) {
    spdlog::error("out of memory (the inputs ask for more than the machine has)");
    code = 3;
  } catch (const std::exception& e) {
    spdlog::error("{}", e.what());
    code = 3;
  }
  // A rank of an MPI run that fails ends the others too (its message printed
  // and its staged output removed by now: docs/scale.md).
  if (code != 0 && ris::process_group().size() > 1) ris::process_group().abort(code);
  return code;
}
