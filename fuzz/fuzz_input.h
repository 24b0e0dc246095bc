// Shared by the fuzz harnesses (fuzz/*_fuzz.cpp): what counts as a finding
// and how bytes reach the loaders that take paths.
//
// A harness feeds one input to one parser. Bad input must end in ris's
// InputError (the message the user sees) or a TOML syntax error; any other
// exception, a crash, a hang or an allocation past libFuzzer's -rss_limit_mb
// is a finding. The harnesses run two ways: under libFuzzer (clang,
// -fsanitize=fuzzer; `make fuzz`), and as a plain replay of the corpus in
// fuzz/corpus/<name>/ through fuzz/replay_main.cpp in `make test`.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <unistd.h>

#include <spdlog/spdlog.h>
#include <toml++/toml.h>

#include "ris/io/config_table.h"
#include "ris/util/error.h"

namespace ris::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Warnings would flood the fuzzer's output; errors still reach stderr.
inline void quiet_logs() {
  static const bool once = [] {
    spdlog::set_level(spdlog::level::err);
    return true;
  }();
  (void)once;
}

// Loaders that take a path read the input from one file per process in the
// temporary folder (a fuzzer is one process; replay tests run one at a time
// per harness). The suffix selects the loader's format.
inline std::string write_input(std::string_view bytes, const std::string& suffix) {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() /
      ("ris-fuzz-" + std::to_string(static_cast<long long>(::getpid())) + suffix);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path.string();
}

// The TOML document, or nothing when the bytes are not TOML (toml++'s
// syntax error is the parser's own, tested upstream).
// Through ris's own edge (ris/io/config_table.h): the nesting pre-scan runs
// before toml++ does, as it does for every file ris reads.
inline bool parse_toml(std::string_view text, toml::table& out) {
  try {
    out = ris::parse_toml_text(text, "fuzz.toml");
    return true;
  } catch (const ris::InputError&) {
    return false;
  }
}

}  // namespace ris::fuzz
