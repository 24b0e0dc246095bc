// --seed, the same on every command: a whole number from 0 to 2^64 - 1.
//
// CLI11 converts "-1" to an unsigned integer by wrapping it (to 2^64 - 1)
// and saturates "18446744073709551616" to the same value, so two different
// seeds typed by a user gave one image. The text is checked first, with
// std::from_chars, which takes no sign and reports what does not fit.
#pragma once

#include <CLI/CLI.hpp>

#include <charconv>
#include <cstdint>
#include <string>

namespace ris::app {

inline CLI::Option* add_seed_option(CLI::App* cmd, std::uint64_t& seed, const std::string& what) {
  const CLI::Validator whole_number(
      [](std::string& text) -> std::string {
        std::uint64_t v = 0;
        const char* end = text.data() + text.size();
        const auto r = std::from_chars(text.data(), end, v);
        if (text.empty() || r.ec != std::errc() || r.ptr != end) {
          return "expected a whole number from 0 to 18446744073709551615 (2^64 - 1), got \"" +
                 text + "\"";
        }
        return "";
      },
      "0..2^64-1");
  return cmd->add_option("--seed", seed, what)->check(whole_number)->capture_default_str();
}

}  // namespace ris::app
