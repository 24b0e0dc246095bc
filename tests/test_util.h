// Shared helpers for ris tests: scratch folders and running the CLI.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "build_paths.h"

namespace ris::test {

// A fresh folder under the system temp dir, removed when the object dies.
class TempDir {
 public:
  TempDir() {
    std::string tmpl = (std::filesystem::temp_directory_path() / "ris-test-XXXXXX").string();
    char* made = ::mkdtemp(tmpl.data());
    path_ = made != nullptr ? std::filesystem::path(made) : std::filesystem::path(tmpl);
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// A path single-quoted for the shell command run_ris builds.
inline std::string q(const std::filesystem::path& p) {
  return "'" + p.string() + "'";
}

inline void write_file(const std::filesystem::path& p, const std::string& text) {
  std::ofstream f(p);
  f << text;
}

inline std::string read_file(const std::filesystem::path& p) {
  std::ifstream f(p);
  std::stringstream ss;
  ss << f.rdbuf();
  return ss.str();
}

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs the ris executable with the given argument string (shell-quoted by the
// caller) and captures its output; env: VAR=value words set for it (or "").
inline RunResult run_ris_env(const std::string& env, const std::string& args) {
  TempDir tmp;
  const std::string log = (tmp / "out.txt").string();
  const std::string cmd = (env.empty() ? std::string() : "env " + env + " ") +
                          std::string(ris::test::ris_exe()) + " " + args + " > " + log + " 2>&1";
  const int status = std::system(cmd.c_str());
  RunResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.output = read_file(log);
  return r;
}

inline RunResult run_ris(const std::string& args) {
  return run_ris_env("", args);
}

}  // namespace ris::test
