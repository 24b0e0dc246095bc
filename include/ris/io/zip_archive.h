// A zip archive of files, made in memory (GDAL's zip writer on /vsimem/):
// the server's "all products" download. Each file is stored under its own
// file name, deflated.
//
// Example:
//   std::vector<std::uint8_t> zip = ris::zip_files({"out/slant_range.png", "out/metadata.json"});
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace ris {

// Throws InputError naming a file that cannot be read.
std::vector<std::uint8_t> zip_files(const std::vector<std::filesystem::path>& files);

}  // namespace ris
