// What a client of `ris serve` is told about files: their names (or names
// relative to --out), never the server's absolute paths. The folders the
// server runs in are not the client's business, and an answer that a hostile
// page manages to read (docs/serve.md, "Threat model") should give it
// nothing to aim at.
//
// Example:
//   ris::without_directories("/home/me/radars/x.toml: frequency: expected ...")
//   // "x.toml: frequency: expected ..."
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace ris {

// `text` with every absolute path in it (a word starting with '/', after a
// space, a quote, '(' or '=' or at the start) cut to its last component.
// Relative names and units ("m/s") are left alone.
std::string without_directories(const std::string& text);

// The same for every string value in `j` (keys are left alone).
void strip_directories_in(nlohmann::json& j);

}  // namespace ris
