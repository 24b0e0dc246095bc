#include "ris/util/data_dir.h"

#include <cstdlib>
#include <system_error>

// RIS_DATA_DIR is defined for this file alone (CMakeLists.txt): an absolute
// path on every compile line would make each checkout's objects differ and
// defeat the compiler cache shared between checkouts.
namespace ris {

namespace {

// <prefix>/share/ris/data for an executable in <prefix>/bin (the layout of
// `cmake --install`), when that folder exists; else empty.
std::filesystem::path installed_data_dir() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || exe.empty()) return {};
  const std::filesystem::path dir = exe.parent_path().parent_path() / "share" / "ris" / "data";
  return std::filesystem::is_directory(dir, ec) ? dir : std::filesystem::path();
}

}  // namespace

std::filesystem::path data_dir() {
  const char* env = std::getenv("RIS_DATA");
  if (env != nullptr && *env != '\0') return env;
  static const std::filesystem::path installed = installed_data_dir();
  if (!installed.empty()) return installed;
  return RIS_DATA_DIR;
}

}  // namespace ris
