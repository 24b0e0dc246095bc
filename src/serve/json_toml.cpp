#include "ris/serve/json_toml.h"

#include <cstdint>
#include <sstream>

#include "ris/serve/json_depth.h"
#include "ris/util/error.h"

namespace ris {
namespace {

toml::array json_array_to_toml(const nlohmann::json& array, const std::string& source,
                               const std::string& path);

// One JSON value appended to a TOML array or inserted into a table by `put`.
template <typename Put>
void convert_value(const nlohmann::json& v, const std::string& source, const std::string& path,
                   Put&& put) {
  switch (v.type()) {
    case nlohmann::json::value_t::object:
      put(json_object_to_toml(v, source));
      break;
    case nlohmann::json::value_t::array:
      put(json_array_to_toml(v, source, path));
      break;
    case nlohmann::json::value_t::string:
      put(v.get<std::string>());
      break;
    case nlohmann::json::value_t::boolean:
      put(v.get<bool>());
      break;
    case nlohmann::json::value_t::number_integer:
      put(v.get<std::int64_t>());
      break;
    case nlohmann::json::value_t::number_unsigned: {
      const auto u = v.get<std::uint64_t>();
      if (u > static_cast<std::uint64_t>(INT64_MAX)) {
        throw InputError(source, path, "integer too large");
      }
      put(static_cast<std::int64_t>(u));
      break;
    }
    case nlohmann::json::value_t::number_float:
      put(v.get<double>());
      break;
    default:
      throw InputError(source, path, "null is not a value (leave the key out instead)");
  }
}

toml::array json_array_to_toml(const nlohmann::json& array, const std::string& source,
                               const std::string& path) {
  toml::array out;
  for (std::size_t i = 0; i < array.size(); ++i) {
    convert_value(array[i], source, path + "[" + std::to_string(i) + "]",
                  [&](auto&& value) { out.push_back(std::forward<decltype(value)>(value)); });
  }
  return out;
}

}  // namespace

toml::table json_object_to_toml(const nlohmann::json& object, const std::string& source) {
  if (!object.is_object()) throw InputError(source, "", "expected a JSON object { ... }");
  toml::table out;
  for (const auto& item : object.items()) {
    const std::string& key = item.key();
    convert_value(item.value(), source, key,
                  [&](auto&& value) { out.insert(key, std::forward<decltype(value)>(value)); });
  }
  return out;
}

toml::table json_body_to_toml(const std::string& body, const std::string& source) {
  // Before parsing: the parser recurses once per level (ris/serve/json_depth.h).
  check_json_depth(body, source, kMaxJsonDepth);
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(body.empty() ? std::string("{}") : body);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(source, "", std::string("not valid JSON: ") + e.what());
  }
  return json_object_to_toml(j, source);
}

void merge_toml(toml::table& base, const toml::table& overrides) {
  for (const auto& [key, node] : overrides) {
    toml::table* sub = base[key].as_table();
    if (sub != nullptr && node.is_table()) {
      merge_toml(*sub, *node.as_table());
    } else {
      base.insert_or_assign(key, node);
    }
  }
}

nlohmann::json toml_to_json(const toml::table& table) {
  std::ostringstream text;
  text << toml::json_formatter{table};
  return nlohmann::json::parse(text.str());
}

}  // namespace ris
