// The real acquisitions and DEMs shipped in tests/data (tests/data/real/SOURCES.md).
#pragma once

#include <string>

namespace ris::test {

inline std::string real_data(const std::string& name) {
  return std::string(RIS_TEST_DATA_DIR) + "/real/" + name;
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
  return std::string(RIS_TEST_DATA_DIR) + "/dem/" + name;
}
inline std::string example_acquisition(const std::string& name) {
  return std::string(RIS_DATA_DIR) + "/acquisitions/" + name;
}

}  // namespace ris::test
