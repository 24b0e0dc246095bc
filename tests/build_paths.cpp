#include "build_paths.h"

// The definitions are given to this file alone (CMakeLists.txt).
namespace ris::test {

const char* ris_exe() {
  return RIS_EXE;
}
const char* source_dir() {
  return RIS_SOURCE_DIR;
}
const char* data_dir() {
  return RIS_SOURCE_DIR "/data";
}
const char* test_data_dir() {
  return RIS_SOURCE_DIR "/tests/data";
}
const char* mpiexec() {
  return RIS_MPIEXEC;
}

}  // namespace ris::test
