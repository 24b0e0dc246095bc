#include "ris/sim/slar_channel_products.h"

#include <algorithm>
#include <fstream>

#include "ris/io/atomic_file.h"
#include "ris/sim/slar_products.h"
#include "ris/util/error.h"

namespace ris {
namespace {

using nlohmann::json;
namespace fs = std::filesystem;

// A file's stem: its name up to the first '.'.
std::string stem_of(const std::string& file) {
  return file.substr(0, file.find('.'));
}

bool scene_wide(const std::string& file) {
  const auto& s = slar_scene_wide_stems();
  return std::find(s.begin(), s.end(), stem_of(file)) != s.end();
}

// A channel's run information: its backscatter source named.
SlarRunInfo channel_info(const SlarRunInfo& info, const SlarChannelProducts& c) {
  SlarRunInfo out = info;
  if (!c.backscatter_path.empty()) out.backscatter_path = c.backscatter_path;
  return out;
}

// What a channel after the first writes: the selection without the
// scene-wide products (written with the first channel). A selection of
// scene-wide products only is kept as it is (an empty selection would mean
// every product); its files are then dropped.
// The calibrated images stay as the run asked for them (wants_calibrated).
ProductSelection later_channel_selection(const SlarRunInfo& info) {
  const ProductSelection& want = info.products;
  ProductSelection out;
  const std::vector<std::string_view>& all = slar_product_stems();
  for (std::string_view s : all) {
    if (!want.wants(s) || scene_wide(std::string(s))) continue;
    if (names_calibrated({{std::string(s)}}) && !wants_calibrated(info, s)) continue;
    out.stems.emplace_back(s);
  }
  return out.stems.empty() ? want : out;
}

// The whole metadata from each channel's own (as write_slar_products wrote it).
json combine_metadata(std::span<const SlarChannelProducts> channels, const std::vector<json>& own) {
  json out = own.front();
  json products = json::object();
  json list = json::array();
  for (std::size_t c = 0; c < channels.size(); ++c) {
    json mine = json::object();
    for (const auto& [file, description] : own[c]["products"].items()) {
      if (file == "metadata.json") continue;
      if (scene_wide(file)) {
        if (c == 0) products[file] = description;
        continue;
      }
      const std::string name = channel_product_file(file, channels[c].name);
      mine[name] = description.get<std::string>() + " (channel " + channels[c].name + ")";
      products[name] = mine[name];
    }
    const SlarSimulation& sim = *channels[c].sim;
    list.push_back({{"name", channels[c].name},
                    {"frequency_hz", sim.radar.frequency_hz},
                    {"polarisation", std::string(to_string(sim.radar.polarisation))},
                    {"backscatter", own[c]["inputs"]["backscatter"]},
                    {"radar", own[c]["inputs"]["radar"]},
                    {"derived", own[c]["derived"]},
                    {"products", mine}});
  }
  products["metadata.json"] = "this file";
  out["products"] = products;
  out["channels"] = list;
  out["channels_note"] =
      "inputs.radar and derived are the first channel's; each channel's own are in channels "
      "(products suffixed by the channel's name; the scene-wide ones written once)";
  return out;
}

// Every channel's own metadata.json, as write_slar_products writes it.
std::vector<json> channel_metadata(const Scene& scene,
                                   std::span<const SlarChannelProducts> channels,
                                   const SlarRunInfo& info) {
  std::vector<json> own;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    SlarRunInfo ic = channel_info(info, channels[c]);
    if (c > 0) ic.products = later_channel_selection(info);
    own.push_back(slar_metadata(scene, *channels[c].sim, *channels[c].pictures, ic));
  }
  return own;
}

}  // namespace

const std::vector<std::string_view>& slar_scene_wide_stems() {
  // The scene-grid maps, the slant image's flags and the shadow map come from
  // the geometry (the same for every channel of a run: slar_channels.h).
  static const std::vector<std::string_view> stems = {"scene_mask", "local_incidence_deg",
                                                      "mask_slant", "shadowmap"};
  return stems;
}

std::string channel_product_file(const std::string& file, const std::string& channel) {
  const std::size_t dot = file.find('.');
  if (dot == std::string::npos) return file + "_" + channel;
  return file.substr(0, dot) + "_" + channel + file.substr(dot);
}

json slar_channels_metadata(const Scene& scene, std::span<const SlarChannelProducts> channels,
                            const SlarRunInfo& info) {
  RIS_CHECK(!channels.empty());
  return combine_metadata(channels, channel_metadata(scene, channels, info));
}

void write_slar_channel_products(const fs::path& out_dir, const Scene& scene,
                                 std::span<const SlarChannelProducts> channels,
                                 const SlarRunInfo& info, const ExtraRunProducts& extra) {
  RIS_CHECK(!channels.empty());
  StagedDirectory dir(out_dir);
  std::vector<json> own;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    // The channel alone, as a one-channel run writes it, in a folder of the
    // staging folder; then its files moved up under their channel's names.
    SlarRunInfo ic = channel_info(info, channels[c]);
    if (c > 0) ic.products = later_channel_selection(info);
    const fs::path sub = dir.path(".channel-" + channels[c].name);
    write_slar_products(sub, scene, *channels[c].sim, *channels[c].pictures, ic);
    {
      std::ifstream in(sub / "metadata.json");
      own.push_back(json::parse(in));
    }
    std::vector<fs::path> files;
    for (const auto& e : fs::directory_iterator(sub)) files.push_back(e.path());
    for (const fs::path& f : files) {
      const std::string file = f.filename().string();
      if (file == "metadata.json" || (scene_wide(file) && c > 0)) continue;
      fs::rename(f,
                 dir.path(scene_wide(file) ? file : channel_product_file(file, channels[c].name)));
    }
    fs::remove_all(sub);
  }
  json meta = combine_metadata(channels, own);
  if (extra) {
    json more = extra(dir.path(""));
    for (auto& [file, what] : more["products"].items()) meta["products"][file] = what;
    more.erase("products");
    for (auto& [key, value] : more.items()) meta[key] = value;
  }
  write_text_file_atomic(dir.path("metadata.json"), meta.dump(2) + "\n");
  dir.commit();
}

}  // namespace ris
