// Where ris finds its shipped data (radars, scenes, backscatter libraries).
#pragma once

#include <filesystem>

namespace ris {

// The data folder: $RIS_DATA when set and non-empty (tests of relocated
// data); else <prefix>/share/ris/data when the running executable is
// <prefix>/bin/ris and that folder exists (`cmake --install`); else the
// source tree's data/ folder compiled in (a build tree).
std::filesystem::path data_dir();

}  // namespace ris
