#include "ris/serve/client_paths.h"

#include <cstring>

namespace ris {
namespace {

bool starts_word(const std::string& text, std::size_t i) {
  return i == 0 || std::strchr(" \t\n\"'(=", text[i - 1]) != nullptr;
}

bool ends_word(char c) {
  return std::strchr(" \t\n\"'),:;", c) != nullptr;
}

}  // namespace

std::string without_directories(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    if (text[i] != '/' || !starts_word(text, i)) {
      out += text[i++];
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && !ends_word(text[end])) ++end;
    const std::string word = text.substr(i, end - i);
    // "/a/b/" keeps "b"; "/" alone stays.
    const std::size_t last = word.find_last_not_of('/');
    if (last == std::string::npos) {
      out += word;
    } else {
      const std::size_t name_start = word.rfind('/', last) + 1;
      out += word.substr(name_start, last + 1 - name_start);
    }
    i = end;
  }
  return out;
}

void strip_directories_in(nlohmann::json& j) {
  if (j.is_string()) {
    j = without_directories(j.get<std::string>());
  } else if (j.is_structured()) {
    for (nlohmann::json& item : j) strip_directories_in(item);
  }
}

}  // namespace ris
