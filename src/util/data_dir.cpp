#include "ris/util/data_dir.h"

#include <cstdlib>

// RIS_DATA_DIR is defined for this file alone (CMakeLists.txt): an absolute
// path on every compile line would make each checkout's objects differ and
// defeat the compiler cache shared between checkouts.
namespace ris {

std::filesystem::path data_dir() {
  const char* env = std::getenv("RIS_DATA");
  if (env != nullptr && *env != '\0') return env;
  return RIS_DATA_DIR;
}

}  // namespace ris
