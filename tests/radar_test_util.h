// Helpers for the radar-file tests: parse a TOML text as the file "r.toml",
// expect an InputError naming a key, and edit a text by replacing a line.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"

namespace ris::test {

inline RadarParams parse_radar(const std::string& text) {
  return radar_from_toml(toml::parse(text), "r.toml");
}

// Expects an InputError naming r.toml and a key (or message) containing `key`.
inline void expect_radar_error(const std::string& text, const std::string& key) {
  try {
    parse_radar(text);
    ADD_FAILURE() << "no InputError for key " << key << " in:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "r.toml");
    const std::string where = e.key() + " " + e.what();
    EXPECT_NE(where.find(key), std::string::npos) << "error was: " << where;
  }
}

// `text` with the first `from` replaced by `to` (a test failure when absent).
inline std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  if (pos != std::string::npos) text.replace(pos, from.size(), to);
  return text;
}

}  // namespace ris::test
