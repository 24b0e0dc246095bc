// Whether a path names anything, without throwing: std::filesystem::exists
// throws filesystem_error when a name cannot be looked up at all (a name
// too long, a component that is not a folder, no permission), and a user's
// path must end in ris's own "no such file" message instead (found by the
// land-cover mapping fuzzer, fuzz/).
#pragma once

#include <filesystem>
#include <system_error>

namespace ris {

inline bool path_exists(const std::filesystem::path& p) noexcept {
  std::error_code ec;
  return std::filesystem::exists(p, ec) && !ec;
}

}  // namespace ris
