// Land cover: a categorical raster (any GDAL format and CRS) resampled onto a
// scene grid and mapped from its class codes to backscatter categories
// (docs/terrain.md).
//
// Mapping file (TOML):
//   [mapping]
//   name = "ESA WorldCover v200"
//   library = "backscatter/generic-terrain.toml"  # resolves category names
//   default = "grass"      # optional: category of codes not in [classes]
//   fill = "bare soil"     # optional: category of cells without land cover
//   nodata = [0]           # optional: codes meaning "no information"
//   [classes]
//   10 = "forest"          # a category name from the library, or an id
//   80 = 3
//
// The library path is taken relative to the mapping file's folder, else to
// the ris data folder; only the id and name of its [[category]] tables are
// read here. Codes present in the land cover but absent from [classes] are an
// error listing them (with cell counts) unless `default` is set. Cells with
// no land-cover information (outside the raster, its no-data value, or a
// `nodata` code) take `fill`, or become no-data when it is not set.
//
// Example:
//   ris::LandCoverMapping m = ris::read_landcover_mapping("worldcover.toml");
//   ris::LandCoverStats st = ris::apply_landcover(scene, "ESA_WorldCover.tif", m);
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"

namespace ris {

struct LandCoverMapping {
  std::string source_file;                        // the mapping file, for messages
  std::string name;                               // free text
  std::string library;                            // resolved library path ("" when ids only)
  std::map<std::int64_t, std::uint16_t> classes;  // land-cover code -> category id
  std::optional<std::uint16_t> default_category;  // codes not in classes
  std::optional<std::uint16_t> fill_category;     // cells without land cover
  std::set<std::int64_t> nodata_codes;            // codes meaning "no information"
};

// Reads and checks a mapping file (unknown keys, bad codes, unknown category
// names: InputError naming the file and key).
LandCoverMapping read_landcover_mapping(const std::filesystem::path& path);

// Category id of `name_or_id` (a decimal id or a name) in the mapping's
// library; for a command-line override of the default category.
std::uint16_t resolve_category(const LandCoverMapping& mapping, const std::string& name_or_id,
                               const std::string& key);

// Name -> id of every [[category]] of a category library (only `id` and
// `name` are read; the models are the backscatter loader's business).
std::map<std::string, std::uint16_t> read_category_names(const std::filesystem::path& library);

// A category given on the command line as a decimal id or a library name;
// InputError naming `key` (and the known names) otherwise.
std::uint16_t parse_category(const std::string& name_or_id,
                             const std::map<std::string, std::uint16_t>& names,
                             const std::string& key);

struct LandCoverStats {
  std::size_t mapped_cells = 0;    // cells whose code is in [classes]
  std::size_t default_cells = 0;   // cells given the default category
  std::size_t fill_cells = 0;      // cells without land cover given `fill`
  std::size_t unfilled_cells = 0;  // cells without land cover made no-data
  std::map<std::uint16_t, std::size_t> cells_per_category;
  RasterMetadata metadata;  // RIS_LANDCOVER, RIS_LANDCOVER_MAPPING, ...
};

// Resamples band 1 of the land-cover raster onto the scene grid (nearest
// neighbour, GDAL's warper) and sets every valid cell's category through the
// mapping. The scene must have a CRS; the land cover must have one. Throws
// InputError when the land cover does not overlap the scene, or holds codes
// without a category (listed) and the mapping has no default.
LandCoverStats apply_landcover(Scene& scene, const std::filesystem::path& landcover_path,
                               const LandCoverMapping& mapping);

}  // namespace ris
