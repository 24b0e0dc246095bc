#include "ris/util/error.h"

#include <cstdio>
#include <cstdlib>

namespace ris {

namespace {
std::string format_input_error(const std::string& file, const std::string& key,
                               const std::string& what) {
  std::string message;
  if (!file.empty()) message += file + ": ";
  if (!key.empty()) message += "'" + key + "': ";
  return message + what;
}
}  // namespace

InputError::InputError(std::string file, std::string key, const std::string& what)
    : std::runtime_error(format_input_error(file, key, what)),
      file_(std::move(file)),
      key_(std::move(key)) {}

void check_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "ris: internal error: check '%s' failed at %s:%d\n", condition, file, line);
  std::abort();
}

}  // namespace ris
