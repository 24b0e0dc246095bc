// A JSON request body as a TOML table, so that the server checks it with the
// same code (ConfigTable, the radar and scene parsers) and the same messages
// as a file: an unknown key or a bad value gives the text `ris simulate` would
// print for that key in a file.
//
// Example:
//   toml::table body = ris::json_body_to_toml(R"({"seed": 3, "radar": {"frequency": "9 GHz"}})",
//                                             "request body");
//   ris::ConfigTable t(body, "request body", "");
//   std::int64_t seed = t.get_int("seed");
#pragma once

#include <string>

#include <toml++/toml.h>
#include <nlohmann/json.hpp>

namespace ris {

// Parses `body` as a JSON object and converts it (objects to tables, arrays,
// strings, integers, floating-point numbers, booleans). Throws InputError
// naming `source` for text that is not JSON, nested deeper than kMaxJsonDepth
// (checked before parsing), a top level that is not an object, or a null
// (TOML has none).
toml::table json_body_to_toml(const std::string& body, const std::string& source);

// The same for a parsed JSON object.
toml::table json_object_to_toml(const nlohmann::json& object, const std::string& source);

// Merges `overrides` into `base`: tables recursively, any other value replaces
// the one in `base` (or is added).
void merge_toml(toml::table& base, const toml::table& overrides);

// A TOML table as JSON (dates and times as their text), for /api/state.
nlohmann::json toml_to_json(const toml::table& table);

}  // namespace ris
