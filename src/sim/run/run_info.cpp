#include "ris/sim/run_info.h"

#include <algorithm>

#include "ris/util/error.h"

namespace ris {

bool ProductSelection::wants(std::string_view stem) const {
  return stems.empty() || std::find(stems.begin(), stems.end(), stem) != stems.end();
}

void check_product_selection(const ProductSelection& selection,
                             const std::vector<std::string_view>& allowed, const std::string& key) {
  for (const std::string& s : selection.stems) {
    if (std::find(allowed.begin(), allowed.end(), s) != allowed.end()) continue;
    std::string list;
    for (std::string_view a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    throw InputError("", key, "unknown product \"" + s + "\" (expected one of: " + list + ")");
  }
}

void remove_unselected_products(const std::filesystem::path& folder,
                                const ProductSelection& selection) {
  if (selection.stems.empty()) return;
  std::vector<std::filesystem::path> drop;
  for (const auto& e : std::filesystem::directory_iterator(folder)) {
    const std::string name = e.path().filename().string();
    if (name == "metadata.json" || name.starts_with(".") || !e.is_regular_file()) continue;
    if (!selection.wants(e.path().stem().string())) drop.push_back(e.path());
  }
  for (const std::filesystem::path& p : drop) std::filesystem::remove(p);
}

GeoTiffCompression product_tiff_settings(const SlarRunInfo& info, bool floating_point) {
  GeoTiffCompression c = geotiff_compression(info.compression, floating_point);
  c.overviews = info.overviews;
  return c;
}

}  // namespace ris
