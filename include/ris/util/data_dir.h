// Where ris finds its shipped data (radars, scenes, backscatter libraries).
#pragma once

#include <filesystem>

namespace ris {

// The data folder: $RIS_DATA when set and non-empty (installed copies, tests
// of relocated data), else the source tree's data/ folder compiled in.
std::filesystem::path data_dir();

}  // namespace ris
