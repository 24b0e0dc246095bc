// The real acquisitions and DEMs shipped in tests/data (tests/data/real/SOURCES.md).
#pragma once

#include <string>

#include "build_paths.h"

namespace ris::test {

inline std::string real_data(const std::string& name) {
  return std::string(ris::test::test_data_dir()) + "/real/" + name;
}
inline std::string winnipeg_h5() {
  return real_data("winnipeg.h5");
}
inline std::string sanand_h5() {
  return real_data("SanAnd_138.h5");
}
inline std::string sentinel1_safe() {
  return real_data(
      "sentinel1/S1A_IW_SLC__1SDV_20220104T170557_20220104T170624_041314_04E951_F1F1.SAFE");
}
inline std::string test_dem(const std::string& name) {
  return std::string(ris::test::test_data_dir()) + "/dem/" + name;
}
inline std::string example_acquisition(const std::string& name) {
  return std::string(ris::test::data_dir()) + "/acquisitions/" + name;
}

}  // namespace ris::test
