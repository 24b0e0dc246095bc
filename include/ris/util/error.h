// Typed errors for bad input (DESIGN.md principle 4: two error channels).
//
// InputError is thrown for anything a user can fix: a missing file, a bad key,
// an impossible parameter. It carries where the problem is (file and key, or
// file and line) so the message can name it. Internal invariants use
// RIS_CHECK instead, which aborts with the failed condition.
#pragma once

#include <stdexcept>
#include <string>

namespace ris {

class InputError : public std::runtime_error {
 public:
  // file: the path the user gave (may be empty for command-line values);
  // key: the configuration key or option ("grid.cell_size", "--seed"), may be
  // empty; what: what was wrong and what was expected.
  InputError(std::string file, std::string key, const std::string& what);

  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }

 private:
  std::string file_;
  std::string key_;
};

[[noreturn]] void check_failed(const char* condition, const char* file, int line);

}  // namespace ris

// An internal invariant: failure is a bug in ris, never a user error.
#define RIS_CHECK(cond)                                          \
  do {                                                           \
    if (!(cond)) ::ris::check_failed(#cond, __FILE__, __LINE__); \
  } while (0)
